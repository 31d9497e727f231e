package org.hapticon.app.playback

import org.hapticon.sensor.safety.SafetyLimits

/**
 * A vibration level that follows a stream of target amplitudes (one per sensor sample) without
 * flooding the vibrator: Android has no "change the running amplitude" call, so each update is a
 * short one-shot of [segmentMillis] at the new level that replaces the previous one.
 *
 * - **Rate limit.** At most one vibrator call per [minIntervalNanos] (default 50 ms, 20 calls/s);
 *   targets in between are dropped (the next sample after the interval carries the newest one).
 * - **Renewal.** An unchanged level is renewed only when its one-shot is about to run out.
 * - **Dead-man's switch.** Every one-shot is short (default 250 ms), so if the stream stalls or the
 *   app dies the phone stops by itself.
 * - **Off at once.** A target of 0 stops the vibrator immediately, without waiting for the interval.
 * - **Cap.** Targets are clamped to [maxAmplitude] and checked against [SafetyLimits].
 *
 * Not thread-safe: call [update] from one thread (the sensor's reading thread).
 */
class ContinuousVibration(
    private val output: VibrationOutput,
    maxAmplitude: Int = SafetyLimits.VIBRATION_AMPLITUDE_MAX,
    private val minIntervalNanos: Long = 50_000_000L,
    private val segmentMillis: Long = 250L,
) {
    /** The largest amplitude this ever plays. */
    val maxAmplitude: Int = SafetyLimits.requireVibrationAmplitude(maxAmplitude)

    private val renewBeforeEndNanos = segmentMillis * 1_000_000L - 2 * minIntervalNanos
    private var lastIssueNanos = Long.MIN_VALUE / 2
    private var playingAmplitude = 0

    /** The amplitude last sent to the vibrator, 0 when off. */
    val currentAmplitude: Int get() = playingAmplitude

    /** Vibrator calls made so far. */
    var calls: Long = 0
        private set

    /**
     * Follows [target] (0..255; 0 = off) at time [nowNanos].
     * @throws org.hapticon.sensor.safety.SafetyLimitException if [target] is outside 0..255.
     */
    fun update(target: Int, nowNanos: Long) {
        SafetyLimits.requireVibrationAmplitude(target)
        val amplitude = minOf(target, maxAmplitude)
        if (amplitude == 0) {
            stop()
            return
        }
        val sinceLast = nowNanos - lastIssueNanos
        if (sinceLast < minIntervalNanos) return
        if (amplitude == playingAmplitude && sinceLast < renewBeforeEndNanos) return
        output.playLevel(amplitude, segmentMillis)
        calls++
        lastIssueNanos = nowNanos
        playingAmplitude = amplitude
    }

    /** Stops the vibrator if this was playing. */
    fun stop() {
        if (playingAmplitude == 0) return
        output.stop()
        calls++
        playingAmplitude = 0
    }
}
