package org.hapticon.companion.sensors

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.shortNumber
import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidButton
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame

/**
 * The JSON objects `hapticon decode` prints, one per decoded frame, and its final statistics object.
 * Keys are snake_case; every object starts with `"type"`. Decoders reuse their frame objects, so each
 * function copies what it needs at once. The objects are kotlinx-serialization trees ([JsonLinesListener] writes
 * them with [org.hapticon.core.io.SchemaJson.encodeElement]); a whole CSV value is written without a fraction
 * (`2`, `-0`), as before.
 */
object FrameJson {
    /** `{"type":"csv","values":[...]}`. */
    fun csv(sample: CsvSample): JsonObject =
        obj("type" to JsonPrimitive("csv"), "values" to JsonArray(List(sample.fieldCount) { shortNumber(sample.values[it]) }))

    /**
     * `{"type":"lucid","fingers":[5 curls]}`, then only what the line carried: `"joystick":[x,y]`, `"trigger"`,
     * `"buttons"` (names of the pressed flags), `"splay"` (5 entries) and `"joints"` (5 × 4 per-joint curls);
     * inside the last three, a value the line did not carry is null.
     */
    fun lucid(frame: LucidGloveFrame): JsonObject {
        val members = linkedMapOf<String, JsonElement>("type" to JsonPrimitive("lucid"), "fingers" to ints(frame.curl))
        if (frame.joystickX != ABSENT || frame.joystickY != ABSENT) {
            members["joystick"] = JsonArray(listOf(optional(frame.joystickX), optional(frame.joystickY)))
        }
        if (frame.trigger != ABSENT) members["trigger"] = JsonPrimitive(frame.trigger)
        val pressed = LucidButton.entries.filter { frame.isPressed(it) }
        if (pressed.isNotEmpty()) members["buttons"] = JsonArray(pressed.map { JsonPrimitive(it.name.lowercase()) })
        if (frame.splay.any { it != ABSENT }) members["splay"] = JsonArray(frame.splay.map(::optional))
        if (frame.jointCurl.any { it != ABSENT }) {
            val perFinger = frame.jointCurl.asList().chunked(LucidGloveFrame.JOINTS_PER_FINGER)
            members["joints"] = JsonArray(perFinger.map { joints -> JsonArray(joints.map(::optional)) })
        }
        return JsonObject(members)
    }

    /** `{"type":"sample","seq":N,"timestamp_us":N,"channels":[...]}` for a framed sample. */
    fun sample(frame: SampleFrame): JsonObject = obj(
        "type" to JsonPrimitive("sample"),
        "seq" to JsonPrimitive(frame.sequence),
        "timestamp_us" to JsonPrimitive(frame.timestampMicros),
        "channels" to JsonArray(List(frame.channelCount) { JsonPrimitive(frame.values[it]) }),
    )

    /** `{"type":"device_info",...}` with the firmware version, ADC bits, rate, outputs, channel units and name. */
    fun deviceInfo(info: DeviceInfo): JsonObject = obj(
        "type" to JsonPrimitive("device_info"),
        "name" to JsonPrimitive(info.name),
        "firmware" to JsonPrimitive(info.firmwareVersion),
        "adc_bits" to JsonPrimitive(info.adcBits),
        "sample_rate_hz" to JsonPrimitive(info.sampleRateHz),
        "outputs" to JsonPrimitive(info.outputCount),
        "channel_units" to JsonArray(info.channelUnits.map { JsonPrimitive(it.name.lowercase()) }),
    )

    /** `{"type":"ack","command_seq":N,"status":"ok","detail":N}`: the device's answer to the command numbered `command_seq`. */
    fun ack(commandSequence: Int, status: AckStatus, detail: Int): JsonObject = obj(
        "type" to JsonPrimitive("ack"),
        "command_seq" to JsonPrimitive(commandSequence),
        "status" to JsonPrimitive(status.name.lowercase()),
        "detail" to JsonPrimitive(detail),
    )

    /**
     * `{"stats":{"frames","bad_frames","dropped_bytes","bytes","ignored_lines","sequence_gaps","lost_frames",
     * "bad_frames_by_error":{...}}}`; the last holds only the [FrameError] kinds that occurred.
     */
    fun stats(stats: StreamStats): JsonObject {
        val byError = LinkedHashMap<String, JsonElement>()
        for (error in FrameError.entries) {
            val count = stats.badFrames(error)
            if (count != 0L) byError[error.name.lowercase()] = JsonPrimitive(count)
        }
        val counts = obj(
            "frames" to JsonPrimitive(stats.frames),
            "bad_frames" to JsonPrimitive(stats.badFrames),
            "dropped_bytes" to JsonPrimitive(stats.droppedBytes),
            "bytes" to JsonPrimitive(stats.bytes),
            "ignored_lines" to JsonPrimitive(stats.ignoredLines),
            "sequence_gaps" to JsonPrimitive(stats.sequenceGaps),
            "lost_frames" to JsonPrimitive(stats.lostFrames),
            "bad_frames_by_error" to JsonObject(byError),
        )
        return obj("stats" to counts)
    }

    private const val ABSENT = LucidGloveFrame.ABSENT

    private fun ints(values: IntArray): JsonArray = JsonArray(values.map { JsonPrimitive(it) })

    private fun optional(value: Int): JsonElement = if (value == ABSENT) JsonNull else JsonPrimitive(value)

    private fun obj(vararg members: Pair<String, JsonElement>): JsonObject = JsonObject(linkedMapOf(*members))
}
