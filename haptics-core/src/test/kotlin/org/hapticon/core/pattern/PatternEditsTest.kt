package org.hapticon.core.pattern

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class PatternEditsTest {
    private val boing = HapticPattern(
        "boing",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 0.8), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 220.0), FrequencyKey(0.4, 110.0)),
        listOf(Transient(0.2, 0.5, 0.3)),
    )

    @Test
    fun edited_gainOctaveAndDoubleTime_scalesEveryKey() {
        val edited = boing.edited("boing soft", gain = 0.5, semitones = -12.0, timeScale = 2.0)
        assertEquals("boing soft", edited.name)
        assertEquals(listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.2, 0.4), AmplitudeKey(0.8, 0.0)), edited.amplitude)
        assertEquals(listOf(FrequencyKey(0.0, 110.0), FrequencyKey(0.8, 55.0)), edited.frequency)
        assertEquals(listOf(Transient(0.4, 0.25, 0.3)), edited.transients)
    }

    @Test
    fun edited_identity_equalsTheOriginal() = assertEquals(boing, boing.edited("boing"))

    @Test
    fun edited_outOfRangeOrNaN_namesTheEdit() {
        assertEquals("gain", assertThrows(PatternException::class.java) { boing.edited("x", gain = 1.5) }.field)
        assertEquals("gain", assertThrows(PatternException::class.java) { boing.edited("x", gain = Double.NaN) }.field)
        assertEquals("semitones", assertThrows(PatternException::class.java) { boing.edited("x", semitones = Double.POSITIVE_INFINITY) }.field)
        assertEquals("timeScale", assertThrows(PatternException::class.java) { boing.edited("x", timeScale = 0.0) }.field)
    }

    @Test
    fun edited_stretchBeyondTheSafetyCap_refusedByThePatternRule() {
        val long = HapticPattern("long", listOf(AmplitudeKey(0.0, 0.5), AmplitudeKey(10.0, 0.5)), listOf(FrequencyKey(0.0, 150.0)))
        assertEquals("duration", assertThrows(PatternException::class.java) { long.edited("x", timeScale = 4.0) }.field)
    }
}
