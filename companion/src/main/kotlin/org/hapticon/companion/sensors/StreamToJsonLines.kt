package org.hapticon.companion.sensors

import org.hapticon.sensor.port.SensorReader
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.StreamStatsDocument
import java.io.Writer

/** The work of `hapticon decode`: a byte source in, JSON lines out. */
object StreamToJsonLines {
    /** Bytes asked for per read: large, since a recording is read as fast as possible rather than awaited. */
    const val READ_BYTES: Int = 1 shl 16

    /**
     * Reads [port] to its end through a [SensorReader] and the [protocol]'s decoder, as the app reads a device,
     * writing one JSON line per decoded frame (the protocol's documents) to [out] and then the
     * [StreamStatsDocument] line. Garbage in the
     * stream is counted, not thrown. Returns the decoder's statistics. The port is not closed.
     * @throws java.io.IOException when reading the port (or writing [out]) fails.
     */
    fun decode(port: SerialPort, protocol: SensorProtocol, out: Writer): StreamStats {
        val listener = JsonLinesListener(out)
        val decoder = protocol.decoder(listener)
        var failure: Throwable? = null
        val reason = SensorReader(port, decoder, { _, cause -> failure = cause }, bufferSize = READ_BYTES).run()
        // A recording only ends; anything else is the failure the reader caught (an I/O error, or a bug).
        if (reason != SensorReader.StopReason.END_OF_STREAM) throw failure ?: IllegalStateException("decoding stopped: $reason")
        listener.write(StreamStatsDocument.serializer(), StreamStatsDocument.of(decoder.stats))
        return decoder.stats
    }
}
