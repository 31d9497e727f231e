package org.hapticon.companion.gesture

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class ClassifyBenchSpeedUpTest {
    private fun result(accuracy: Double, micros: Double) =
        RecognitionResult(0.5, 30, accuracy, 0.01, latencyMs = Double.NaN, liveHitRate = 0.9, microsPerWindow = micros)

    @Test
    fun formatSpeedUp_parallelAndBaseline_printsBothAndTheirRatio() {
        assertEquals(
            "leave-one-out wall time: 17.0 s on 2 cores (folds in parallel), 34.0 s on one thread (baseline, same run): speed-up 2.00x; figures identical",
            formatSpeedUp(17.0, 34.0, 2, identical = true),
        )
        assertTrue(formatSpeedUp(20.0, 10.0, 2, identical = false).endsWith("speed-up 0.50x; figures DIFFER"))
    }

    @Test
    fun sameFigures_onlyTimingDiffers_isTrue() {
        assertTrue(sameFigures(listOf(result(0.8, 12.0)), listOf(result(0.8, 30.0))))
    }

    @Test
    fun sameFigures_accuracyDiffersOrRowMissing_isFalse() {
        assertFalse(sameFigures(listOf(result(0.8, 12.0)), listOf(result(0.81, 12.0))))
        assertFalse(sameFigures(listOf(result(0.8, 12.0)), emptyList()))
    }
}
