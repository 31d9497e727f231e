package org.hapticon.app.playback

import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertEquals
import org.junit.Test

class ContinuousVibrationTest {
    private val calls = mutableListOf<String>()
    private val output = object : VibrationOutput {
        override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
        override fun play(waveform: VibrationWaveform) { calls += "play" }
        override fun playLevel(amplitude: Int, durationMillis: Long) { calls += "level $amplitude for $durationMillis" }
        override fun stop() { calls += "stop" }
    }
    private val ms = 1_000_000L

    @Test
    fun update_sameLevel_isRenewedOnlyBeforeItsOneShotRunsOut() {
        val vibration = ContinuousVibration(output)

        for (t in 0L..300L step 10) vibration.update(100, t * ms)

        // One-shots of 250 ms, renewed 150 ms after each call.
        assertEquals(listOf("level 100 for 250", "level 100 for 250", "level 100 for 250"), calls)
    }

    @Test
    fun update_changingLevel_atMostOneCallPer50Ms() {
        val vibration = ContinuousVibration(output)

        for (t in 0L until 100L step 5) vibration.update(50 + t.toInt(), t * ms)

        assertEquals(listOf("level 50 for 250", "level 100 for 250"), calls)
    }

    @Test
    fun update_zero_stopsAtOnceAndOnlyOnce() {
        val vibration = ContinuousVibration(output)
        vibration.update(120, 0)

        vibration.update(0, 1 * ms)
        vibration.update(0, 2 * ms)

        assertEquals(listOf("level 120 for 250", "stop"), calls)
        assertEquals(0, vibration.currentAmplitude)
    }

    @Test
    fun update_aboveTheCap_isClamped() {
        val vibration = ContinuousVibration(output, maxAmplitude = 180)

        vibration.update(255, 0)

        assertEquals(listOf("level 180 for 250"), calls)
    }

    @Test(expected = SafetyLimitException::class)
    fun update_outsideTheVibratorsRange_isRefused() {
        ContinuousVibration(output).update(300, 0)
    }
}
