package org.hapticon.sensor.electrotactile

import java.math.BigDecimal
import java.time.Instant
import java.time.format.DateTimeParseException
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.descriptors.StructureKind
import kotlinx.serialization.encoding.CompositeDecoder
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.SchemaReport
import org.hapticon.sensor.SensorFormats
import org.hapticon.sensor.safety.SafetyLimits

/**
 * One person's finished electrotactile calibration as it is kept between sessions: the calibrated [result] (the
 * amplitude step of electrodes 1..9), when it was made ([calibratedAt]) and, when given, who it belongs to
 * ([participant], an id or label; at most [CalibrationFile.MAX_PARTICIPANT_LENGTH] characters, no control characters).
 */
public data class StoredCalibration(
    /** The calibrated steps, each checked against 0..200 (2.7 mA). */
    val result: ElectrotactileCalibrationResult,
    /** When the calibration finished. */
    val calibratedAt: Instant,
    /** The participant's id or label, or null. */
    val participant: String? = null,
) {
    init {
        participant?.let(CalibrationFile::participantProblem)?.let { throw IllegalArgumentException("participant: $it") }
    }
}

/** A calibration file that cannot be used: [field] names the member (`electrodes[3].step`; empty for the document). */
public class CalibrationFileException(
    /** The member at fault, as a path (`schema`, `electrodes[3].milliamps`), or empty for the whole document. */
    public val field: String,
    detail: String,
) : IllegalArgumentException(if (field.isEmpty()) detail else "$field: $detail")

/**
 * The electrotactile calibration file, schema `hapticon.electrotactile-calibration` version 1 ([SensorFormats]): what
 * `hapticon board calibrate --save` writes and `hapticon board set --calibration` reads (docs/protocols.md, "From a
 * laptop"), in the project's JSON conventions (docs/json.md: a `@Serializable` document written by
 * kotlinx-serialization, read by the strict reader and [SchemaJson.check]). Example, members in this order:
 *
 * ```
 * {"schema": "hapticon.electrotactile-calibration", "version": 1, "participant": "P07",
 *  "calibratedAt": "2026-11-27T00:12:03Z",
 *  "electrodes": [{"electrode": 1, "step": 61, "milliamps": 0.8235}, … nine, electrodes 1..9 in order]}
 * ```
 *
 * The step is what is sent (Shaping Compliance's hardware: 200 steps over 0–2.7 mA, [AmplitudeSteps]); `milliamps`
 * is the current it means, written for the reader of the file. Reading is stricter than our other formats, because
 * this file drives a current through a person: an unknown member (a misspelt `stpe` would otherwise be ignored), a
 * wrong schema or version, other than nine electrodes, an electrode out of order, a step outside 0..200, a
 * `milliamps` that is not exactly the step's current (a hand-edited file whose two numbers disagree: which one did
 * the researcher mean?) or a time that is not ISO-8601 is refused as a [CalibrationFileException] naming the member.
 * JSON itself has no NaN or infinity, so those are refused by the strict reader (not valid JSON, at its offset).
 */
public object CalibrationFile {
    /** Largest file read: a calibration is under 1 KiB, so anything past this is not one. */
    public const val MAX_BYTES: Int = 16 * 1024

    /** Longest participant id or label. */
    public const val MAX_PARTICIPANT_LENGTH: Int = 64

    /** [calibration] as the file's text: two-space indent, one member per line, a final newline. */
    public fun encode(calibration: StoredCalibration): String {
        val document = CalibrationDocument(
            schema = SensorFormats.CALIBRATION_SCHEMA,
            version = SensorFormats.CALIBRATION_VERSION,
            participant = calibration.participant,
            calibratedAt = calibration.calibratedAt.toString(),
            electrodes = calibration.result.steps.mapIndexed { i, step -> ElectrodeDocument(i + 1, step, milliampsOf(step)) },
        )
        return SchemaJson.encode(CalibrationDocument.serializer(), document, "  ") + "\n"
    }

    /**
     * The calibration in the UTF-8 [bytes] of a file.
     * @throws CalibrationFileException naming the member at fault (see the class comment for what is refused).
     */
    public fun decode(bytes: ByteArray): StoredCalibration {
        if (bytes.size > MAX_BYTES) throw CalibrationFileException("", "larger than $MAX_BYTES bytes: not a calibration file")
        val tree = try {
            SchemaJson.parseUtf8(bytes, maxLength = MAX_BYTES)
        } catch (e: JsonException) {
            throw CalibrationFileException("", "not valid JSON: ${e.message}")
        }
        val document = SchemaJson.decode(CalibrationDocument.serializer(), tree, Report)
        rejectUnknownMembers(tree, CalibrationDocument.serializer().descriptor, "")
        if (document.electrodes.size != ElectrotactileCalibration.ELECTRODES) {
            throw CalibrationFileException("electrodes", "needs ${ElectrotactileCalibration.ELECTRODES} electrodes (1..9), has ${document.electrodes.size}")
        }
        val steps = document.electrodes.mapIndexed { i, electrode ->
            val at = "electrodes[$i]"
            if (electrode.electrode != i + 1) throw CalibrationFileException("$at.electrode", "must be ${i + 1} (electrodes 1..9 in order), was ${electrode.electrode}")
            if (electrode.step !in 0..AmplitudeSteps.STEPS) {
                throw CalibrationFileException("$at.step", "must be in 0..${AmplitudeSteps.STEPS} (${SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS} mA), was ${electrode.step}")
            }
            val expected = milliampsOf(electrode.step)
            if (electrode.milliamps != expected) {
                throw CalibrationFileException("$at.milliamps", "${electrode.milliamps} is not the current of step ${electrode.step} ($expected mA)")
            }
            electrode.step
        }
        val calibratedAt = try {
            Instant.parse(document.calibratedAt)
        } catch (e: DateTimeParseException) {
            throw CalibrationFileException("calibratedAt", "must be an ISO-8601 UTC time such as 2026-11-27T00:12:03Z, was \"${document.calibratedAt}\"")
        }
        document.participant?.let { participant -> participantProblem(participant)?.let { throw CalibrationFileException("participant", it) } }
        return StoredCalibration(ElectrotactileCalibrationResult(steps), calibratedAt, document.participant)
    }

    /**
     * The current of [step] as the file writes it: step × 0.0135 mA computed in decimal, so it is the exact 4-decimal
     * current (0.81, not 0.8099999999999999) and reads back as the same double.
     * @throws org.hapticon.sensor.safety.SafetyLimitException when [step] is outside 0..200.
     */
    public fun milliampsOf(step: Int): Double = BigDecimal.valueOf(SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS)
        .multiply(BigDecimal(AmplitudeSteps.requireStep(step)))
        .divide(BigDecimal(AmplitudeSteps.STEPS))
        .toDouble()

    /**
     * Why [participant] cannot be stored (empty, longer than [MAX_PARTICIPANT_LENGTH], or holding a control or line
     * separator character, which would break the one-line messages that quote it), or null when it can.
     */
    public fun participantProblem(participant: String): String? = when {
        participant.isBlank() -> "must not be empty"
        participant.length > MAX_PARTICIPANT_LENGTH -> "at most $MAX_PARTICIPANT_LENGTH characters, has ${participant.length}"
        participant.any { Character.isISOControl(it) || it == '\u2028' || it == '\u2029' } -> "must not hold control characters or line breaks"
        else -> null
    }

    // SchemaJson ignores unknown members (newer writers may add some within a version, docs/json.md); this file is
    // refused instead, so a misspelt member is never silently dropped from a file that sets currents.
    @OptIn(ExperimentalSerializationApi::class)
    private fun rejectUnknownMembers(element: JsonElement, descriptor: SerialDescriptor, path: String) {
        val obj = element as? JsonObject ?: return
        for ((name, value) in obj) {
            val at = if (path.isEmpty()) name else "$path.$name"
            val index = descriptor.getElementIndex(name)
            if (index == CompositeDecoder.UNKNOWN_NAME) {
                throw CalibrationFileException(at, "unknown member (version ${SensorFormats.CALIBRATION_VERSION} has ${(0 until descriptor.elementsCount).joinToString(", ") { descriptor.getElementName(it) }})")
            }
            val child = descriptor.getElementDescriptor(index)
            if (child.kind == StructureKind.LIST && value is JsonArray) {
                value.forEachIndexed { i, item -> rejectUnknownMembers(item, child.getElementDescriptor(0), "$at[$i]") }
            }
        }
    }

    /** Schema problems in one line each, naming the member; `schema` and `version` are checked as soon as they are read. */
    private object Report : SchemaReport {
        override fun notAnObject(path: String, value: JsonElement): Nothing =
            throw CalibrationFileException(path, if (path.isEmpty()) "expected a JSON object" else "expected an object")

        override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing =
            throw CalibrationFileException(join(path, member), if (value == null) "missing" else "must be ${word(expected)}, was $value")

        override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
            throw CalibrationFileException("${join(path, member)}[$index]", "must be ${word(expected)}, was $value")

        override fun checked(path: String, member: String, value: JsonElement) {
            if (path.isNotEmpty()) return
            when (member) {
                "schema" -> {
                    val schema = (value as JsonPrimitive).content
                    if (schema != SensorFormats.CALIBRATION_SCHEMA) {
                        throw CalibrationFileException("schema", "must be \"${SensorFormats.CALIBRATION_SCHEMA}\", was \"$schema\": not a calibration file")
                    }
                }
                "version" -> {
                    val version = (value as JsonPrimitive).content.toInt()
                    if (version != SensorFormats.CALIBRATION_VERSION) {
                        val why = if (version > SensorFormats.CALIBRATION_VERSION) ": newer than this build reads" else ""
                        throw CalibrationFileException("version", "must be ${SensorFormats.CALIBRATION_VERSION}, was $version$why")
                    }
                }
            }
        }

        private fun join(path: String, member: String) = if (path.isEmpty()) member else "$path.$member"

        private fun word(kind: JsonKind): String = when (kind) {
            JsonKind.STRING -> "a string"
            JsonKind.NUMBER -> "a finite number"
            JsonKind.INT, JsonKind.LONG -> "a whole number"
            JsonKind.BOOLEAN -> "true or false"
            JsonKind.ARRAY -> "an array"
            JsonKind.OBJECT -> "an object"
            JsonKind.ANY -> "a value"
        }
    }
}

/** The file's document; members in file order. */
@Serializable
internal class CalibrationDocument(
    val schema: String,
    val version: Int,
    val participant: String? = null,
    val calibratedAt: String,
    val electrodes: List<ElectrodeDocument>,
)

/** One electrode: its number (1..9), its step and the current the step means. */
@Serializable
internal class ElectrodeDocument(val electrode: Int, val step: Int, val milliamps: Double)
