package org.hapticon.sensor.grains

import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class LraGrainTest {
    @Test
    fun lraGrain_waveform_isOneEntryOfTheGrainsLength() {
        val waveform = LraGrain(0.020, 255).waveform()
        assertArrayEquals(longArrayOf(20), waveform.timings())
        assertArrayEquals(intArrayOf(255), waveform.amplitudes())
        assertArrayEquals(intArrayOf(128), LraGrain(0.012, 128).waveform().amplitudes())
        assertArrayEquals(longArrayOf(12), LraGrain(0.012, 128).waveform().timings())
    }

    @Test
    fun lraGrain_icon_isAHeldNote53OfTheGrainsLength() {
        val icon = LraGrain(0.015, 51).icon()
        assertEquals(0.015, icon.duration, 0.0)
        assertEquals(53.0, icon.note, 0.0)
        assertEquals(0.2, icon.level, 1e-15)
        assertEquals(174.61411571650194, icon.frequency, 1e-9)
    }

    @Test
    fun lraGrain_outsideTheVibrationLimits_isRefused() {
        for (make in listOf({ LraGrain(0.02, 256) }, { LraGrain(Math.nextUp(30.0), 255) }, { LraGrain(Double.NaN, 255) })) {
            try {
                make()
                fail("accepted")
            } catch (_: SafetyLimitException) {
            }
        }
        for (make in listOf({ LraGrain(0.02, 0) }, { LraGrain(0.0009, 255) })) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }
}
