package org.hapticon.companion.sensors

import org.hapticon.sensor.protocol.StreamDecoder
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder

/** The byte protocols `hapticon decode` reads, by their command-line names. */
enum class DecodeProtocol(val cliName: String) {
    /** Lines of numbers, as Arduino sketches print them; the field count is learned from the stream. */
    CSV("csv"),

    /** The LucidGloves / OpenGloves alpha encoding. */
    LUCID("lucid"),

    /** The Hapticon framed binary protocol (COBS, CRC-16), device-to-host frames. */
    FRAMED("framed"),
    ;

    /** A fresh decoder for this protocol that hands every frame to [listener]. */
    fun decoder(listener: JsonLinesListener): StreamDecoder = when (this) {
        CSV -> CsvDecoder(listener)
        LUCID -> LucidGloveDecoder(listener)
        FRAMED -> FramedDecoder(listener)
    }

    companion object {
        /** `--protocol` values. */
        val CHOICES: Map<String, DecodeProtocol> = entries.associateByTo(LinkedHashMap()) { it.cliName }
    }
}
