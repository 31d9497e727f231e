package org.hapticon.core.pattern

import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.double
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.hapticon.core.io.SchemaJson
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

/**
 * Files made by Lofelt Studio and kept as test data by Lofelt's and Meta's SDKs (`src/test/resources/real/`, with
 * their sources and licence in its README): what users have, read as those SDKs' own players read them.
 */
class RealPatternFilesTest {
    private fun bytes(name: String): ByteArray = javaClass.getResourceAsStream("/real/$name")!!.use { it.readBytes() }

    private fun read(name: String): PatternImport = MetaHaptic.read(bytes(name), name.substringBefore('.'))

    @Test
    fun lofeltStudioExports_frequencyPastTheEnd_readClippedWithOneNote() {
        val button = read("lofelt-studio-Button1.haptic")
        assertEquals(0.11618934, button.pattern.duration, 0.0)
        assertEquals(0.11618934, button.pattern.frequency.last().time, 0.0)
        assertEquals(listOf("frequency envelope clipped to the amplitude envelope (0.000 s..0.116 s): 1 past its end (up to 0.50 ms) " +
            "breakpoint(s) outside it, as Lofelt Studio exports write"), button.notes)
        assertEquals(2, button.pattern.transients.size)

        val alert = read("lofelt-studio-Alert1.haptic")
        assertEquals(2.0, alert.pattern.duration, 0.0)
        assertEquals(listOf("frequency envelope clipped to the amplitude envelope (0.000 s..2.000 s): 1 past its end (up to 10.00 ms) " +
            "breakpoint(s) outside it, as Lofelt Studio exports write"), alert.notes)
        // Both are short enough for the app to import and play.
        PatternImporter.read(bytes("lofelt-studio-Alert1.haptic"), "Alert1.haptic").pattern.vibrationWaveform()
    }

    @Test
    fun metasLegacyValidationFile_frequencyJustPastTheEnd_readsAsMetasLoadersRead_it() {
        val (pattern, notes) = read("meta-invalid_freq_bp_outside_amp_env.haptic")
        // (1.0, 1.0) then (1.0001, 0.0): the breakpoint at 1.0 already ends the clipped envelope.
        assertEquals(listOf(1.0, 1.0), pattern.frequency.map { FrequencyMapping.DEFAULT.normalizedOf(it.hertz) }.map { Math.round(it * 1e9) / 1e9 })
        assertEquals(listOf(0.0, 1.0), pattern.frequency.map { it.time })
        assertEquals(1, notes.size)
    }

    @Test
    fun dataModelsRequiredOnlyFile_versionWithMajorAlone_reads() {
        val (pattern, notes) = read("lofelt-valid_required_v1.haptic")
        assertEquals(listOf(AmplitudeKey(0.0, 0.2), AmplitudeKey(0.1, 0.3), AmplitudeKey(0.2, 0.2), AmplitudeKey(0.3, 0.5)), pattern.amplitude)
        assertEquals(listOf("no frequency envelope: the carrier stays at 185.0 Hz, the middle of the range"), notes)
    }

    @Test
    fun whatEveryValidationModeRefuses_stillRefused() {
        val amplitude = "signals.continuous.envelopes.amplitude"
        assertEquals("$amplitude: has zero duration (every breakpoint at 0.0 s)",
            assertThrows(PatternException::class.java) { read("meta-invalid_zero_duration.haptic") }.message)
        assertEquals("$amplitude: has a single breakpoint; it needs at least two",
            assertThrows(PatternException::class.java) { read("meta-invalid_single_amplitude_breakpoint.haptic") }.message)
    }

    @Test
    fun seventySecondClip_readsConvertsToAhapInThirtySecondEvents_butDoesNotPlay() {
        val (pattern, _) = read("meta-long_clip.haptic")
        assertEquals(70.0, pattern.duration, 0.0)
        // Meta's converter writes this clip as continuous events at 0, 30 and 60 s lasting 30, 30 and 10 s
        // (its own reference, core/haptic_data/test_files/long_clip.ahap).
        val ahap = Ahap.write(pattern)
        val events = SchemaJson.parseUtf8(ahap.text.toByteArray()).jsonObject["Pattern"]!!.jsonArray
            .mapNotNull { (it.jsonObject["Event"] as JsonObject?) }
            .filter { it["EventType"]!!.jsonPrimitive.content == "HapticContinuous" }
            .map { it["Time"]!!.jsonPrimitive.double to it["EventDuration"]!!.jsonPrimitive.double }
        assertEquals(listOf(0.0 to 30.0, 30.0 to 30.0, 60.0 to 10.0), events)
        // Read back: the same curve, across the event boundaries too.
        val back = Ahap.read(ahap.text.toByteArray(), "long").pattern
        assertEquals(70.0, back.duration, 1e-9)
        for (t in listOf(2.5, 15.0, 29.999, 30.0, 30.001, 45.0, 59.5, 60.0, 65.0, 69.9)) {
            assertEquals("at $t s", pattern.amplitudeAt(t), back.amplitudeAt(t), 0.005)
        }
        // Nothing plays it: the app's import, every vibration path.
        assertEquals("meta-long_clip.haptic: duration: plays for 70.000 s, longer than the 30.0 s safety cap for playing",
            assertThrows(PatternImportException::class.java) { PatternImporter.read(bytes("meta-long_clip.haptic"), "meta-long_clip.haptic") }.message)
        assertThrows(PatternException::class.java) { pattern.vibrationWaveform() }
    }
}
