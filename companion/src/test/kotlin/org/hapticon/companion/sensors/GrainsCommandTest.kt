package org.hapticon.companion.sensors

import org.hapticon.companion.cli
import org.hapticon.sensor.grains.GrainCsv
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.Locale

class GrainsCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun file(name: String, text: String): File = temp.newFile(name).also { it.writeText(text) }

    /** 100 rows at 1 kHz: 0 N, then 10 N for 40 samples (k = 1..40), then 0 N. */
    private fun stepCsv(): File = file("step.csv", buildString {
        append("time_s,force\n")
        for (k in 0 until 100) append(String.format(Locale.ROOT, "%.3f,%s\n", k / 1000.0, if (k in 1..40) "10" else "0"))
    })

    @Test
    fun grains_forceStepWithOneGrainTwoBins_firesUpAndDownWithBinAndFilteredForce() {
        val result = cli("grains", "--in", stepCsv().path, "--grains", "1")
        assertEquals(result.toString(), 0, result.exitCode)
        // The 20 Hz low-pass at 1 kHz has a = 1 − e^(−2π·20/1000) = 0.11809: after k samples of 10 N it reads
        // 10·(1 − 0.88191^k), which first reaches bin 1 (≥ 5 N) at k = 6 (5.2951 N). It then decays from 0 N
        // input at k = 41 and falls below 5 N at k = 46 (4.6740 N), after the 20-sample grain has ended.
        assertEquals("onset_s,bin,force_n\n0.006000,1,5.2951\n0.046000,0,4.6740\n", result.stdout)
        assertEquals(
            listOf("grains: 2 onsets from 100 samples at 1000.0 Hz (mean rate of time_s), 20-sample grains, 1 grains = 2 linear bins over 0-10 N"),
            result.stderrLines,
        )
    }

    @Test
    fun grains_convexBins_crowdGrainsAtLightForce() {
        // Convex edges for 4 bins over 0–10 N: 0, 0.625, 2.5, 5.625, 10. The rising filter output is in bin 1
        // at k = 1 (1.1809 N); the grain holds until k = 21 (9.2856 N, bin 3, skipping bin 2). Falling from k = 41,
        // it is in bin 2 by k = 45 (5.2999 N) and, after that grain, in bin 0 at k = 65 (0.4293 N).
        val result = cli("grains", "--in", stepCsv().path, "--grains", "3", "--distribution", "convex")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("onset_s,bin,force_n\n0.001000,1,1.1809\n0.021000,3,9.2856\n0.045000,2,5.2999\n0.065000,0,0.4293\n", result.stdout)
    }

    @Test
    fun grains_voltageRecording_matchesGrainCsvOnsetsAndBinsRiseDuringThePress() {
        val csv = SensorDemo.voltageCsv(SensorDemo.pressRecording())
        val result = cli("grains", "--in", file("press.csv", csv).path)
        assertEquals(result.toString(), 0, result.exitCode)
        val rows = result.stdout.lines().drop(1).dropLast(1).map { it.split(',') }
        val expectedTimes = GrainCsv.format(GrainCsv.onsets(csv)).lines().drop(1).dropLast(1)
        assertEquals(expectedTimes, rows.map { it[0] })
        // One press to 10 N with 24 grains = 25 linear bins: 0.8 s up, bin by bin to the top one (24 grains);
        // the 0.6 s release is faster, so the 20-sample grains now and then skip a bin on the way down.
        val bins = rows.map { it[1].toInt() }
        assertEquals((1..24).toList() + (23 downTo 15) + (13 downTo 10) + (8 downTo 0), bins)
    }

    /** A 20 s linear press from 0 to 10 N at 1 kHz, then 1 s held: slow enough that no grain swallows a bin. */
    private fun slowPressCsv(): File = file("slow-press.csv", buildString {
        append("time_s,force\n")
        for (k in 0 until 21_000) append(String.format(Locale.ROOT, "%.3f,%.6f\n", k / 1000.0, minOf(10.0, k / 2000.0)))
    })

    @Test
    fun grains_slowFullPress_firesExactlyTheRequestedNumber() {
        val csv = slowPressCsv()
        for (grains in listOf(9, 19, 39)) {
            val result = cli("grains", "--in", csv.path, "--grains", "$grains")
            assertEquals(result.toString(), 0, result.exitCode)
            val bins = result.stdout.lines().drop(1).filter { it.isNotEmpty() }.map { it.split(',')[1].toInt() }
            // Shaping Compliance: grains = bins − 1, so the press walks bins 1..N of N + 1.
            assertEquals((1..grains).toList(), bins)
        }
    }

    @Test
    fun grains_zeroGrains_firesNothing() {
        val result = cli("grains", "--in", slowPressCsv().path, "--grains", "0")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("onset_s,bin,force_n\n", result.stdout)
    }

    @Test
    fun grains_badValue_exitsTwoNamingFileAndLine() {
        val bad = file("bad.csv", "time_s,force\n0,1\n# a comment\n0.001,abc\n")
        val result = cli("grains", "--in", bad.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: $bad:4: force is not a number: \"abc\""), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun grains_wrongHeader_exitsTwoNamingLineOne() {
        val bad = file("header.csv", "time,force\n0,1\n")
        val result = cli("grains", "--in", bad.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: $bad:1: expected a header time_s,force or time_s,voltage, got \"time,force\""), result.stderrLines)
    }

    @Test
    fun grains_recordingTooSlowForTheFilter_exitsTwo() {
        val slow = file("slow.csv", "time_s,force\n0,1\n0.1,2\n0.2,3\n")
        val result = cli("grains", "--in", slow.path)
        assertEquals(2, result.exitCode)
        assertEquals(
            listOf("hapticon: $slow: cannot decide grains at this sample rate: cutoffHz must be in (0, 5.0) for 10.0 Hz, was 20.0"),
            result.stderrLines,
        )
    }

    @Test
    fun grains_countOutOfRange_exitsTwo() {
        val result = cli("grains", "--in", stepCsv().path, "--grains", "100")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --grains must be in 0..99, got 100"), result.stderrLines)
    }

    @Test
    fun grains_unknownDistribution_exitsTwo() {
        val result = cli("grains", "--in", stepCsv().path, "--distribution", "cubic")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --distribution must be linear or convex or concave, got 'cubic'"), result.stderrLines)
    }

    @Test
    fun grains_missingFileOrOption_exitsTwo() {
        val missing = File(temp.root, "none.csv")
        assertEquals(listOf("hapticon: --in: no such file: $missing"), cli("grains", "--in", missing.path).stderrLines)
        val noOption = cli("grains")
        assertEquals(2, noOption.exitCode)
        assertEquals(listOf("hapticon: grains needs --in"), noOption.stderrLines)
    }
}
