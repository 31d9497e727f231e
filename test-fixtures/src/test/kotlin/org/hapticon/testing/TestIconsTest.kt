package org.hapticon.testing

import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class TestIconsTest {
    @Test
    fun longest_isExactlyAtBothSafetyCaps() {
        assertEquals(HapticIcon.MAX_DURATION_SECONDS, TestIcons.LONGEST.duration, 0.0)
        assertEquals(HapticIcon.MAX_COUNT, TestIcons.LONGEST.count)
        assertEquals(1_323_000L, IconRenderer(TestIcons.LONGEST, 44_100).sampleCount)
    }

    @Test
    fun longest_oneMoreSampleOfSustain_isRejectedForDuration() {
        val longest = TestIcons.LONGEST
        try {
            longest.copy(sustain = longest.sustain + 1e-6)
            fail("expected the duration cap to reject a longer icon")
        } catch (e: IconValidationException) {
            assertEquals("duration", e.field)
        }
    }

    @Test
    fun note127_rendersAt44100ButNotAt22050() {
        assertEquals(5_292L, IconRenderer(TestIcons.NOTE_127, 44_100).sampleCount) // 0.12 s
        try {
            IconRenderer(TestIcons.NOTE_127, 22_050)
            fail("note 127 is above the Nyquist frequency of 22.05 kHz")
        } catch (e: IconValidationException) {
            assertEquals("note", e.field)
        }
    }

    @Test
    fun note0_isTheLowestMidiNote() {
        assertEquals(0.0, TestIcons.NOTE_0.note, 0.0)
        assertEquals(8.175798915643707, TestIcons.NOTE_0.frequency, 1e-12)
    }

    @Test
    fun zeroLength_hasNoSamples() {
        assertEquals(0L, IconRenderer(TestIcons.ZERO_LENGTH, 48_000).sampleCount)
    }

    @Test
    fun stepOnset_startsAtItsLevelOnTheFirstSample() {
        // The paper's trapezoid; under the processing model a new envelope reader's first sample is 0 (JSyn).
        val renderer = IconRenderer(TestIcons.STEP_ONSET, 48_000, EnvelopeModel.PAPER)
        assertEquals(0.8, renderer.envelopeAt(0), 0.0)
        assertEquals(0.8, renderer.envelopeAt(9_600), 0.0) // second repetition's onset at 0.2 s
    }

    @Test
    fun overlapping_repetitionsOverlap() {
        val icon = TestIcons.OVERLAPPING
        assertTrue(icon.period < icon.envelopeDuration)
    }

    @Test
    fun edgeCases_listsEveryIconOnce() {
        assertEquals(6, TestIcons.EDGE_CASES.map { it.name }.toSet().size)
    }
}
