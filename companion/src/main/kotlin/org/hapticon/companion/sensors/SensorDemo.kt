package org.hapticon.companion.sensors

import org.hapticon.companion.cli.OutputFiles
import org.hapticon.sensor.glove.HandshakeCsv
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.port.ReplayPort
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.protocol.framed.SampleFrame
import java.io.File
import java.io.OutputStreamWriter
import java.util.Locale

/**
 * The sensor part of `hapticon demo`: the path from a board's bytes to grains, and a handshake, each step
 * written as the file the matching command reads or prints, so a reader can rerun any step by hand.
 */
object SensorDemo {
    /** Samples recorded: one [SyntheticPress] press-and-release cycle. */
    val PRESS_SAMPLES: Int = (SyntheticPress.PERIOD_SECONDS * SyntheticPress.SAMPLE_RATE_HZ).toInt()

    /** The board's self-description in the recording. */
    val DEVICE: DeviceInfo = DeviceInfo(1, 0, 0, SyntheticPress.ADC_BITS, SyntheticPress.SAMPLE_RATE_HZ, 0, listOf(ChannelUnit.RAW), "hapticon-demo-fsr")

    /**
     * Writes into [dir] (which must exist), reporting each file through [report]:
     * `fsr-press.bin` (a framed recording of a board reading an FSR: device info, then [PRESS_SAMPLES] samples),
     * `fsr-press.jsonl` (what `hapticon decode --protocol framed` prints for it), `fsr-press.csv` (its samples as
     * `time_s,voltage`), `grains.csv` (what `hapticon grains` prints for that), `handshake-self.csv` and
     * `handshake-partner.csv` (two gloves' angles) and `handshake.csv` (what `hapticon handshake` prints for them).
     */
    fun write(dir: File, report: (String) -> Unit) {
        val recording = File(dir, "fsr-press.bin")
        val bytes = pressRecording()
        OutputFiles.write(recording) { it.write(bytes) }
        report("wrote $recording: framed stream from ${DEVICE.name}, device info + $PRESS_SAMPLES FSR samples at ${DEVICE.sampleRateHz} Hz, ${bytes.size} bytes")

        val decoded = File(dir, "fsr-press.jsonl")
        var stats: StreamStats? = null
        OutputFiles.write(decoded) { stream ->
            val out = OutputStreamWriter(stream, Charsets.UTF_8)
            stats = ReplayPort(recording).use { StreamToJsonLines.decode(it, SensorProtocol.FRAMED, out) }
            out.flush()
        }
        val decodedStats = checkNotNull(stats)
        report("wrote $decoded: ${decodedStats.frames} frames decoded, ${decodedStats.badFrames} bad, ${decodedStats.droppedBytes} bytes dropped")

        val forces = File(dir, "fsr-press.csv")
        val forceCsv = voltageCsv(bytes)
        OutputFiles.write(forces) { it.write(forceCsv.toByteArray(Charsets.UTF_8)) }
        report("wrote $forces: $PRESS_SAMPLES rows of time_s,voltage")

        val grains = File(dir, "grains.csv")
        val settings = GrainSettings()
        val table = GrainTable.compute(forceCsv, settings, source = forces.path)
        OutputFiles.write(grains) { it.write(table.format().toByteArray(Charsets.UTF_8)) }
        report("wrote $grains: ${table.summary.grains.size} grain onsets (${settings.grainCount} grains = ${settings.binCount} ${settings.distribution.name.lowercase()} bins, ${table.summary.grainSamples}-sample grains)")

        val self = File(dir, "handshake-self.csv")
        val partner = File(dir, "handshake-partner.csv")
        val selfCsv = SyntheticHandshake.selfCsv()
        val partnerCsv = SyntheticHandshake.partnerCsv()
        OutputFiles.write(self) { it.write(selfCsv.toByteArray(Charsets.UTF_8)) }
        OutputFiles.write(partner) { it.write(partnerCsv.toByteArray(Charsets.UTF_8)) }
        val rows = (SyntheticHandshake.SECONDS * SyntheticHandshake.RATE_HZ).toInt()
        report("wrote $self and $partner: $rows rows each of ${HandshakeCsv.ANGLE_HEADER}")

        val handshake = File(dir, "handshake.csv")
        val steps = HandshakeCsv.commands(selfCsv, partnerCsv, self.path, partner.path)
        OutputFiles.write(handshake) { it.write(HandshakeCsv.format(steps).toByteArray(Charsets.UTF_8)) }
        report("wrote $handshake: ${steps.size} steps, handshake active in ${steps.count { it.frame.active }}")
    }

    /** The framed bytes a board would send: device info, then one sample frame of [SyntheticPress.countsAt] per sample. */
    fun pressRecording(): ByteArray {
        val encoder = FramedEncoder()
        val frame = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val out = java.io.ByteArrayOutputStream()
        out.write(frame, 0, encoder.deviceInfo(DEVICE, frame))
        val value = IntArray(1)
        for (k in 0 until PRESS_SAMPLES) {
            value[0] = SyntheticPress.countsAt(k)
            out.write(frame, 0, encoder.sample(k * 1_000_000L / DEVICE.sampleRateHz, value, frame))
        }
        return out.toByteArray()
    }

    /** The samples of a framed [recording] as a `time_s,voltage` CSV: device time in seconds, counts in volts. */
    fun voltageCsv(recording: ByteArray): String {
        val csv = StringBuilder("time_s,voltage\n")
        val decoder = FramedDecoder(object : FramedDecoder.Listener {
            override fun onSample(frame: SampleFrame) {
                val volts = SyntheticPress.voltsOfCounts(frame.values[0])
                csv.append(String.format(Locale.ROOT, "%.6f,%.5f\n", frame.timestampMicros / 1e6, volts))
            }
        })
        decoder.feed(recording)
        decoder.finish()
        return csv.toString()
    }
}
