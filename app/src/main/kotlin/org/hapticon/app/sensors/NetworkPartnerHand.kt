package org.hapticon.app.sensors

import org.hapticon.messaging.HandPose
import org.hapticon.sensor.glove.PartnerHand

/**
 * A tele-handshake partner on the other end of the chat: their thumb and middle angles as their
 * [HandPose]s arrive ([offer], from the messaging thread). A hand not heard from for [staleAfterNanos]
 * reads as open (0°, 0°): a dropped connection must release the wearer, never hold the last grip.
 * Samples are kept in arrival order of their own timestamps, so a late, older one cannot undo a newer one.
 */
class NetworkPartnerHand(
    val peer: String,
    private val staleAfterNanos: Long = 500_000_000L,
) : PartnerHand {
    override val label: String = "$peer (over the network)"

    @Volatile private var latest: Received? = null

    private class Received(val thumb: Double, val middle: Double, val atMillis: Long, val receivedNanos: Long)

    /** Takes [pose], received at [receivedNanos]; ignored when it is not [peer]'s or older than the one held. */
    fun offer(pose: HandPose, receivedNanos: Long) {
        if (pose.from != peer) return
        val held = latest
        if (held != null && pose.atMillis < held.atMillis) return
        latest = Received(pose.thumbDegrees, pose.middleDegrees, pose.atMillis, receivedNanos)
    }

    /** Whether a fresh sample is held at [nowNanos]. */
    fun isLive(nowNanos: Long): Boolean = latest?.let { nowNanos - it.receivedNanos <= staleAfterNanos } ?: false

    override fun readAngles(nowNanos: Long, out: DoubleArray) {
        val held = latest
        if (held == null || nowNanos - held.receivedNanos > staleAfterNanos) {
            out[0] = 0.0
            out[1] = 0.0
        } else {
            out[0] = held.thumb
            out[1] = held.middle
        }
    }
}
