package org.hapticon.app.playback

import android.os.Vibrator
import kotlin.math.roundToInt
import org.robolectric.Shadows.shadowOf
import org.robolectric.shadows.ShadowVibrator

/** The last waveform handed to a (Robolectric) vibrator: step durations in ms and amplitudes 0..255. */
data class RecordedVibration(val timings: List<Long>, val amplitudes: List<Int>)

/**
 * Knock under the `paper` model on an amplitude vibrator: three 20 ms trapezoids (0 → 0.5 in 5 ms, 0.5 for 10 ms,
 * 0.5 → 0 in 5 ms) every 270 ms, each 10 ms step averaging 0.375 → 96/255.
 */
val PAPER_KNOCK = RecordedVibration(listOf(20L, 250L, 20L, 250L, 20L), listOf(96, 0, 96, 0, 96))

/** Knock under the `processing` model (the default): each pulse rises to 1 in 5 ms, then falls to 0.5 — steps 175 and 111. */
val PROCESSING_KNOCK = RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111))

/**
 * Reads what [vibrator] was last asked to play. Robolectric 4.17 records waveform effects as the
 * platform's step segments in a protected field without a getter, and the segment class is hidden
 * from the public android.jar, so both are read reflectively.
 *
 * The app vibrates from its render thread (`playOffMain`) while a test polls from its own, and ShadowVibrator
 * keeps the segments in a plain static ArrayList that each `vibrate` clears and refills: a read can meet it
 * half-written (a ConcurrentModificationException, or segments and pattern of different lengths). Such a read is
 * taken again, up to [TORN_READ_RETRIES] times, 1 ms apart; a record still torn after that is an error.
 */
fun lastVibration(vibrator: Vibrator): RecordedVibration? {
    var torn: Throwable? = null
    repeat(TORN_READ_RETRIES) {
        try {
            return readLastVibration(vibrator)
        } catch (e: ConcurrentModificationException) {
            torn = e
        } catch (e: TornRecord) {
            torn = e
        }
        Thread.sleep(1)
    }
    throw AssertionError("the vibrator's record stayed half-written over $TORN_READ_RETRIES reads", torn)
}

private const val TORN_READ_RETRIES = 200

private class TornRecord(message: String) : RuntimeException(message)

private fun readLastVibration(vibrator: Vibrator): RecordedVibration? {
    val timingsOnly = shadowOf(vibrator).pattern ?: return null
    val field = ShadowVibrator::class.java.getDeclaredField("vibrationEffectSegments").apply { isAccessible = true }
    val segments = (field.get(null) as List<*>).toList()
    if (segments.size != timingsOnly.size) throw TornRecord("segments and pattern disagree: ${segments.size} vs ${timingsOnly.size}")
    val timings = segments.map { it!!.javaClass.getMethod("getDuration").invoke(it) as Long }
    val amplitudes = segments.map { segment ->
        val amplitude = segment!!.javaClass.getMethod("getAmplitude").invoke(segment) as Float
        (amplitude * 255f).roundToInt()
    }
    return RecordedVibration(timings, amplitudes)
}
