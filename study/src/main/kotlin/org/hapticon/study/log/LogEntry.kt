package org.hapticon.study.log

import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonString
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
            val payload = Json.encode(StudyEvent.payload(event))
            val hash = hashOf(sequence, timestampMillis, participantId, event.type, payload, previousHash)
            return LogEntry(sequence, timestampMillis, participantId, event.type, payload, previousHash, hash)
        }

        /**
         * The text the hash covers: a compact JSON array `[sequence, timestamp, participant, type, payload, previousHash]`
         * with the numbers as decimal strings (exact for any Long) and the payload as a string. JSON escaping makes
         * field boundaries unambiguous, and [Json.encode] writes one spelling for each value.
         */
        public fun canonicalForm(
            sequence: Long, timestampMillis: Long, participantId: String, type: String, payload: String, previousHash: String,
        ): String = Json.encode(
            JsonArray(listOf(sequence.toString(), timestampMillis.toString(), participantId, type, payload, previousHash).map(::JsonString)),
        )

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
