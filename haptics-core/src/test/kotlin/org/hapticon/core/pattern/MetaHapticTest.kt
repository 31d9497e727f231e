package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import kotlin.math.sqrt

class MetaHapticTest {
    private fun haptic(amplitude: String, frequency: String? = null) = """
        {"version": {"major": 1, "minor": 0, "patch": 0}, "metadata": {"editor": "Meta Haptics Studio"},
         "signals": {"continuous": {"envelopes": {"amplitude": [$amplitude]${frequency?.let { ", \"frequency\": [$it]" } ?: ""}}}}}
    """.toByteArray()

    private fun error(bytes: ByteArray) = assertThrows(PatternException::class.java) { MetaHaptic.read(bytes, "x") }.message

    @Test
    fun read_breakpointsAndEmphasis_becomeCurvesAndTransients() {
        val (pattern, notes) = MetaHaptic.read(haptic(
            """{"time": 0.0, "amplitude": 0.2}, {"time": 0.1, "amplitude": 0.5, "emphasis": {"amplitude": 0.81, "frequency": 0.7}}, {"time": 0.4, "amplitude": 0.0}""",
            """{"time": 0.0, "frequency": 0.0}, {"time": 0.4, "frequency": 1.0}""",
        ), "clip")
        assertEquals(listOf(AmplitudeKey(0.0, 0.2), AmplitudeKey(0.1, 0.5), AmplitudeKey(0.4, 0.0)), pattern.amplitude)
        assertEquals(listOf(Transient(0.1, 0.9, 0.7)), pattern.transients) // intensity √0.81
        assertEquals(FrequencyMapping.DEFAULT.minHz, pattern.frequency.first().hertz, 1e-9)
        assertEquals(FrequencyMapping.DEFAULT.maxHz, pattern.frequency.last().hertz, 1e-9)
        assertEquals(emptyList<String>(), notes)
    }

    @Test
    fun read_whatMetasValidatorRejects_namesTheField() {
        val amplitude = "signals.continuous.envelopes.amplitude"
        assertEquals("$amplitude: is empty; it needs at least two breakpoints", error(haptic("")))
        assertEquals("$amplitude: has a single breakpoint; it needs at least two", error(haptic("""{"time": 0, "amplitude": 0.5}""")))
        assertEquals("$amplitude: has zero duration (every breakpoint at 0.2 s)",
            error(haptic("""{"time": 0.2, "amplitude": 0.5}, {"time": 0.2, "amplitude": 0.1}""")))
        assertEquals("signals.continuous.envelopes.frequency[1].time: must not be before the previous breakpoint",
            error(haptic("""{"time": 0, "amplitude": 0.5}, {"time": 0.3, "amplitude": 0}""", """{"time": 0.2, "frequency": 0.5}, {"time": 0.1, "frequency": 0.5}""")))
        assertEquals("signals.continuous.envelopes.frequency[0].frequency: must be in [0, 1], was 1.1",
            error(haptic("""{"time": 0, "amplitude": 0.5}, {"time": 0.3, "amplitude": 0}""", """{"time": 0.2, "frequency": 1.1}""")))
        assertEquals("$amplitude[1].emphasis.amplitude: must not be below the breakpoint's amplitude 0.5, was 0.4",
            error(haptic("""{"time": 0, "amplitude": 0.1}, {"time": 0.3, "amplitude": 0.5, "emphasis": {"amplitude": 0.4, "frequency": 0.5}}""")))
        assertEquals("$amplitude[1].time: must not be before the previous breakpoint (0.3 s), was 0.1",
            error(haptic("""{"time": 0.3, "amplitude": 0.1}, {"time": 0.1, "amplitude": 0.5}""")))
        assertEquals("$amplitude[0].amplitude: must be in [0, 1], was 1.5", error(haptic("""{"time": 0, "amplitude": 1.5}, {"time": 1, "amplitude": 0}""")))
        assertEquals("version.major: unsupported data model version 2.0 (this build reads 1)",
            error("""{"version": {"major": 2, "minor": 0, "patch": 0}, "signals": {}}""".toByteArray()))
        assertEquals("version: missing", error("""{"signals": {}}""".toByteArray()))
    }

    @Test
    fun read_noFrequencyEnvelope_carrierAtTheMiddleWithANote() {
        val (pattern, notes) = MetaHaptic.read(haptic("""{"time": 0, "amplitude": 0.5}, {"time": 1, "amplitude": 0}"""), "x")
        assertEquals(FrequencyMapping.DEFAULT.hertzOf(0.5), pattern.frequencyAt(0.5), 1e-9)
        assertEquals(1, notes.size)
    }

    @Test
    fun read_frequencyPastBothEnds_clippedToTheAmplitudeEnvelopeWithOneNote() {
        val mapping = FrequencyMapping.DEFAULT
        val (pattern, notes) = MetaHaptic.read(haptic(
            """{"time": 0.1, "amplitude": 0.5}, {"time": 0.3, "amplitude": 0}""",
            """{"time": 0.0, "frequency": 0.0}, {"time": 0.2, "frequency": 1.0}, {"time": 0.4, "frequency": 0.0}""",
        ), "x", mapping)
        // Edges interpolated in the file's normalised frequency: 0.5 at 0.1 s and at 0.3 s.
        assertEquals(listOf(0.1, 0.2, 0.3), pattern.frequency.map { it.time })
        val expected = listOf(mapping.hertzOf(0.5), mapping.maxHz, mapping.hertzOf(0.5))
        expected.zip(pattern.frequency) { hz, key -> assertEquals(hz, key.hertz, 1e-9) }
        assertEquals(listOf("frequency envelope clipped to the amplitude envelope (0.100 s..0.300 s): 1 before its start (up to 100.00 ms) " +
            "and 1 past its end (up to 100.00 ms) breakpoint(s) outside it, as Lofelt Studio exports write"), notes)
    }

    @Test
    fun read_frequencyWhollyPastTheEnd_heldFromItsFirstBreakpoint() {
        val (pattern, notes) = MetaHaptic.read(haptic(
            """{"time": 0, "amplitude": 0.5}, {"time": 0.3, "amplitude": 0}""",
            """{"time": 0.5, "frequency": 0.25}, {"time": 0.6, "frequency": 1.0}""",
        ), "x")
        assertEquals(listOf(FrequencyKey(0.3, FrequencyMapping.DEFAULT.hertzOf(0.25))), pattern.frequency)
        assertEquals(1, notes.size)
    }

    @Test
    fun read_versionWithMajorOnly_minorAndPatchDefaultToZero() {
        val (pattern, _) = MetaHaptic.read("""{"version": {"major": 1}, "signals": {"continuous": {"envelopes": {"amplitude": [
            {"time": 0, "amplitude": 0.5}, {"time": 0.3, "amplitude": 0}]}}}}""".toByteArray(), "x")
        assertEquals(0.3, pattern.duration, 0.0)
        assertEquals("version.minor: expected a number, got \"0\"",
            error("""{"version": {"major": 1, "minor": "0"}, "signals": {}}""".toByteArray()))
    }

    @Test
    fun roundTrip_presetsAndAChirpWithTaps_keepTimingAndAmplitude() {
        val chirp = HapticPattern(
            "chirp",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.2, 0.9), AmplitudeKey(1.0, 0.0)),
            listOf(FrequencyKey(0.0, 80.0), FrequencyKey(1.0, 400.0)),
            listOf(Transient(0.2, 1.0, 0.9), Transient(0.55, 0.8, 0.1)),
        )
        for (pattern in HapticIcon.PRESETS.map { it.toPattern() } + chirp) {
            val export = MetaHaptic.write(pattern)
            assertEquals(pattern.name, emptyList<String>(), export.notes)
            AhapTest.assertSameShape(pattern, MetaHaptic.read(export.text.toByteArray(), pattern.name).pattern)
            // And across formats: .haptic → pattern → AHAP → pattern.
            val viaAhap = Ahap.read(Ahap.write(pattern).text.toByteArray(), pattern.name).pattern
            AhapTest.assertSameShape(pattern, viaAhap)
        }
    }

    @Test
    fun write_weakTransientOnALoudBreakpoint_isRaisedAndSaysSo() {
        val pattern = HapticPattern("x", listOf(AmplitudeKey(0.0, 0.8), AmplitudeKey(1.0, 0.8)), listOf(FrequencyKey(0.0, 150.0)), listOf(Transient(0.5, 0.5, 0.5)))
        val export = MetaHaptic.write(pattern)
        assertEquals(listOf("transient at 0.500 s raised to the breakpoint's amplitude 0.800: an emphasis cannot be weaker"), export.notes)
        val back = MetaHaptic.read(export.text.toByteArray(), "x").pattern
        assertEquals(sqrt(0.8), back.transients.single().intensity, 1e-9)
    }
}
