package org.hapticon.sensor.protocol

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import org.hapticon.sensor.protocol.lucid.LucidButton
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * The LucidGloves / OpenGloves alpha encoding: curls A..E per line, as five channels named by finger, on the
 * glove's 12-bit ADC. Its decoder is a [LucidGloveDecoder]; `hapticon decode` writes each line as a
 * `{"type":"lucid",…}` document.
 */
public data object LucidGlovesProtocol : SensorProtocol {
    /** The five channels, thumb first. */
    public val FINGER_NAMES: List<String> = listOf("thumb", "index", "middle", "ring", "pinky")

    override val label: String get() = "LucidGloves"

    override val cliName: String get() = "lucid"

    override val assumedAdcBits: Int get() = 12

    override fun initialInfo(): StreamInfo = StreamInfo(this, FINGER_NAMES)

    override fun decoder(sink: FrameSink): StreamDecoder = LucidGloveDecoder(LucidFrames(sink))
}

private class LucidFrames(private val sink: FrameSink) : LucidGloveDecoder.Listener {
    private val frame = LiveFrame()
    private val info = LucidGlovesProtocol.initialInfo()

    override fun onFrame(frame: LucidGloveFrame) {
        for (f in 0 until LucidGloveFrame.FINGERS) this.frame.values[f] = frame.curl[f].toDouble()
        this.frame.channelCount = LucidGloveFrame.FINGERS
        sink.onFrame(this.frame, info)
        sink.documents?.write(LucidDocument.serializer(), LucidDocument.of(frame))
    }
}

/**
 * `{"type":"lucid","fingers":[5 curls]}`, then only what the line carried: `"joystick":[x,y]`, `"trigger"`,
 * `"buttons"` (names of the pressed flags), `"splay"` (5 entries) and `"joints"` (5 × 4 per-joint curls);
 * inside the last three, a value the line did not carry is null.
 */
@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class LucidDocument(
    val type: String = "lucid",
    val fingers: List<Int>,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val joystick: List<Int?>? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val trigger: Int? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val buttons: List<String>? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val splay: List<Int?>? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val joints: List<List<Int?>>? = null,
) {
    companion object {
        private const val ABSENT = LucidGloveFrame.ABSENT

        private fun optional(value: Int): Int? = value.takeUnless { it == ABSENT }

        /** Copies what [frame] carried at once (the decoder reuses it). */
        fun of(frame: LucidGloveFrame): LucidDocument = LucidDocument(
            fingers = frame.curl.toList(),
            joystick = if (frame.joystickX != ABSENT || frame.joystickY != ABSENT) listOf(optional(frame.joystickX), optional(frame.joystickY)) else null,
            trigger = optional(frame.trigger),
            buttons = LucidButton.entries.filter { frame.isPressed(it) }.map { it.name.lowercase() }.ifEmpty { null },
            splay = if (frame.splay.any { it != ABSENT }) frame.splay.map(::optional) else null,
            joints = if (frame.jointCurl.any { it != ABSENT }) {
                frame.jointCurl.asList().chunked(LucidGloveFrame.JOINTS_PER_FINGER).map { joints -> joints.map(::optional) }
            } else {
                null
            },
        )
    }
}
