package org.hapticon.companion.gesture

import kotlinx.serialization.json.JsonObject
import org.hapticon.core.io.SchemaJson
import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.EXIT_USAGE
import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.Json
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.io.RecordingWav
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File

class FitCommandTest {
    @get:Rule val temp = TemporaryFolder()

    @Test fun fitsAKnockWavAndWritesItsIconJson() {
        val wav = knockWav()
        val out = File(temp.root, "knock.json")
        // The default reference is the input's full scale: the knock's level 0.5 survives the fit.
        val result = cli("fit", "--in", wav.path, "--out", out.path)
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val icon = IconJson.decode(out.readText())
        assertEquals("knock", icon.name)
        assertEquals(57.0, icon.note, 0.0)
        assertEquals(3, icon.count)
        assertEquals(0.27, icon.period, 0.0005)
        assertEquals(0.5, icon.level, 0.01)
        assertTrue(result.stdout, result.stdout.startsWith("icon knock: attack "))
        assertTrue(result.stdout, result.stdout.contains("\nchannel vibration at 44100.0 Hz: vibration, dominant "))
        assertTrue(result.stdout, result.stdout.contains("\n  count        3.0000  onsets"))
        assertTrue(result.stdout, result.stdout.contains("\nlevel reference: the input's full scale 1.000\n"))
        assertEquals("", result.stderr)
    }

    @Test fun jsonOutputHoldsTheIconAndTheReport() {
        val result = cli("fit", "--in", knockWav().path, "--out", File(temp.root, "k.json").path, "--json", "--envelope", "rms", "--name", "tap")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val json = Json.decode(result.stdout) as JsonObject
        assertEquals("tap", IconJson.fromJsonElement(json["icon"]!!).name)
        val report = json["report"] as JsonObject
        assertEquals("\"rms\"", SchemaJson.encodeElement(report["envelope"]!!))
        assertEquals("\"vibration\"", SchemaJson.encodeElement(report["kind"]!!))
    }

    @Test fun fitsAForceCsvAndReportsNoGestureForSilence() {
        val csv = File(temp.root, "press.csv")
        csv.writeText("time_s,force_N\n" + (0 until 2000).joinToString("") { i -> "${i / 1000.0},${if (i in 500 until 1200) 6.0 else 0.2}\n" })
        val out = File(temp.root, "press.json")
        // Newtons have no full scale in a CSV: the sensor's calibrated maximum (here 12 N) is given.
        val ok = cli("fit", "--in", csv.path, "--out", out.path, "--channel", "force", "--reference", "12")
        assertEquals(ok.toString(), EXIT_OK, ok.exitCode)
        assertEquals(0.5, IconJson.decode(out.readText()).level, 0.02)
        assertTrue(ok.stdout, ok.stdout.contains("\nlevel reference: the given reference 12.00 N\n"))
        val noReference = cli("fit", "--in", csv.path, "--out", out.path, "--channel", "force")
        assertEquals(EXIT_USAGE, noReference.exitCode)
        assertEquals(
            listOf("hapticon: ${csv.path}: channel force is in N with no known full scale: give a reference (--reference VALUE, e.g. the sensor's calibrated maximum, or --reference strongest)"),
            noReference.stderrLines,
        )
        assertTrue(ok.stdout, ok.stdout.contains(": force, dominant "))
        assertEquals(1, IconJson.decode(out.readText()).count)

        val zeros = File(temp.root, "zeros.csv")
        zeros.writeText("time_s,force_N\n" + (0 until 100).joinToString("") { "${it / 100.0},0\n" })
        val none = cli("fit", "--in", zeros.path, "--out", File(temp.root, "z.json").path, "--reference", "10")
        assertEquals(EXIT_USAGE, none.exitCode)
        assertEquals(listOf("hapticon: ${zeros.path}: no gesture found: channel force is all zeros"), none.stderrLines)
        assertTrue(!File(temp.root, "z.json").exists())
    }

    @Test fun usageErrorsAreOneLineWithExit2() {
        val wav = knockWav().path
        val out = File(temp.root, "x.json").path
        assertUsage("hapticon: fit needs --in", "fit", "--out", out)
        assertUsage("hapticon: fit needs --out", "fit", "--in", wav)
        assertUsage("hapticon: --envelope must be lowpass or rms, got 'median'", "fit", "--in", wav, "--out", out, "--envelope", "median")
        assertUsage("hapticon: --in: no such file: ${temp.root}/missing.wav", "fit", "--in", "${temp.root}/missing.wav", "--out", out)
        assertUsage("hapticon: --in: ${temp.root}/a.txt must be a .wav or .csv recording", "fit", "--in", File(temp.root, "a.txt").also { it.writeText("x") }.path, "--out", out)
        assertUsage("hapticon: $wav: no channel 'force'; the recording has vibration", "fit", "--in", wav, "--out", out, "--channel", "force")
        val nan = File(temp.root, "nan.csv").also { it.writeText("time_s,v\n0,1\n0.01,NaN\n0.02,1\n") }
        assertUsage("hapticon: ${nan.path}:3: v is NaN; gaps are rejected (fill them, or read with GapPolicy.INTERPOLATE)", "fit", "--in", nan.path, "--out", out)
        assertUsage("hapticon: --reference must be full-scale, peak, strongest or a number > 0, got '-1'", "fit", "--in", wav, "--out", out, "--reference", "-1")
        assertUsage("hapticon: --in: ${temp.root} is a directory; a batch needs --reference strongest", "fit", "--in", temp.root.path, "--out", out)
        assertUsage("hapticon: --trials must be in 1..10000, got 0", "fit-bench", "--trials", "0")
        assertUsage("hapticon: --seed must be a whole number, got 'x'", "fit-bench", "--seed", "x")
    }

    @Test fun strongestReferenceFitsADirectoryRelativeToItsStrongestGesture() {
        val dir = temp.newFolder("takes")
        knockWav().copyTo(File(dir, "a-strong.wav"))
        wavOf(HapticIcon.KNOCK.copy(level = 0.25), File(dir, "b-weak.wav"))
        val out = File(temp.root, "icons")
        val result = cli("fit", "--in", dir.path, "--out", out.path, "--reference", "strongest")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val strong = IconJson.decode(File(out, "a-strong.json").readText())
        val weak = IconJson.decode(File(out, "b-weak.json").readText())
        assertEquals("a-strong", strong.name)
        assertEquals(1.0, strong.level, 0.03)
        assertEquals(0.5, weak.level, 0.03)
        assertTrue(result.stdout, result.stdout.contains("level reference: the strongest gesture of the batch of 2 "))
    }

    @Test fun fitBenchPrintsTheRecoveryTable() {
        val result = cli("fit-bench", "--trials", "1", "--seed", "3")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val lines = result.stdout.lines()
        assertEquals("fit-bench: 1 random icons per row, seed 3, 44.1 kHz, white Gaussian noise; mean |error|", lines[0])
        assertTrue(lines[1], lines[1].startsWith("envelope  SNR env.err   attack"))
        assertEquals(listOf("lowpass", "lowpass", "lowpass", "lowpass", "rms", "rms", "rms", "rms"), lines.drop(3).filter { it.isNotBlank() }.map { it.substringBefore(' ') })
    }

    private fun assertUsage(expected: String, vararg args: String) {
        val result = cli(*args)
        assertEquals(result.toString(), EXIT_USAGE, result.exitCode)
        assertEquals(listOf(expected), result.stderrLines)
    }

    private fun knockWav(): File {
        val file = File(temp.root, "knock.wav")
        if (!file.exists()) wavOf(HapticIcon.KNOCK, file)
        return file
    }

    private fun wavOf(knock: HapticIcon, file: File) {
        run {
            // Silence either side, as a recording would have; PCM16 like a sensor capture. The paper trapezoid: the
            // fitter recovers a held level.
            val pad = 11_025
            val icon = IconRenderer(knock, 44_100, EnvelopeModel.PAPER)
            val samples = DoubleArray(icon.sampleCount.toInt() + 2 * pad) { i ->
                val j = i - pad
                if (j in 0 until icon.sampleCount) icon.sampleAt(j.toLong()) else 0.0
            }
            val recording = Recording(44_100.0, listOf(Channel("vibration", "", samples)))
            file.outputStream().use { RecordingWav.write(recording, it) }
        }
    }
}
