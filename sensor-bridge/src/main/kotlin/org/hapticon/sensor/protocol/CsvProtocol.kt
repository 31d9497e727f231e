package org.hapticon.sensor.protocol

import kotlinx.serialization.KSerializer
import kotlinx.serialization.Serializable
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.PrimitiveSerialDescriptor
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.encoding.Decoder
import kotlinx.serialization.encoding.Encoder
import kotlinx.serialization.json.JsonElement
import org.hapticon.core.io.shortNumber
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * Lines of numbers, as Arduino sketches print them: the field count is learned from the stream, and a header
 * line names the channels (otherwise `ch0`, `ch1`, …). Its decoder is a [CsvDecoder] (its
 * [CsvDecoder.channelNames] reachable by a cast); `hapticon decode` writes each line as a [ValuesDocument].
 */
public data object CsvProtocol : SensorProtocol {
    override val label: String get() = "CSV"

    override val cliName: String get() = "csv"

    override fun decoder(sink: FrameSink): StreamDecoder = CsvFrames(sink).decoder
}

/** `{"type":…,"values":[…]}`: one frame's values, whole numbers without a fraction (`2`, `-0`). */
@Serializable
public class ValuesDocument(
    /** The protocol's [SensorProtocol.cliName]. */
    public val type: String,
    /** The frame's values in channel order. */
    public val values: List<@Serializable(with = ShortNumber::class) Double>,
) {
    public companion object {
        /** The document of [frame]'s values, for a protocol named [type]. */
        public fun of(type: String, frame: LiveFrame): ValuesDocument = ValuesDocument(type, List(frame.channelCount) { frame.values[it] })
    }
}

private class CsvFrames(private val sink: FrameSink) : CsvDecoder.Listener {
    val decoder = CsvDecoder(this)
    private val frame = LiveFrame()
    private var info = CsvProtocol.initialInfo()

    // The header's names live on the decoder, not on the sample; compared by identity, as it replaces the list.
    private var names: List<String>? = null

    override fun onSample(sample: CsvSample) {
        val n = sample.fieldCount
        val header = decoder.channelNames
        if (n != info.channelCount || header !== names) {
            names = header
            info = StreamInfo(CsvProtocol, header.takeIf { it.size == n } ?: channelNumbers(n))
        }
        sample.values.copyInto(frame.values, 0, 0, n)
        frame.channelCount = n
        sink.onFrame(frame, info)
        sink.documents?.write(ValuesDocument.serializer(), ValuesDocument.of(CsvProtocol.cliName, frame))
    }
}

/**
 * A value spelled as [shortNumber] spells it, as frame lines always were: a whole number without a fraction (`2`),
 * negative zero as `-0` (which `ShortDouble` writes `-0.0`), anything else as [Double.toString]. Reads any number.
 */
internal object ShortNumber : KSerializer<Double> {
    override val descriptor: SerialDescriptor = PrimitiveSerialDescriptor("org.hapticon.sensor.ShortNumber", PrimitiveKind.DOUBLE)

    override fun serialize(encoder: Encoder, value: Double): Unit = encoder.encodeSerializableValue(JsonElement.serializer(), shortNumber(value))

    override fun deserialize(decoder: Decoder): Double = decoder.decodeDouble()
}

/** `ch0`, `ch1`, …: the names of [count] channels the stream did not name. */
internal fun channelNumbers(count: Int): List<String> = List(count) { "ch$it" }
