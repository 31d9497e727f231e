package org.hapticon.messaging.e2e

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.SchemaReport
import org.hapticon.messaging.MessageLimits
import org.hapticon.messaging.WireFormats
import java.util.Base64

/**
 * The parts of a sealed payload: the sender's [KeyBundle] ([keys]), the HPKE [ciphertext] and the Ed25519 [signature].
 * On the wire they are one `hapticon.sealed` document ([SealedDocument]).
 */
internal class SealedPayload(val keys: ByteArray, val ciphertext: ByteArray, val signature: ByteArray) {
    /** The payload's bytes: compact JSON, members in schema order, base64 values (ASCII). */
    fun encode(): ByteArray {
        val b64 = Base64.getEncoder()
        val document = SealedDocument(WireFormats.SEALED_SCHEMA, VERSION, b64.encodeToString(keys), b64.encodeToString(ciphertext), b64.encodeToString(signature))
        return SchemaJson.encode(SealedDocument.serializer(), document).toByteArray(Charsets.US_ASCII)
    }

    companion object {
        const val VERSION: Int = 1

        /**
         * The parts of [payload], or null when it is not a sealed document of this version: malformed JSON (the strict
         * reader's refusals: duplicate members, too deep), a member missing or of the wrong type, another schema or
         * version, or a value that is empty or not base64. Linear in the payload, whatever it holds.
         */
        fun decode(payload: ByteArray): SealedPayload? = try {
            val element = SchemaJson.parseUtf8(payload, payload.size, MessageLimits.MAX_JSON_DEPTH)
            val document = SchemaJson.decode(SealedDocument.serializer(), element, NotSealed)
            if (document.schema != WireFormats.SEALED_SCHEMA || document.version != VERSION) {
                null
            } else {
                SealedPayload(base64(document.keys), base64(document.ct), base64(document.sig))
            }
        } catch (e: IllegalArgumentException) {
            null // the strict reader's JsonException; kotlinx's SerializationException, which check leaves no room for
        } catch (e: NotSealedException) {
            null
        }

        private fun base64(value: String): ByteArray {
            if (value.isEmpty()) throw NotSealedException()
            return try {
                Base64.getDecoder().decode(value)
            } catch (e: IllegalArgumentException) {
                throw NotSealedException()
            }
        }
    }
}

/**
 * The `hapticon.sealed` document, in the member order every build has written:
 * `{"schema":"hapticon.sealed","version":1,"keys":"…","ct":"…","sig":"…"}`.
 */
@Serializable
internal class SealedDocument(
    val schema: String,
    val version: Int,
    val keys: String,
    val ct: String,
    val sig: String,
)

/** A payload that names the sealed schema but is not in its form; [EndToEnd] words the refusal itself. */
private class NotSealedException : Exception(null, null, false, false)

private object NotSealed : SchemaReport {
    override fun notAnObject(path: String, value: JsonElement): Nothing = throw NotSealedException()

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing = throw NotSealedException()

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing = throw NotSealedException()
}
