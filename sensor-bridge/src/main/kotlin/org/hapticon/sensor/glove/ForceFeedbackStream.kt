package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimits

/** Takes LucidGloves force-feedback servo values, thumb … pinky (0 no force … 1000 full force). */
public fun interface ForceFeedbackSink {
    /** Sends [servoValues] (five values) to the glove; false if nothing could take them. */
    public fun send(servoValues: IntArray): Boolean
}

/**
 * Follows the handshake's per-region servo values (one set per sensor sample) with LucidGloves
 * force-feedback commands, without flooding the serial line:
 *
 * - **Changes only.** The glove's servos hold their position, so an unchanged set is not resent.
 * - **Rate limit.** At most one command per [minIntervalNanos] (default 50 ms, 20 commands/s, the same
 *   pace as the phone vibrator); sets in between are dropped and the next sample carries the newest.
 * - **Release at once.** A set with no force anywhere (the handshake ended) goes out without waiting
 *   for the interval, so the wearer's hand is freed immediately.
 *
 * Values are checked against [SafetyLimits] before anything is sent. Not thread-safe: call [update]
 * from one thread (the sensor's reading thread).
 */
public class ForceFeedbackStream(private val minIntervalNanos: Long = 50_000_000L) {
    private val pending = IntArray(HandshakeFrame.LUCID_GLOVES_FINGERS)
    private val lastSent = IntArray(HandshakeFrame.LUCID_GLOVES_FINGERS)
    private var lastSendNanos = Long.MIN_VALUE / 2
    private var sentAnything = false

    /** Commands sent so far. */
    public var commands: Long = 0
        private set

    /** A copy of the last set sent (all 0 before the first). */
    public fun lastSentValues(): IntArray = lastSent.copyOf()

    /**
     * Follows [regionServoValues] (per region in [HandRegion.ALL] order, as
     * [org.hapticon.sensor.glove.HandshakeSession.computeInto] writes them) at [nowNanos] through [sink].
     * @throws org.hapticon.sensor.safety.SafetyLimitException if a value is outside the servo range.
     */
    public fun update(regionServoValues: IntArray, nowNanos: Long, sink: ForceFeedbackSink) {
        var release = true
        for (region in HandRegion.entries) {
            val finger = region.lucidGlovesIndex ?: continue
            val value = SafetyLimits.requireServoValue(regionServoValues[region.ordinal])
            pending[finger] = value
            if (value != SafetyLimits.SERVO_MIN) release = false
        }
        if (sentAnything && pending.contentEquals(lastSent)) return
        if (!release && nowNanos - lastSendNanos < minIntervalNanos) return
        send(nowNanos, sink)
    }

    /** Releases every finger now (all servo values 0), unless that is what the glove already has. */
    public fun release(nowNanos: Long, sink: ForceFeedbackSink) {
        pending.fill(SafetyLimits.SERVO_MIN)
        if (sentAnything && pending.contentEquals(lastSent)) return
        send(nowNanos, sink)
    }

    private fun send(nowNanos: Long, sink: ForceFeedbackSink) {
        if (!sink.send(pending)) return
        pending.copyInto(lastSent)
        lastSendNanos = nowNanos
        sentAnything = true
        commands++
    }
}
