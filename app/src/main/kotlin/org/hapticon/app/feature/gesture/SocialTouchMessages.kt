package org.hapticon.app.feature.gesture

import org.hapticon.gesture.social.ContactFrame
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.TouchPadSkin
import org.hapticon.gesture.social.TouchThresholds

/** One touch message cut from a contact stream: its 13 [SocialTouchFeatures], how many touches and how long. */
class TouchMessage(val features: DoubleArray, val touches: Int, val seconds: Double)

/**
 * Cuts a live contact stream into touch messages for [SocialTouchFeatures]. Each pointer sample is drawn on [pad]
 * (a grid of elements, [TouchPadSkin]) and a touch is any contact ([TouchThresholds.ANY_CONTACT]). The EIT-skin paper
 * recorded one message per prompted trial (001_e790093bbd2e3cd3.txt:164); a live pad has no trials, so a message here
 * is every touch until the pad has had no contact for [gapSeconds] (ours, not the paper's). Frames come in time
 * order; streaming, memory of two frames.
 */
class SocialTouchMessages(private val gapSeconds: Double = DEFAULT_GAP_SECONDS, private val pad: TouchPadSkin = TouchPadSkin()) {
    init {
        require(gapSeconds > 0.0 && gapSeconds.isFinite()) { "gapSeconds must be positive and finite, was $gapSeconds" }
    }

    private var features = SocialTouchFeatures(pad.layout, TouchThresholds.ANY_CONTACT)
    private var lastContactSeconds = Double.NaN

    /** Whether a finger is on the pad now. */
    val inContact: Boolean get() = features.inContact

    /** Touches so far in the message being collected. */
    val touchesSoFar: Int get() = features.touchCount

    /** Feeds one frame (intensity 0 or less: no contact); a frame with a non-finite field is skipped. */
    fun offer(frame: ContactFrame) {
        if (!(frame.timeSeconds.isFinite() && frame.intensity.isFinite() && frame.x.isFinite() && frame.y.isFinite() && frame.area.isFinite())) return
        val before = features.skippedFrames
        val wasInContact = features.inContact
        features.offer(pad.frame(frame))
        if (features.skippedFrames != before) return
        if (features.inContact || wasInContact) lastContactSeconds = frame.timeSeconds
    }

    /** The message, when it has had no contact for [gapSeconds] by [nowSeconds]; the next one starts empty. Else null. */
    fun endIfQuiet(nowSeconds: Double): TouchMessage? {
        // A microsecond of slack: times in seconds as doubles (21.55 + 1.0 − 21.55 is not exactly 1.0).
        if (inContact || touchesSoFar == 0 || nowSeconds - lastContactSeconds < gapSeconds - CLOCK_SLACK_SECONDS) return null
        return finish()
    }

    /** Whatever was collected as a message (the end of a file), or null without a touch; the next one starts empty. */
    fun finish(): TouchMessage? {
        if (touchesSoFar == 0) return null
        val message = TouchMessage(features.features(), touchesSoFar, features.contactSeconds)
        features = SocialTouchFeatures(pad.layout, TouchThresholds.ANY_CONTACT)
        lastContactSeconds = Double.NaN
        return message
    }

    companion object {
        /** A second without contact ends a message: longer than the pauses inside a pat or a tickle. */
        const val DEFAULT_GAP_SECONDS: Double = 1.0

        private const val CLOCK_SLACK_SECONDS = 1e-6
    }
}
