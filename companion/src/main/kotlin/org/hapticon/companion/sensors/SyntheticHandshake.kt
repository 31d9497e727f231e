package org.hapticon.companion.sensors

import org.hapticon.sensor.glove.HandshakeCsv
import java.util.Locale
import kotlin.math.PI
import kotlin.math.cos

/**
 * Two gloves shaking hands, made up for the demo: angle CSVs as [HandshakeCsv] reads them, at [RATE_HZ] for
 * [SECONDS]. Each hand rests open, closes to its grip along a raised cosine over 0.6 s, holds, and opens
 * again over 0.6 s; the partner grips less and 0.2 s later, as in the sensor-bridge loopback test.
 */
object SyntheticHandshake {
    /** Rows per second: a glove's usual rate. */
    const val RATE_HZ: Int = 100

    /** Length of each recording. */
    const val SECONDS: Double = 5.0

    /** The self hand: thumb 60°, middle 90°, gripping from 1.0 s to 3.4 s. */
    fun selfCsv(): String = csv(thumbPeak = 60.0, middlePeak = 90.0, gripStart = 1.0, releaseStart = 3.4)

    /** The partner hand: thumb 50°, middle 80°, gripping from 1.2 s to 3.6 s. */
    fun partnerCsv(): String = csv(thumbPeak = 50.0, middlePeak = 80.0, gripStart = 1.2, releaseStart = 3.6)

    private fun csv(thumbPeak: Double, middlePeak: Double, gripStart: Double, releaseStart: Double): String = buildString {
        append(HandshakeCsv.ANGLE_HEADER).append('\n')
        val rows = (SECONDS * RATE_HZ).toInt()
        for (i in 0 until rows) {
            val t = i.toDouble() / RATE_HZ
            val closed = closure(t, gripStart, releaseStart)
            append(String.format(Locale.ROOT, "%.2f,%.2f,%.2f", t, thumbPeak * closed, middlePeak * closed)).append('\n')
        }
    }

    /** How far the hand is closed at [t], 0..1. */
    private fun closure(t: Double, gripStart: Double, releaseStart: Double): Double = when {
        t < gripStart -> 0.0
        t < gripStart + MOVE -> rise((t - gripStart) / MOVE)
        t < releaseStart -> 1.0
        t < releaseStart + MOVE -> 1 - rise((t - releaseStart) / MOVE)
        else -> 0.0
    }

    private const val MOVE = 0.6

    private fun rise(x: Double): Double = (1 - cos(PI * x)) / 2
}
