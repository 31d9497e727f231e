package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame

/**
 * The byte protocols a board may speak (docs/protocols.md), with the name the app shows ([label]) and
 * the one the `hapticon` command line takes ([cliName]).
 */
public enum class SensorProtocol(public val label: String, public val cliName: String) {
    /** Lines of numbers, as Arduino sketches print them; the field count is learned from the stream. */
    CSV("CSV", "csv"),

    /** The LucidGloves / OpenGloves alpha encoding: curls A..E per line. */
    LUCID_GLOVES("LucidGloves", "lucid"),

    /** The Hapticon framed binary protocol (COBS + CRC-16), with device info. */
    FRAMED("Framed", "framed"),
    ;

    public companion object {
        /** The protocols by [cliName], in declaration order (`--protocol` values). */
        public val CLI_CHOICES: Map<String, SensorProtocol> = entries.associateByTo(LinkedHashMap()) { it.cliName }
    }
}

/** Baud rates offered in the UI; 1200 is left out on purpose (it reboots native-USB boards). */
public val BAUD_RATES: List<Int> = listOf(9_600, 19_200, 38_400, 57_600, 115_200, 230_400, 460_800, 921_600)

/**
 * Hears the frames of whichever protocol [decoderFor] decodes. Every callback does nothing unless
 * overridden, so a reader of one protocol overrides only that protocol's callbacks. Frames are reused
 * by their decoder and valid only during the call.
 */
public interface ProtocolListener : CsvDecoder.Listener, LucidGloveDecoder.Listener, FramedDecoder.Listener {
    override fun onSample(sample: CsvSample) {}

    override fun onFrame(frame: LucidGloveFrame) {}

    override fun onSample(frame: SampleFrame) {}
}

/**
 * A fresh decoder for [protocol] that hands every frame to [listener]: the one place that maps a
 * protocol to its decoder, used by the app's live session and every `hapticon` command. A CSV stream
 * gets a [CsvDecoder] (its [CsvDecoder.channelNames] reachable by a cast), the others their own decoder.
 */
public fun decoderFor(protocol: SensorProtocol, listener: ProtocolListener): StreamDecoder = when (protocol) {
    SensorProtocol.CSV -> CsvDecoder(listener)
    SensorProtocol.LUCID_GLOVES -> LucidGloveDecoder(listener)
    SensorProtocol.FRAMED -> FramedDecoder(listener)
}
