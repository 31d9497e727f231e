package org.hapticon.core.pattern

import org.hapticon.core.midiNoteToHz
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class FrequencyMappingTest {
    private val default = FrequencyMapping.DEFAULT

    @Test
    fun default_endsOfTheRange_areNotes36And72() {
        assertEquals(65.40639132514966, default.hertzOf(0.0), 1e-12)
        assertEquals(523.2511306011972, default.hertzOf(1.0), 1e-9)
    }

    @Test
    fun default_normalisedFrequency_isLinearInTheMidiNote() {
        for (note in 36..72) {
            assertEquals((note - 36) / 36.0, default.normalizedOf(midiNoteToHz(note.toDouble())), 1e-12)
        }
        assertEquals(midiNoteToHz(54.0), default.hertzOf(0.5), 1e-9)
    }

    @Test
    fun sharpness_isTheSquareRootOfNormalisedFrequency_asMetasConverter() {
        assertEquals(0.25, FrequencyMapping.normalizedOfSharpness(0.5), 0.0)
        assertEquals(0.5, FrequencyMapping.sharpnessOfNormalized(0.25), 0.0)
        assertEquals(default.hertzOf(0.25), default.hertzOfSharpness(0.5), 0.0)
        assertEquals(0.5, default.sharpnessOf(default.hertzOf(0.25)), 1e-12)
    }

    @Test
    fun mapping_outsideOrNotANumber_clampsToTheEnds() {
        assertEquals(0.0, default.normalizedOf(10.0), 0.0)
        assertEquals(1.0, default.normalizedOf(10_000.0), 0.0)
        assertEquals(0.0, default.normalizedOf(Double.NaN), 0.0)
        assertEquals(default.minHz, default.hertzOf(Double.NaN), 0.0)
        assertEquals(default.maxHz, default.hertzOf(7.0), 0.0)
        assertEquals(default.minHz, default.hertzOfSharpness(-0.3), 0.0)
        assertTrue(150.0 in default)
        assertFalse(600.0 in default)
    }

    @Test
    fun mapping_badRange_throws() {
        assertThrows(IllegalArgumentException::class.java) { FrequencyMapping(0.0, 100.0) }
        assertThrows(IllegalArgumentException::class.java) { FrequencyMapping(200.0, 100.0) }
        assertThrows(IllegalArgumentException::class.java) { FrequencyMapping(50.0, Double.POSITIVE_INFINITY) }
    }
}
