package org.hapticon.core.io

import kotlinx.serialization.KSerializer
import kotlinx.serialization.Serializable
import kotlinx.serialization.SerializationException
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.PrimitiveSerialDescriptor
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.encoding.Decoder
import kotlinx.serialization.encoding.Encoder
import kotlinx.serialization.json.JsonDecoder
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException

/** An icon, schema `hapticon.icon` ([IconJson]); members in schema order. */
@Serializable
internal class IconDocument(
    val schema: String,
    val version: Long,
    val name: String,
    @Serializable(with = ShortDouble::class) val attack: Double,
    @Serializable(with = ShortDouble::class) val sustain: Double,
    @Serializable(with = ShortDouble::class) val level: Double,
    @Serializable(with = ShortDouble::class) val release: Double,
    @Serializable(with = ShortDouble::class) val note: Double,
    @Serializable(with = ShortDouble::class) val period: Double = 0.0,
    val count: Long = 1,
)

/**
 * A [HapticIcon] as its `hapticon.icon` document, for formats that embed an icon (the chat message): written
 * straight to the output, member by member as [IconJson.encode] writes it, instead of building the tree of
 * [IconJson.toJsonElement] first and writing that (about a quarter of a chat message's encoding, docs/json.md
 * "Speed of the chat codec"). Read as a tree and checked by [IconJson.fromJsonElement], with its wording, so it
 * reads JSON only; an invalid icon throws [IconValidationException] (kotlinx's string decoder hands it on as the
 * cause of a `JsonDecodingException` naming the path; the chat codec reads its icon from its own tree instead).
 */
public object HapticIconSerializer : KSerializer<HapticIcon> {
    override val descriptor: SerialDescriptor get() = IconDocument.serializer().descriptor

    override fun serialize(encoder: Encoder, value: HapticIcon) {
        encoder.encodeSerializableValue(IconDocument.serializer(), IconJson.document(value))
    }

    override fun deserialize(decoder: Decoder): HapticIcon {
        val json = decoder as? JsonDecoder ?: throw SerializationException("a hapticon.icon is read from JSON only")
        return IconJson.fromJsonElement(json.decodeJsonElement())
    }
}

/**
 * A double written as an integer when it is one within ±2^53 (`57`, not `57.0`), as icons have always been
 * written: messages and files stay byte-identical to those of earlier builds. Reads either spelling.
 */
public object ShortDouble : KSerializer<Double> {
    override val descriptor: SerialDescriptor = PrimitiveSerialDescriptor("org.hapticon.ShortDouble", PrimitiveKind.DOUBLE)

    override fun serialize(encoder: Encoder, value: Double) {
        val whole = value == Math.rint(value) && Math.abs(value) <= 9.007199254740992E15 && !(value == 0.0 && 1.0 / value < 0)
        if (whole) encoder.encodeLong(value.toLong()) else encoder.encodeDouble(value)
    }

    override fun deserialize(decoder: Decoder): Double = decoder.decodeDouble()
}

/** Icons' wording of schema problems: an [IconValidationException] naming the member; `null` is a wrong type. */
internal object IconReport : SchemaReport {
    override val nullMeansAbsent: Boolean get() = false

    override fun notAnObject(path: String, value: JsonElement): Nothing =
        throw IconValidationException("icon", "expected an object, got ${snippet(value)}")

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing {
        if (value == null) throw IconValidationException(member, if (member == "schema") "missing; expected \"${IconJson.SCHEMA}\"" else "missing")
        val got = snippet(value)
        val number = (value as? JsonPrimitive)?.takeUnless { it.isString }?.doubleOrNull
        throw IconValidationException(
            member,
            when {
                member == "schema" -> "expected \"${IconJson.SCHEMA}\", got $got"
                expected == JsonKind.STRING -> "expected a string, got $got"
                number == null -> "expected a number, got $got"
                !number.isFinite() -> "expected a finite number, got $got"
                number != Math.rint(number) -> "expected an integer, got $got"
                else -> "integer $got is out of range"
            },
        )
    }

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
        throw IconValidationException("$member[$index]", "expected ${expected.name.lowercase()}, got ${snippet(value)}")

    // Schema and version come first: a newer document may have changed any other member.
    override fun checked(path: String, member: String, value: JsonElement) {
        val found = (value as? JsonPrimitive)?.content ?: return
        when (member) {
            "schema" -> if (found != IconJson.SCHEMA) throw IconValidationException(member, "expected \"${IconJson.SCHEMA}\", got ${snippet(value)}")
            "version" -> if (found != "${IconJson.VERSION}") {
                throw IconValidationException(member, "unsupported icon schema version $found (this build reads version ${IconJson.VERSION})")
            }
        }
    }
}
