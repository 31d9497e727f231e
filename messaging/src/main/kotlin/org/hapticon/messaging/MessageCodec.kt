package org.hapticon.messaging

import org.hapticon.core.IconValidationException
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonBoolean
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonNull
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue
import org.hapticon.core.pattern.PatternException
import org.hapticon.core.pattern.PatternJson
import org.hapticon.core.pattern.PitchFit

/**
 * The wire format: UTF-8 JSON, versioned by `schema` and `version` members.
 *
 * ```
 * {"schema":"hapticon.message","version":1,"id":"<uuid>","sender":"alice","sentAt":<epoch ms>,
 *  "text":"…","sticker":"hug"|null,"icon":{icon JSON}|null}
 * {"schema":"hapticon.message","version":2, …the same members…, "icon":null,"pattern":{pattern JSON}}
 * {"schema":"hapticon.receipt","version":1,"messageId":"<uuid>","from":"bob","state":"delivered"|"read","at":<epoch ms>}
 * {"schema":"hapticon.hand","version":1,"from":"bob","thumb":12.5,"middle":48.0,"at":<epoch ms>}
 * {"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"amplitude-waveform","amplitudeControl":true,
 *  "apiLevel":34|null,"resonantFrequencyHz":170.0|null,
 *  "envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"octaves"|"clamp"}   (each optional)
 * ```
 *
 * Decoding is for untrusted input and never throws: the size is checked before parsing, the parser is
 * strict and depth-limited, and every problem becomes a [Decoded.Rejected] with a [RejectionReason].
 * Unknown members are ignored, so that newer writers can add optional members within version 1.
 *
 * A message with a haptic pattern ([ChatMessage.pattern], [PatternJson]) is written as version 2, every other
 * message still as version 1: a build that predates patterns reads version 1 only, so it keeps reading icon
 * and text messages and rejects a pattern message as `UNSUPPORTED_VERSION` ("this build reads version 1 of
 * \"hapticon.message\", got 2"), which it shows as a message it cannot read, instead of dropping the pattern
 * and showing the text as if nothing were missing.
 */
public object MessageCodec {
    /** `schema` of a chat message. */
    public const val MESSAGE_SCHEMA: String = "hapticon.message"

    /** `schema` of a receipt. */
    public const val RECEIPT_SCHEMA: String = "hapticon.receipt"

    /** `schema` of a tele-handshake sample. */
    public const val HAND_SCHEMA: String = "hapticon.hand"

    /** `schema` of a capabilities document. */
    public const val CAPABILITIES_SCHEMA: String = "hapticon.capabilities"

    /** The version this build writes for receipts, poses, capabilities and messages without a pattern. */
    public const val VERSION: Int = 1

    /** The version of a message with a pattern; this build reads messages of versions [VERSION]..[PATTERN_VERSION]. */
    public const val PATTERN_VERSION: Int = 2

    /** [message] as UTF-8 JSON. Does not throw: every valid message is encodable and within the payload limit. */
    public fun encode(message: ChatMessage): ByteArray {
        val members = listOf(
            "schema" to JsonString(MESSAGE_SCHEMA),
            "version" to JsonNumber(if (message.pattern != null) PATTERN_VERSION else VERSION),
            "id" to JsonString(message.id),
            "sender" to JsonString(message.sender),
            "sentAt" to JsonNumber(message.sentAtMillis),
            "text" to JsonString(message.text),
            "sticker" to (message.sticker?.let(::JsonString) ?: JsonNull),
            "icon" to (message.icon?.let(IconJson::toJsonValue) ?: JsonNull),
        )
        val pattern = message.pattern?.let { listOf("pattern" to PatternJson.toJsonValue(it)) }.orEmpty()
        return encodeObject(*(members + pattern).toTypedArray())
    }

    /** [receipt] as UTF-8 JSON. Does not throw. */
    public fun encode(receipt: Receipt): ByteArray = encodeObject(
        "schema" to JsonString(RECEIPT_SCHEMA),
        "version" to JsonNumber(VERSION),
        "messageId" to JsonString(receipt.messageId),
        "from" to JsonString(receipt.from),
        "state" to JsonString(receipt.state.wireName),
        "at" to JsonNumber(receipt.atMillis),
    )

    /** [pose] as UTF-8 JSON. Does not throw. */
    public fun encode(pose: HandPose): ByteArray = encodeObject(
        "schema" to JsonString(HAND_SCHEMA),
        "version" to JsonNumber(VERSION),
        "from" to JsonString(pose.from),
        "thumb" to JsonNumber(pose.thumbDegrees),
        "middle" to JsonNumber(pose.middleDegrees),
        "at" to JsonNumber(pose.atMillis),
    )

    /** [capabilities] as UTF-8 JSON. Does not throw. */
    public fun encode(capabilities: Capabilities): ByteArray = encodeObject(
        "schema" to JsonString(CAPABILITIES_SCHEMA),
        "version" to JsonNumber(VERSION),
        "user" to JsonString(capabilities.user),
        "renderer" to JsonString(capabilities.renderer.wireName),
        "amplitudeControl" to JsonBoolean(capabilities.amplitudeControl),
        "apiLevel" to (capabilities.apiLevel?.let { JsonNumber(it) } ?: JsonNull),
        "resonantFrequencyHz" to (capabilities.resonantFrequencyHz?.let { JsonNumber(it) } ?: JsonNull),
        // Added with the API 36 pitch (optional members within version 1): written only when known, so a document
        // without them stays byte for byte what older builds wrote.
        *listOfNotNull(
            capabilities.envelopeEffects?.let { "envelopeEffects" to JsonBoolean(it) },
            capabilities.frequencyRangeHz?.let { "frequencyMinHz" to JsonNumber(it.start) },
            capabilities.frequencyRangeHz?.let { "frequencyMaxHz" to JsonNumber(it.endInclusive) },
            capabilities.pitchFit?.let { "pitchFit" to JsonString(it.wireName) },
        ).toTypedArray(),
    )

    /** Decodes what arrives in an inbox: a [ChatMessage], a [Receipt] or a [HandPose]. Never throws. */
    public fun decodeInbox(payload: ByteArray): Decoded<InboxPayload> = decodeWith(payload) { fields ->
        when (fields.schema(MESSAGE_SCHEMA, RECEIPT_SCHEMA, HAND_SCHEMA, messageVersions = VERSION..PATTERN_VERSION)) {
            MESSAGE_SCHEMA -> decodeMessage(fields)
            HAND_SCHEMA -> HandPose(
                from = fields.requiredString("from"),
                thumbDegrees = fields.optionalNumber("thumb") ?: throw InvalidMessageException(RejectionReason.MISSING_FIELD, "thumb", "missing"),
                middleDegrees = fields.optionalNumber("middle") ?: throw InvalidMessageException(RejectionReason.MISSING_FIELD, "middle", "missing"),
                atMillis = fields.requiredWhole("at"),
            )
            else -> decodeReceipt(fields)
        }
    }

    /** Decodes a capabilities document. Never throws. */
    public fun decodeCapabilities(payload: ByteArray): Decoded<Capabilities> = decodeWith(payload) { fields ->
        fields.schema(CAPABILITIES_SCHEMA)
        val renderer = fields.requiredString("renderer").let { name ->
            RendererKind.entries.firstOrNull { it.wireName == name }
                ?: if (RENDERER_FORM.matches(name)) RendererKind.UNKNOWN else invalid("renderer", "expected a renderer name, got ${quote(name)}")
        }
        Capabilities(
            user = fields.requiredString("user"),
            renderer = renderer,
            amplitudeControl = fields.requiredBoolean("amplitudeControl"),
            apiLevel = fields.optionalWhole("apiLevel")?.let { if (it in 1..Capabilities.MAX_API_LEVEL) it.toInt() else invalid("apiLevel", "expected 1..${Capabilities.MAX_API_LEVEL}, got $it") },
            resonantFrequencyHz = fields.optionalNumber("resonantFrequencyHz"),
            envelopeEffects = fields.optionalBoolean("envelopeEffects"),
            frequencyRangeHz = fields.optionalNumber("frequencyMinHz").let { min ->
                val max = fields.optionalNumber("frequencyMaxHz")
                when {
                    min == null && max == null -> null
                    min == null -> fields.missing("frequencyMinHz")
                    max == null -> fields.missing("frequencyMaxHz")
                    else -> min..max
                }
            },
            // A fit a newer build names is unknown here, like a renderer: the sender then sees no pitch promise.
            pitchFit = fields.optionalString("pitchFit")?.let { name -> PitchFit.entries.firstOrNull { it.wireName == name } },
        )
    }

    private fun decodeMessage(fields: Fields): ChatMessage {
        val icon = when (val value = fields.optional("icon")) {
            null -> null
            else -> try {
                IconJson.fromJsonValue(value)
            } catch (e: IconValidationException) {
                val detail = e.message.orEmpty().removePrefix("${e.field}: ")
                throw InvalidMessageException(RejectionReason.INVALID_ICON, if (e.field == "icon") "icon" else "icon.${e.field}", detail)
            }
        }
        val pattern = if (fields.version < PATTERN_VERSION) null else decodePattern(fields.optional("pattern"))
        return ChatMessage(
            // Upper-case UUIDs name the same message; one spelling keeps deduplication by id exact.
            id = fields.requiredString("id").lowercase(),
            sender = fields.requiredString("sender"),
            sentAtMillis = fields.requiredWhole("sentAt"),
            text = fields.requiredString("text"),
            sticker = fields.optionalString("sticker"),
            icon = icon,
            pattern = pattern,
        )
    }

    private fun decodePattern(value: JsonValue?): org.hapticon.core.pattern.HapticPattern? {
        if (value == null) return null
        // Only a pattern document: PatternJson.read would also turn an icon into a pattern, which belongs in "icon".
        val schema = ((value as? JsonObject)?.get("schema") as? JsonString)?.value
        if (schema != PatternJson.SCHEMA) {
            throw InvalidMessageException(RejectionReason.INVALID_ICON, "pattern.schema", "expected \"${PatternJson.SCHEMA}\"")
        }
        return try {
            PatternJson.read(value).pattern
        } catch (e: PatternException) {
            val detail = e.message.orEmpty().removePrefix("${e.field}: ")
            throw InvalidMessageException(RejectionReason.INVALID_ICON, "pattern.${e.field}", detail)
        }
    }

    private fun decodeReceipt(fields: Fields): Receipt {
        val stateName = fields.requiredString("state")
        val state = ReceiptState.entries.firstOrNull { it.wireName == stateName }
            ?: invalid("state", "expected \"delivered\" or \"read\", got ${quote(stateName)}")
        return Receipt(
            messageId = fields.requiredString("messageId").lowercase(),
            from = fields.requiredString("from"),
            state = state,
            atMillis = fields.requiredWhole("at"),
        )
    }

    private inline fun <T> decodeWith(payload: ByteArray, decode: (Fields) -> T): Decoded<T> {
        // Checked before the bytes are even decoded as UTF-8: an oversized payload costs nothing more.
        if (payload.size > MessageLimits.MAX_PAYLOAD_BYTES) {
            return Decoded.Rejected(
                RejectionReason.PAYLOAD_TOO_LARGE, null,
                "${payload.size} bytes exceed the limit of ${MessageLimits.MAX_PAYLOAD_BYTES}",
            )
        }
        return try {
            val value = Json.decodeUtf8(payload, MessageLimits.MAX_PAYLOAD_BYTES, MessageLimits.MAX_JSON_DEPTH)
            if (value !is JsonObject) return Decoded.Rejected(RejectionReason.NOT_AN_OBJECT, null, "expected an object, got ${kind(value)}")
            Decoded.Accepted(decode(Fields(value)))
        } catch (e: JsonException) {
            Decoded.Rejected(RejectionReason.MALFORMED_JSON, null, e.message.orEmpty())
        } catch (e: InvalidMessageException) {
            Decoded.Rejected(e.reason, e.field, e.message.orEmpty().removePrefix("${e.field}: "))
        } catch (e: RuntimeException) {
            // Not reachable through the checks above; a decoder of untrusted input must be total regardless.
            Decoded.Rejected(RejectionReason.INVALID_VALUE, null, "unexpected ${e.javaClass.simpleName}: ${e.message}")
        }
    }

    private fun encodeObject(vararg members: Pair<String, JsonValue>): ByteArray =
        Json.encode(JsonObject(linkedMapOf(*members))).toByteArray(Charsets.UTF_8)

    private val RENDERER_FORM = Regex("[a-z0-9-]{1,32}")

    /** Typed access to the members of a decoded object; every problem is an [InvalidMessageException]. */
    private class Fields(private val json: JsonObject) {
        /** The document's version, known once [schema] has accepted it. */
        var version: Int = VERSION
            private set

        fun schema(vararg accepted: String, messageVersions: IntRange = VERSION..VERSION): String {
            val schema = json["schema"] ?: throw InvalidMessageException(RejectionReason.UNKNOWN_SCHEMA, "schema", "missing")
            val name = (schema as? JsonString)?.value
            if (name == null || name !in accepted) {
                throw InvalidMessageException(
                    RejectionReason.UNKNOWN_SCHEMA, "schema",
                    "expected ${accepted.joinToString(" or ") { "\"$it\"" }}, got ${snippet(schema)}",
                )
            }
            // The version comes right after the schema: a newer document may have changed any other member.
            val version = json["version"]
            val readable = if (name == MESSAGE_SCHEMA) messageVersions else VERSION..VERSION
            val number = (version as? JsonNumber)?.value
            if (number == null || number != Math.rint(number) || number < readable.first || number > readable.last) {
                val versions = if (readable.first == readable.last) "version ${readable.first}" else "versions ${readable.first}–${readable.last}"
                throw InvalidMessageException(
                    RejectionReason.UNSUPPORTED_VERSION, "version",
                    "this build reads $versions of \"$name\", got ${version?.let(::snippet) ?: "none"}",
                )
            }
            this.version = number.toInt()
            return name
        }

        fun optional(field: String): JsonValue? = json[field]?.takeUnless { it == JsonNull }

        fun requiredString(field: String): String = optionalString(field) ?: missing(field)

        fun optionalString(field: String): String? {
            val value = optional(field) ?: return null
            return (value as? JsonString)?.value ?: wrongType(field, "a string", value)
        }

        fun optionalBoolean(field: String): Boolean? {
            val value = optional(field) ?: return null
            return (value as? JsonBoolean)?.value ?: wrongType(field, "true or false", value)
        }

        fun requiredBoolean(field: String): Boolean {
            val value = optional(field) ?: missing(field)
            return (value as? JsonBoolean)?.value ?: wrongType(field, "true or false", value)
        }

        fun optionalNumber(field: String): Double? {
            val value = optional(field) ?: return null
            val number = (value as? JsonNumber)?.value ?: wrongType(field, "a number", value)
            // JSON has no NaN or infinity, but 1e400 overflows a double to infinity.
            if (!number.isFinite()) invalid(field, "expected a finite number, got ${snippet(value)}")
            return number
        }

        fun requiredWhole(field: String): Long = optionalWhole(field) ?: missing(field)

        fun optionalWhole(field: String): Long? {
            val number = optionalNumber(field) ?: return null
            if (number != Math.rint(number)) invalid(field, "expected a whole number, got ${snippet(json[field]!!)}")
            // Beyond 2^53 a double is no longer an exact integer; no field of ours gets near it.
            if (Math.abs(number) > MAX_EXACT_INTEGER) invalid(field, "${snippet(json[field]!!)} is out of range")
            return number.toLong()
        }

        fun missing(field: String): Nothing = throw InvalidMessageException(RejectionReason.MISSING_FIELD, field, "missing")

        private fun wrongType(field: String, expected: String, value: JsonValue): Nothing =
            throw InvalidMessageException(RejectionReason.WRONG_TYPE, field, "expected $expected, got ${snippet(value)}")
    }

    private const val MAX_EXACT_INTEGER = 9.007199254740992E15
}

private fun invalid(field: String, detail: String): Nothing = throw InvalidMessageException(RejectionReason.INVALID_VALUE, field, detail)

private fun kind(value: JsonValue): String = when (value) {
    is JsonObject -> "an object"
    is org.hapticon.core.io.JsonArray -> "an array"
    is JsonString -> "a string"
    is JsonNumber -> "a number"
    is JsonBoolean -> "a boolean"
    JsonNull -> "null"
}

/** A short rendering of [value] for a one-line detail: strings quoted and cut, containers by kind. */
private fun snippet(value: JsonValue): String = when (value) {
    is JsonString -> quote(value.value)
    is JsonNumber -> if (value.isIntegral && Math.abs(value.value) <= 9.007199254740992E15) value.value.toLong().toString() else value.value.toString()
    is JsonBoolean -> value.value.toString()
    JsonNull -> "null"
    else -> kind(value)
}

/** The value of the capabilities' `pitchFit` member. */
public val PitchFit.wireName: String
    get() = when (this) {
        PitchFit.OCTAVES -> "octaves"
        PitchFit.CLAMP -> "clamp"
    }
