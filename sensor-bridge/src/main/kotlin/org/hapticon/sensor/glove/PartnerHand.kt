package org.hapticon.sensor.glove

import kotlin.math.PI
import kotlin.math.cos

/**
 * The other person's hand in a tele-handshake: their thumb and middle-finger angles: [NoPartner],
 * [SimulatedPartner], or the app's `NetworkPartnerHand` receiving them through the chat's broker. Read on the
 * sensor's reading thread: implementations must be thread-safe, non-blocking and allocation-free.
 */
public interface PartnerHand {
    /** Shown in the UI. */
    public val label: String

    /** Writes the partner's thumb angle to `out[0]` and middle-finger angle to `out[1]`, in degrees, at [nowNanos]. */
    public fun readAngles(nowNanos: Long, out: DoubleArray)
}

/** Nobody on the other side: an open hand (0°, 0°). */
public object NoPartner : PartnerHand {
    override val label: String = "No partner"

    override fun readAngles(nowNanos: Long, out: DoubleArray) {
        out[0] = 0.0
        out[1] = 0.0
    }
}

/**
 * A simulated partner who keeps shaking hands: over each [periodSeconds] the hand closes smoothly
 * from open to [gripThumbDegrees]/[gripMiddleDegrees] (like glove B of the loopback test: 50°/80°),
 * holds, and opens again, then rests.
 */
public class SimulatedPartner(
    private val periodSeconds: Double = 6.0,
    private val gripThumbDegrees: Double = 50.0,
    private val gripMiddleDegrees: Double = 80.0,
    private val startNanos: Long = System.nanoTime(),
) : PartnerHand {
    override val label: String = "Simulated partner"

    override fun readAngles(nowNanos: Long, out: DoubleArray) {
        val t = ((nowNanos - startNanos) / 1e9).mod(periodSeconds) / periodSeconds
        // 0–0.15 rest, 0.15–0.35 close, 0.35–0.65 hold, 0.65–0.85 open, 0.85–1 rest.
        val grip = when {
            t < 0.15 -> 0.0
            t < 0.35 -> ease((t - 0.15) / 0.2)
            t < 0.65 -> 1.0
            t < 0.85 -> 1.0 - ease((t - 0.65) / 0.2)
            else -> 0.0
        }
        out[0] = gripThumbDegrees * grip
        out[1] = gripMiddleDegrees * grip
    }

    private fun ease(x: Double): Double = (1 - cos(PI * x)) / 2
}
