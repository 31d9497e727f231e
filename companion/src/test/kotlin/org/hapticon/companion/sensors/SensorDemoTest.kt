package org.hapticon.companion.sensors

import org.hapticon.companion.cli
import org.hapticon.sensor.grains.FsrForceConverter
import org.hapticon.sensor.grains.FsrReading
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File

class SensorDemoTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun write_reportsEveryFileAndEachIsWhatTheMatchingCommandPrints() {
        val dir = temp.newFolder("demo")
        val report = ArrayList<String>()
        SensorDemo.write(dir) { report += it }

        fun f(name: String) = File(dir, name)
        assertEquals(
            listOf(
                "wrote ${f("fsr-press.bin")}: framed stream from hapticon-demo-fsr, device info + 2000 FSR samples at 1000 Hz, 28036 bytes",
                "wrote ${f("fsr-press.jsonl")}: 2001 frames decoded, 0 bad, 0 bytes dropped",
                "wrote ${f("fsr-press.csv")}: 2000 rows of time_s,voltage",
                "wrote ${f("grains.csv")}: 46 grain onsets (24 grains = 25 linear bins, 20-sample grains)",
                "wrote ${f("handshake-self.csv")} and ${f("handshake-partner.csv")}: 500 rows each of time_s,thumb_deg,middle_deg",
                // Active while the self hand's own middle finger is past 30.9°: it lets go 0.2 s before the partner,
                // whose grip does not keep it going (only the self hand starts and holds it: either hand would give 19 more steps).
                "wrote ${f("handshake.csv")}: 500 steps, handshake active in 253",
            ),
            report,
        )
        val decoded = cli("decode", "--protocol", "framed", "--in", f("fsr-press.bin").path)
        assertEquals(decoded.stdout, f("fsr-press.jsonl").readText())
        assertEquals(cli("grains", "--in", f("fsr-press.csv").path).stdout, f("grains.csv").readText())
        val handshake = cli("handshake", "--self", f("handshake-self.csv").path, "--partner", f("handshake-partner.csv").path)
        assertEquals(handshake.stdout, f("handshake.csv").readText())
    }

    @Test
    fun pressRecording_decodesToTheSyntheticPressCounts() {
        val csv = SensorDemo.voltageCsv(SensorDemo.pressRecording()).lines()
        assertEquals("time_s,voltage", csv[0])
        assertEquals("0.000000,0.00000", csv[1])
        // At 1.2 s the press holds 10 N: G = 800 µS, so Vout = 5 V · 10 kΩ / (10 kΩ + 1.25 kΩ) = 4.444 V = 3640 counts.
        assertEquals("1.200000,4.44444", csv[1201])
        assertEquals(2002, csv.size) // header, 2000 rows, and the empty string after the last line break
    }

    @Test
    fun syntheticPress_voltsInvertsTheForceConverter() {
        for (newtons in listOf(0.5, 2.0, 7.5, 10.0)) {
            val force = FsrForceConverter().forceOf(SyntheticPress.volts(newtons))
            assertEquals(newtons, (force as FsrReading.Force).newtons, 1e-9)
        }
        assertEquals(0.0, SyntheticPress.volts(0.0), 0.0)
    }
}
