package org.hapticon.messaging

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.KSerializer
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.core.io.HapticIconSerializer
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.SchemaReport
import org.hapticon.core.io.ShortDouble
import org.hapticon.core.io.numberOrNull
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternException
import org.hapticon.core.pattern.PatternJson
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind

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
 *  "envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"octaves"|"clamp",
 *  "envelopeMaxControlPoints":16,"envelopeMinControlPointMillis":20,"envelopeMaxControlPointMillis":1000,
 *  "envelopeMaxDurationMillis":16000}   (each optional; the frequency pair and the four envelope limits all or none)
 * ```
 *
 * Each document is a `@Serializable` type (`MessageDocument` …, this file), encoded by kotlinx-serialization;
 * the schema names and versions are in [WireFormats]. Decoding is for untrusted input and never throws: the
 * size is checked before parsing, the strict reader ([SchemaJson.parseUtf8]) refuses malformed text, duplicate
 * names and nesting deeper than [MessageLimits.MAX_JSON_DEPTH], [SchemaJson.check] checks the members against
 * the type with this format's wording ([WireReport]), and every problem becomes a [Decoded.Rejected] with a
 * [RejectionReason].
 * Unknown members are ignored, so that newer writers can add optional members within version 1.
 *
 * A message with a haptic pattern ([ChatMessage.pattern], [PatternJson]) is written as version 2, every other
 * message still as version 1: a build that predates patterns reads version 1 only, so it keeps reading icon
 * and text messages and rejects a pattern message as `UNSUPPORTED_VERSION` ("this build reads version 1 of
 * \"hapticon.message\", got 2"), which it shows as a message it cannot read, instead of dropping the pattern
 * and showing the text as if nothing were missing.
 */
public object MessageCodec {
    /** `schema` of a chat message ([WireFormats.MESSAGE_SCHEMA]). */
    public const val MESSAGE_SCHEMA: String = WireFormats.MESSAGE_SCHEMA

    /** `schema` of a receipt ([WireFormats.RECEIPT_SCHEMA]). */
    public const val RECEIPT_SCHEMA: String = WireFormats.RECEIPT_SCHEMA

    /** `schema` of a tele-handshake sample ([WireFormats.HAND_SCHEMA]). */
    public const val HAND_SCHEMA: String = WireFormats.HAND_SCHEMA

    /** `schema` of a capabilities document ([WireFormats.CAPABILITIES_SCHEMA]). */
    public const val CAPABILITIES_SCHEMA: String = WireFormats.CAPABILITIES_SCHEMA

    /** The version this build writes for receipts, poses, capabilities and messages without a pattern ([WireFormats.VERSION]). */
    public const val VERSION: Int = WireFormats.VERSION

    /** The version of a message with a pattern; this build reads messages of versions [VERSION]..[PATTERN_VERSION] ([WireFormats.PATTERN_MESSAGE_VERSION]). */
    public const val PATTERN_VERSION: Int = WireFormats.PATTERN_MESSAGE_VERSION

    /** [message] as UTF-8 JSON. Does not throw: every valid message is encodable and within the payload limit. */
    public fun encode(message: ChatMessage): ByteArray = encode(
        MESSAGE_WRITER,
        MessageDocument(
            MESSAGE_SCHEMA, if (message.pattern != null) PATTERN_VERSION else VERSION, message.id, message.sender, message.sentAtMillis,
            message.text, message.sticker, message.icon, message.pattern?.let(PatternJson::toJsonElement),
        ),
    )

    /** [receipt] as UTF-8 JSON. Does not throw. */
    public fun encode(receipt: Receipt): ByteArray = encode(
        ReceiptDocument.serializer(),
        ReceiptDocument(RECEIPT_SCHEMA, VERSION, receipt.messageId, receipt.from, receipt.state.wireName, receipt.atMillis),
    )

    /** [pose] as UTF-8 JSON. Does not throw. */
    public fun encode(pose: HandPose): ByteArray = encode(
        HandDocument.serializer(),
        HandDocument(HAND_SCHEMA, VERSION, pose.from, pose.thumbDegrees, pose.middleDegrees, pose.atMillis),
    )

    /** [capabilities] as UTF-8 JSON. Does not throw. */
    public fun encode(capabilities: Capabilities): ByteArray = encode(
        CapabilitiesDocument.serializer(),
        CapabilitiesDocument(
            CAPABILITIES_SCHEMA, VERSION, capabilities.user, capabilities.renderer.wireName, capabilities.amplitudeControl,
            capabilities.apiLevel?.toLong(), capabilities.resonantFrequencyHz,
            // Added with the API 36 pitch (optional members within version 1): written only when known, so a document
            // without them stays byte for byte what older builds wrote.
            envelopeEffects = capabilities.envelopeEffects,
            frequencyMinHz = capabilities.frequencyRangeHz?.start,
            frequencyMaxHz = capabilities.frequencyRangeHz?.endInclusive,
            pitchFit = capabilities.pitchFit?.wireName,
            // Added with the published envelope limits, the same way: absent when unknown.
            envelopeMaxControlPoints = capabilities.envelopeLimits?.maxControlPoints?.toLong(),
            envelopeMinControlPointMillis = capabilities.envelopeLimits?.minControlPointMillis,
            envelopeMaxControlPointMillis = capabilities.envelopeLimits?.maxControlPointMillis,
            envelopeMaxDurationMillis = capabilities.envelopeLimits?.maxDurationMillis,
        ),
    )

    /** Decodes what arrives in an inbox: a [ChatMessage], a [Receipt] or a [HandPose]. Never throws. */
    public fun decodeInbox(payload: ByteArray): Decoded<InboxPayload> = decodeWith(payload) { json ->
        val (schema, version) = schema(json, MESSAGE_SCHEMA, RECEIPT_SCHEMA, HAND_SCHEMA)
        when (schema) {
            MESSAGE_SCHEMA -> decodeMessage(SchemaJson.decode(MESSAGE_READER, json, WireReport), version)
            HAND_SCHEMA -> SchemaJson.decode(HandDocument.serializer(), json, WireReport).let { HandPose(it.from, it.thumb, it.middle, it.at) }
            else -> decodeReceipt(SchemaJson.decode(ReceiptDocument.serializer(), json, WireReport))
        }
    }

    /** Decodes a capabilities document. Never throws. */
    public fun decodeCapabilities(payload: ByteArray): Decoded<Capabilities> = decodeWith(payload) { json ->
        schema(json, CAPABILITIES_SCHEMA)
        val doc = SchemaJson.decode(CapabilitiesDocument.serializer(), json, WireReport)
        val renderer = RendererKind.entries.firstOrNull { it.wireName == doc.renderer }
            ?: if (RENDERER_FORM.matches(doc.renderer)) RendererKind.UNKNOWN else invalid("renderer", "expected a renderer name, got ${quote(doc.renderer)}")
        Capabilities(
            user = doc.user,
            renderer = renderer,
            amplitudeControl = doc.amplitudeControl,
            apiLevel = doc.apiLevel?.let { if (it in 1..Capabilities.MAX_API_LEVEL) it.toInt() else invalid("apiLevel", "expected 1..${Capabilities.MAX_API_LEVEL}, got $it") },
            resonantFrequencyHz = doc.resonantFrequencyHz,
            envelopeEffects = doc.envelopeEffects,
            frequencyRangeHz = when {
                doc.frequencyMinHz == null && doc.frequencyMaxHz == null -> null
                doc.frequencyMinHz == null -> throw InvalidMessageException(RejectionReason.MISSING_FIELD, "frequencyMinHz", "missing")
                doc.frequencyMaxHz == null -> throw InvalidMessageException(RejectionReason.MISSING_FIELD, "frequencyMaxHz", "missing")
                else -> doc.frequencyMinHz..doc.frequencyMaxHz
            },
            // A fit a newer build names is unknown here, like a renderer: the sender then sees no pitch promise.
            pitchFit = doc.pitchFit?.let { name -> PitchFit.entries.firstOrNull { it.wireName == name } },
            envelopeLimits = envelopeLimitsOf(doc),
        )
    }

    // The four envelope limits come together (one VibratorEnvelopeEffectInfo) or not at all: a document without them
    // is an older build's or a phone without envelope effects, and its reader assumes the guaranteed ones.
    private fun envelopeLimitsOf(doc: CapabilitiesDocument): EnvelopeEffectInfo? {
        val members = listOf(
            "envelopeMaxControlPoints" to doc.envelopeMaxControlPoints,
            "envelopeMinControlPointMillis" to doc.envelopeMinControlPointMillis,
            "envelopeMaxControlPointMillis" to doc.envelopeMaxControlPointMillis,
            "envelopeMaxDurationMillis" to doc.envelopeMaxDurationMillis,
        )
        if (members.all { it.second == null }) return null
        members.firstOrNull { it.second == null }?.let { (field, _) -> throw InvalidMessageException(RejectionReason.MISSING_FIELD, field, "missing") }
        val (points, min, max, total) = members.map { it.second!! }
        // Range-checked here before the Int conversion; the Capabilities constructor checks how they relate.
        if (points !in 1..Capabilities.MAX_ENVELOPE_CONTROL_POINTS) {
            invalid("envelopeMaxControlPoints", "expected 1..${Capabilities.MAX_ENVELOPE_CONTROL_POINTS}, got $points")
        }
        return EnvelopeEffectInfo(points.toInt(), min, max, total)
    }

    private fun decodeMessage(doc: MessageDocument<JsonElement>, version: Int): ChatMessage {
        val icon = doc.icon?.takeUnless { it is JsonNull }?.let { value ->
            try {
                IconJson.fromJsonElement(value)
            } catch (e: IconValidationException) {
                val detail = e.message.orEmpty().removePrefix("${e.field}: ")
                throw InvalidMessageException(RejectionReason.INVALID_ICON, if (e.field == "icon") "icon" else "icon.${e.field}", detail)
            }
        }
        val pattern = if (version < PATTERN_VERSION) null else decodePattern(doc.pattern?.takeUnless { it is JsonNull })
        return ChatMessage(
            // Upper-case UUIDs name the same message; one spelling keeps deduplication by id exact.
            id = doc.id.lowercase(),
            sender = doc.sender,
            sentAtMillis = doc.sentAt,
            text = doc.text,
            sticker = doc.sticker,
            icon = icon,
            pattern = pattern,
        )
    }

    private fun decodePattern(value: JsonElement?): HapticPattern? {
        if (value == null) return null
        // Only a pattern document: PatternJson.read would also turn an icon into a pattern, which belongs in "icon".
        val schema = ((value as? JsonObject)?.get("schema") as? JsonPrimitive)?.takeIf { it.isString }?.content
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

    private fun decodeReceipt(doc: ReceiptDocument): Receipt {
        val state = ReceiptState.entries.firstOrNull { it.wireName == doc.state }
            ?: invalid("state", "expected \"delivered\" or \"read\", got ${quote(doc.state)}")
        return Receipt(messageId = doc.messageId.lowercase(), from = doc.from, state = state, atMillis = doc.at)
    }

    /**
     * The document's schema, one of [accepted], and its version, checked before any other member: a newer
     * document may have changed any of them.
     */
    private fun schema(json: JsonObject, vararg accepted: String): Pair<String, Int> {
        val schema = json["schema"] ?: throw InvalidMessageException(RejectionReason.UNKNOWN_SCHEMA, "schema", "missing")
        val name = (schema as? JsonPrimitive)?.takeIf { it.isString }?.content
        if (name == null || name !in accepted) {
            throw InvalidMessageException(
                RejectionReason.UNKNOWN_SCHEMA, "schema",
                "expected ${accepted.joinToString(" or ") { "\"$it\"" }}, got ${snippet(schema)}",
            )
        }
        val version = json["version"]
        val readable = if (name == MESSAGE_SCHEMA) VERSION..PATTERN_VERSION else VERSION..VERSION
        val number = (version as? JsonPrimitive)?.takeUnless { it is JsonNull }?.numberOrNull()
        if (number == null || number != Math.rint(number) || number < readable.first || number > readable.last) {
            val versions = if (readable.first == readable.last) "version ${readable.first}" else "versions ${readable.first}–${readable.last}"
            throw InvalidMessageException(
                RejectionReason.UNSUPPORTED_VERSION, "version",
                "this build reads $versions of \"$name\", got ${version?.let(::snippet) ?: "none"}",
            )
        }
        return name to number.toInt()
    }

    private inline fun <T> decodeWith(payload: ByteArray, decode: (JsonObject) -> T): Decoded<T> {
        // Checked before the bytes are even decoded as UTF-8: an oversized payload costs nothing more.
        if (payload.size > MessageLimits.MAX_PAYLOAD_BYTES) {
            return Decoded.Rejected(
                RejectionReason.PAYLOAD_TOO_LARGE, null,
                "${payload.size} bytes exceed the limit of ${MessageLimits.MAX_PAYLOAD_BYTES}",
            )
        }
        return try {
            val value = SchemaJson.parseUtf8(payload, MessageLimits.MAX_PAYLOAD_BYTES, MessageLimits.MAX_JSON_DEPTH)
            if (value !is JsonObject) return Decoded.Rejected(RejectionReason.NOT_AN_OBJECT, null, "expected an object, got ${kind(value)}")
            Decoded.Accepted(decode(value))
        } catch (e: JsonException) {
            Decoded.Rejected(RejectionReason.MALFORMED_JSON, null, e.message.orEmpty())
        } catch (e: InvalidMessageException) {
            Decoded.Rejected(e.reason, e.field, e.message.orEmpty().removePrefix("${e.field}: "))
        } catch (e: RuntimeException) {
            // Not reachable through the checks above; a decoder of untrusted input must be total regardless.
            Decoded.Rejected(RejectionReason.INVALID_VALUE, null, "unexpected ${e.javaClass.simpleName}: ${e.message}")
        }
    }

    private fun <T> encode(serializer: KSerializer<T>, document: T): ByteArray =
        SchemaJson.format.encodeToString(serializer, document).toByteArray(Charsets.UTF_8)

    private val RENDERER_FORM = Regex("[a-z0-9-]{1,32}")

    // The two forms of the one message type, made once (a generic class's serializer is built per call otherwise).
    // Written: the icon goes straight from its document to the text (HapticIconSerializer); the tree IconJson.toJsonElement
    // built first cost about a quarter of an encode (docs/json.md, "Speed of the chat codec"). Read: the icon is a tree,
    // so that IconJson checks it with its own wording (icon.attack: …) after the message's members are checked.
    private val MESSAGE_WRITER = MessageDocument.serializer(HapticIconSerializer)
    private val MESSAGE_READER = MessageDocument.serializer(JsonElement.serializer())
}

/**
 * A chat message on the wire (`hapticon.message`, versions 1 and 2); members in wire order. [I] is how the icon is
 * held: a [HapticIcon] when written, a [JsonElement] when read (see `MESSAGE_WRITER`/`MESSAGE_READER`).
 */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class MessageDocument<I>(
    val schema: String,
    val version: Int,
    val id: String,
    val sender: String,
    val sentAt: Long,
    val text: String,
    val sticker: String? = null,
    // Icon and pattern keep their own formats' checks and wording (IconJson, PatternJson), so they are read as trees.
    val icon: I? = null,
    // Absent from version 1 messages, which is what builds before patterns expect.
    @EncodeDefault(EncodeDefault.Mode.NEVER) val pattern: JsonElement? = null,
)

/** A receipt on the wire (`hapticon.receipt`, version 1). */
@Serializable
internal class ReceiptDocument(val schema: String, val version: Int, val messageId: String, val from: String, val state: String, val at: Long)

/** A tele-handshake sample on the wire (`hapticon.hand`, version 1); angles written without a fraction when whole. */
@Serializable
internal class HandDocument(
    val schema: String,
    val version: Int,
    val from: String,
    @Serializable(with = ShortDouble::class) val thumb: Double,
    @Serializable(with = ShortDouble::class) val middle: Double,
    val at: Long,
)

/** A capabilities document on the wire (`hapticon.capabilities`, version 1). */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class CapabilitiesDocument(
    val schema: String,
    val version: Int,
    val user: String,
    val renderer: String,
    val amplitudeControl: Boolean,
    val apiLevel: Long? = null,
    @Serializable(with = ShortDouble::class) val resonantFrequencyHz: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val envelopeEffects: Boolean? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val frequencyMinHz: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val frequencyMaxHz: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val pitchFit: String? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val envelopeMaxControlPoints: Long? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val envelopeMinControlPointMillis: Long? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val envelopeMaxControlPointMillis: Long? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val envelopeMaxDurationMillis: Long? = null,
)

/** The wire format's wording of schema problems: an [InvalidMessageException] with the [RejectionReason] and a one-line detail. */
internal object WireReport : SchemaReport {
    override fun notAnObject(path: String, value: JsonElement): Nothing =
        throw InvalidMessageException(RejectionReason.WRONG_TYPE, path, "expected an object, got ${kind(value)}")

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing {
        val field = if (path.isEmpty()) member else "$path.$member"
        if (value == null) throw InvalidMessageException(RejectionReason.MISSING_FIELD, field, "missing")
        val number = (value as? JsonPrimitive)?.takeUnless { it is JsonNull }?.numberOrNull()
        val wanted = when (expected) {
            JsonKind.STRING -> "a string"
            JsonKind.BOOLEAN -> "true or false"
            JsonKind.OBJECT -> "an object"
            JsonKind.ARRAY -> "an array"
            else -> "a number"
        }
        when {
            number == null || expected == JsonKind.STRING || expected == JsonKind.BOOLEAN ->
                throw InvalidMessageException(RejectionReason.WRONG_TYPE, field, "expected $wanted, got ${snippet(value)}")
            // JSON has no NaN or infinity, but 1e400 overflows a double to infinity.
            !number.isFinite() -> invalid(field, "expected a finite number, got ${snippet(value)}")
            number != Math.rint(number) -> invalid(field, "expected a whole number, got ${snippet(value)}")
            // Beyond 2^53 a double is no longer an exact integer; no member of ours gets near it.
            else -> invalid(field, "${snippet(value)} is out of range")
        }
    }

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
        throw InvalidMessageException(RejectionReason.WRONG_TYPE, "$member[$index]", "expected ${expected.name.lowercase()}, got ${snippet(value)}")
}

private fun invalid(field: String, detail: String): Nothing = throw InvalidMessageException(RejectionReason.INVALID_VALUE, field, detail)

private fun kind(value: JsonElement): String = when (value) {
    is JsonObject -> "an object"
    is JsonArray -> "an array"
    JsonNull -> "null"
    is JsonPrimitive -> when {
        value.isString -> "a string"
        value.content == "true" || value.content == "false" -> "a boolean"
        else -> "a number"
    }
}

/** A short rendering of [value] for a one-line detail: strings quoted and cut, containers by kind, numbers as written before. */
private fun snippet(value: JsonElement): String = when {
    value is JsonPrimitive && value.isString -> quote(value.content)
    value is JsonPrimitive && value !is JsonNull && value.content != "true" && value.content != "false" -> {
        // Integers beyond ±2^53 were always shown as the double they read as.
        val whole = value.content.toLongOrNull()
        if (whole != null && Math.abs(whole.toDouble()) > 9.007199254740992E15) whole.toDouble().toString() else value.content
    }
    value is JsonPrimitive -> value.content
    else -> kind(value)
}

/** The value of the capabilities' `renderer` member; [UNKNOWN][RendererKind.UNKNOWN] is written as `unknown`. */
public val RendererKind.wireName: String
    get() = when (this) {
        RendererKind.AUDIO_COUPLED -> "audio-coupled"
        RendererKind.ENVELOPE -> "envelope"
        RendererKind.AMPLITUDE_WAVEFORM -> "amplitude-waveform"
        RendererKind.ON_OFF -> "on-off"
        RendererKind.AUDIO -> "audio"
        RendererKind.NONE -> "none"
        RendererKind.UNKNOWN -> "unknown"
    }

/** The value of the capabilities' `pitchFit` member. */
public val PitchFit.wireName: String
    get() = when (this) {
        PitchFit.OCTAVES -> "octaves"
        PitchFit.CLAMP -> "clamp"
    }
