package org.hapticon.app.playback

import android.os.VibrationEffect
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.VibrationWaveform

/**
 * The platform effect for this waveform. [VibrationWaveform] guarantees the safety limits
 * (timings > 0, amplitudes 0..255, total ≤ 30 s); checked again here because this is the last
 * step before the actuator.
 */
fun VibrationWaveform.toVibrationEffect(): VibrationEffect {
    val timings = timings()
    val amplitudes = amplitudes()
    check(timings.sum() <= HapticIcon.MAX_DURATION_SECONDS * 1000) { "vibration longer than the safety cap" }
    check(amplitudes.all { it in 0..VibrationWaveform.MAX_AMPLITUDE }) { "amplitude outside 0..255" }
    return VibrationEffect.createWaveform(timings, amplitudes, NO_REPEAT)
}

private const val NO_REPEAT = -1
