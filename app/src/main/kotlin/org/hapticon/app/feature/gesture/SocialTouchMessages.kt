package org.hapticon.app.feature.gesture

import org.hapticon.gesture.social.ContactFrame
import org.hapticon.gesture.social.SocialTouchFeatures

/** One touch message cut from a contact stream: its 13 [SocialTouchFeatures], how many touches and how long. */
class TouchMessage(val features: DoubleArray, val touches: Int, val seconds: Double)

/**
 * Cuts a live contact stream into touch messages for [SocialTouchFeatures]. The EIT-skin paper recorded one
 * message per trial, started and stopped by the experimenter; a live pad has no trials, so a message here is
 * every touch until the pad has had no contact for [gapSeconds] (our rule, not the paper's). Frames come in time
 * order; streaming, O(1) in memory.
 */
class SocialTouchMessages(private val gapSeconds: Double = DEFAULT_GAP_SECONDS) {
    init {
        require(gapSeconds > 0.0 && gapSeconds.isFinite()) { "gapSeconds must be positive and finite, was $gapSeconds" }
    }

    private var features = SocialTouchFeatures()
    private var contact = false
    private var touches = 0
    private var lastContactSeconds = Double.NaN

    /** Whether a finger is on the pad now. */
    val inContact: Boolean get() = contact

    /** Touches so far in the message being collected. */
    val touchesSoFar: Int get() = touches

    /** Feeds one frame (intensity 0 or less: no contact). */
    fun offer(frame: ContactFrame) {
        val before = features.skippedFrames
        features.offer(frame)
        if (features.skippedFrames != before) return
        val touching = frame.intensity > 0.0
        if (touching && !contact) touches++
        if (touching || contact) lastContactSeconds = frame.timeSeconds
        contact = touching
    }

    /** The message, when it has had no contact for [gapSeconds] by [nowSeconds]; the next one starts empty. Else null. */
    fun endIfQuiet(nowSeconds: Double): TouchMessage? {
        // A microsecond of slack: times in seconds as doubles (21.55 + 1.0 − 21.55 is not exactly 1.0).
        if (contact || touches == 0 || nowSeconds - lastContactSeconds < gapSeconds - CLOCK_SLACK_SECONDS) return null
        return finish()
    }

    /** Whatever was collected as a message (the end of a file), or null without a touch; the next one starts empty. */
    fun finish(): TouchMessage? {
        if (touches == 0) return null
        val f = features.features()
        val message = TouchMessage(f, touches, f[MESSAGE_SECONDS])
        features = SocialTouchFeatures()
        contact = false
        touches = 0
        lastContactSeconds = Double.NaN
        return message
    }

    companion object {
        /** A second without contact ends a message: longer than the pauses inside a pat or a tickle. */
        const val DEFAULT_GAP_SECONDS: Double = 1.0

        private const val CLOCK_SLACK_SECONDS = 1e-6

        /** Index of `message_s` in [SocialTouchFeatures.NAMES]. */
        private val MESSAGE_SECONDS = SocialTouchFeatures.NAMES.indexOf("message_s")
    }
}
