package org.hapticon.study.log

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.Json
import org.hapticon.core.io.SchemaJson
import java.security.MessageDigest

/**
 * One row of a session's tamper-evident log. [hash] is the SHA-256 (lower-case hex) of [canonicalForm], which
 * covers every other field and [previousHash], the hash of the row before ([GENESIS_HASH] for the first). Editing,
 * deleting or reordering rows therefore breaks the chain; [HashChain.verify] finds where.
 *
 * @property sequence 0-based position in the session's log.
 * @property timestampMillis when it happened, epoch milliseconds.
 * @property participantId the pseudonymous participant id.
 * @property type the event type, see [StudyEvent].
 * @property payload the event's properties as compact JSON text.
 */
public data class LogEntry(
    val sequence: Long,
    val timestampMillis: Long,
    val participantId: String,
    val type: String,
    val payload: String,
    val previousHash: String,
    val hash: String,
) {
    /** The event this entry records. Throws [IllegalArgumentException] when the type or payload is not an event. */
    public val event: StudyEvent get() = StudyEvent.of(type, Json.decode(payload))

    public companion object {
        /** [previousHash] of the first entry: 64 zeros. */
        public val GENESIS_HASH: String = "0".repeat(64)

        /**
         * The entry at [sequence] recording [event] at [timestampMillis], chained to [previousHash]. Throws
         * [IllegalArgumentException] when [sequence] is negative.
         */
        public fun create(sequence: Long, timestampMillis: Long, participantId: String, event: StudyEvent, previousHash: String): LogEntry {
            require(sequence >= 0) { "sequence must be >= 0, was $sequence" }
            val payload = canonicalJson(StudyEvent.payload(event))
            val hash = hashOf(sequence, timestampMillis, participantId, event.type, payload, previousHash)
            return LogEntry(sequence, timestampMillis, participantId, event.type, payload, previousHash, hash)
        }

        /**
         * The text the hash covers: a compact JSON array `[sequence, timestamp, participant, type, payload, previousHash]`
         * with the numbers as decimal strings (exact for any Long) and the payload as a string. JSON escaping makes
         * field boundaries unambiguous, and [canonicalJson] writes one spelling for each value. Throws
         * [IllegalArgumentException] when a string holds an unpaired surrogate (it has no UTF-8 form to hash).
         */
        public fun canonicalForm(
            sequence: Long, timestampMillis: Long, participantId: String, type: String, payload: String, previousHash: String,
        ): String = canonicalJson(
            JsonArray(listOf(sequence.toString(), timestampMillis.toString(), participantId, type, payload, previousHash).map(::JsonPrimitive)),
        )

        /**
         * [element] as compact JSON, spelled exactly as the hand-written writer of earlier builds spelled it, because
         * that text is hashed into every log already recorded (`recorded/study-log-v1.txt` in the tests holds such a
         * log). kotlinx-serialization writes the same escapes (`\"`, `\\`, `\b\f\n\r\t`, other control
         * characters as lower-case `\u00xx`; `StringOps.kt`, `ESCAPE_STRINGS`) and the same integers, with one
         * difference: it leaves U+2028/U+2029 raw where the old writer wrote `\u2028`/`\u2029`. Outside strings
         * compact JSON has no such characters, so escaping every one of them in the output restores the old
         * text. The old writer also refused unpaired surrogates (they have no UTF-8 form, so two different strings
         * would hash alike); so does this. Payloads hold only strings and `Int`s, never doubles, so number spelling
         * (kotlinx's `1.0` against the old `1`) does not arise.
         */
        internal fun canonicalJson(element: JsonElement): String {
            val text = SchemaJson.encodeElement(element)
            var out: StringBuilder? = null
            for (i in text.indices) {
                val c = text[i]
                if (c.isHighSurrogate()) require(i + 1 < text.length && text[i + 1].isLowSurrogate()) { "unpaired surrogate at index $i" }
                if (c.isLowSurrogate()) require(i > 0 && text[i - 1].isHighSurrogate()) { "unpaired surrogate at index $i" }
                if (c == '\u2028' || c == '\u2029') {
                    if (out == null) out = StringBuilder(text.length + 10).append(text, 0, i)
                    out.append(if (c == '\u2028') "\\u2028" else "\\u2029")
                } else {
                    out?.append(c)
                }
            }
            return out?.toString() ?: text
        }

        /** SHA-256 hex of [canonicalForm] of the arguments. */
        public fun hashOf(
            sequence: Long, timestampMillis: Long, participantId: String, type: String, payload: String, previousHash: String,
        ): String {
            val digest = MessageDigest.getInstance("SHA-256")
                .digest(canonicalForm(sequence, timestampMillis, participantId, type, payload, previousHash).toByteArray(Charsets.UTF_8))
            return digest.joinToString("") { "%02x".format(it.toInt() and 0xff) }
        }
    }
}
