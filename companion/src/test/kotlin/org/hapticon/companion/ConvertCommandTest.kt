package org.hapticon.companion

import org.hapticon.companion.cli.PatternSource
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.WavReader
import org.hapticon.core.pattern.Ahap
import org.hapticon.core.pattern.MetaHaptic
import org.hapticon.core.pattern.signal
import org.hapticon.core.pattern.toPattern
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File

class ConvertCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun file(name: String) = File(temp.root, name)

    @Test
    fun convert_presetToAhapToHapticToJson_keepsTheShape() {
        val ahap = file("knock.ahap")
        val haptic = file("knock.haptic")
        val json = file("knock.json")
        assertEquals(0, cli("convert", "knock", ahap.path).exitCode)
        assertEquals(0, cli("convert", ahap.path, haptic.path).exitCode)
        val result = cli("convert", haptic.path, json.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertTrue(result.stdout, result.stdout.startsWith("wrote $json: knock as json, 0.560 s"))
        val back = PatternSource.load(json.path).pattern
        val knock = HapticIcon.KNOCK.toPattern()
        for (t in listOf(0.0025, 0.01, 0.0175, 0.2775, 0.55)) assertEquals("at $t", knock.amplitudeAt(t), back.amplitudeAt(t), 0.01)
        assertEquals(knock.frequencyAt(0.0), back.frequencyAt(0.0), 0.01)
    }

    @Test
    fun render_ahapFile_writesTheSampledPattern() {
        val ahap = file("hug.ahap").also { it.writeText(Ahap.write(HapticIcon.HUG.toPattern()).text) }
        val wav = file("hug.wav")
        val result = cli("render", ahap.path, "--out", wav.path, "--rate", "8000")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("wrote $wav: hug, 24000 samples, 3.000 s at 8000 Hz, f32\n", result.stdout)
        val samples = wav.inputStream().use { WavReader.read(it) }.samples()
        val expected = PatternSource.load(ahap.path).pattern.signal()
        for (i in listOf(1, 4000, 12_345, 23_999)) assertEquals(expected.sample(i / 8000.0).toFloat(), samples[i], 1e-6f)
    }

    @Test
    fun convert_readerAssumption_printsANoteOnStderr() {
        val haptic = file("clip.haptic").also {
            it.writeText(
                """{"version": {"major": 1, "minor": 0, "patch": 0}, "signals": {"continuous": {"envelopes":
                   {"amplitude": [{"time": 0, "amplitude": 0.8}, {"time": 0.5, "amplitude": 0.8, "emphasis": {"amplitude": 0.9, "frequency": 0.5}}]}}}}""",
            )
        }
        val result = cli("convert", haptic.path, file("clip.ahap").path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(listOf("hapticon: note: no frequency envelope: the carrier stays at 185.0 Hz, the middle of the range"), result.stderrLines)
    }

    @Test
    fun convert_badInput_oneLineNamingFileAndMember() {
        val bad = file("bad.haptic").also {
            it.writeText("""{"version": {"major": 1, "minor": 0, "patch": 0}, "signals": {"continuous": {"envelopes": {"amplitude": []}}}}""")
        }
        val out = file("out.ahap")
        val result = cli("convert", bad.path, out.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: $bad: signals.continuous.envelopes.amplitude: is empty; it needs at least two breakpoints"), result.stderrLines)
        assertFalse(out.exists())
        assertEquals(listOf("hapticon: cannot tell the format of x.mp3: expected .json, .ahap, .haptic or .wav"), cli("convert", "knock", "x.mp3").stderrLines)
        assertEquals(listOf("hapticon: --range must be MIN_HZ:MAX_HZ with 0 < MIN < MAX, was '300:100'"),
            cli("convert", "knock", out.path, "--range", "300:100").stderrLines)
        assertEquals(2, cli("convert", "knock").exitCode)
    }

    @Test
    fun convert_seventySecondClip_fileToFileIsNotHeldToThePlaybackCap() {
        // Meta's own 70 s test clip (facebook/meta-haptics-sdk core/haptic_data/test_files/long_clip.haptic), compacted.
        val clip = file("long_clip.haptic").also {
            it.writeText("""{"version": {"major": 1, "minor": 0, "patch": 0}, "signals": {"continuous": {"envelopes": {
                "amplitude": [{"time": 0.0, "amplitude": 0.0}, {"time": 5.0, "amplitude": 0.5, "emphasis": {"amplitude": 0.75, "frequency": 1.0}},
                  {"time": 10.0, "amplitude": 1.0}, {"time": 20.0, "amplitude": 0.0}, {"time": 40.0, "amplitude": 1.0},
                  {"time": 50.0, "amplitude": 0.0}, {"time": 70.0, "amplitude": 1.0}],
                "frequency": [{"time": 0.0, "frequency": 0.0}, {"time": 10.0, "frequency": 1.0}, {"time": 20.0, "frequency": 0.0},
                  {"time": 40.0, "frequency": 1.0}, {"time": 50.0, "frequency": 0.0}, {"time": 70.0, "frequency": 1.0}]}}}}""")
        }
        val ahap = file("long_clip.ahap")
        val result = cli("convert", clip.path, ahap.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertTrue(result.stdout, result.stdout.startsWith("wrote $ahap: long_clip as ahap, 70.000 s"))
        assertEquals(70.0, PatternSource.load(ahap.path).pattern.duration, 1e-9)
        val wav = file("long_clip.wav")
        val rendered = cli("convert", clip.path, wav.path, "--rate", "8000")
        assertEquals(rendered.toString(), 0, rendered.exitCode)
        assertEquals(560_000, wav.inputStream().use { WavReader.read(it) }.samples().size)
    }

    @Test
    fun convert_rangeOption_mapsSharpnessIntoThePhonesRange() {
        val out = file("hit.haptic")
        assertEquals(0, cli("convert", "hit", out.path, "--range", "100:300").exitCode)
        val back = MetaHaptic.read(out.readBytes(), "hit", org.hapticon.core.pattern.FrequencyMapping(100.0, 300.0)).pattern
        assertEquals(HapticIcon.HIT.frequency, back.frequencyAt(0.0), 0.01)
    }
}
