package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrotactileUserLimit
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class GrainOutputTest {
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

    @Test
    fun electrotactile_withinTheUserLimit_holdsTheGrainBurst() {
        val output = GrainOutput.electrotactile(ElectrodeMask.TRIANGLE, 1.5, ElectrotactileUserLimit(2.0))
        assertEquals(ElectrodeMask.TRIANGLE.pattern, output.command.pattern)
        assertEquals(1.5, output.command.currentMilliamps, 0.0)
        assertEquals(125.0, output.command.pulses.frequencyHz, 0.0)
    }

    @Test
    fun electrotactile_aboveTheUserLimit_isRefused() {
        try {
            GrainOutput.electrotactile(ElectrodeMask.TRIANGLE, 2.1, ElectrotactileUserLimit(2.0))
            fail("accepted")
        } catch (e: SafetyLimitException) {
            assertEquals("electrotactileCurrent", e.limit)
        }
    }
}
