package org.hapticon.messaging

/**
 * One tele-handshake sample: the sender's thumb and middle-finger flex angles, streamed into the partner's
 * inbox about 30 times a second. Sent with QoS 0: a lost sample is replaced by the next one, and no
 * acknowledgement or retry holds up the stream (a handshake is live or not at all; receivers treat a hand
 * they have not heard from for a moment as open).
 *
 * A value is always valid: the constructor throws [InvalidMessageException] naming the first bad field.
 *
 * @property from who the hand belongs to (self-declared, as [ChatMessage.sender]).
 * @property thumbDegrees the thumb's flex angle, in [MIN_DEGREES]..[MAX_DEGREES].
 * @property middleDegrees the middle finger's flex angle, in the same range.
 * @property atMillis when it was measured, in milliseconds since the epoch (the sender's clock).
 */
public data class HandPose(
    val from: String,
    val thumbDegrees: Double,
    val middleDegrees: Double,
    val atMillis: Long,
) : InboxPayload {
    init {
        check(Topics.isValidUserName(from), RejectionReason.INVALID_VALUE, "from") { "not a valid user name: ${quote(from)}" }
        checkAngle(thumbDegrees, "thumb")
        checkAngle(middleDegrees, "middle")
        checkTimestamp(atMillis, "at")
    }

    public companion object {
        /** Lowest angle accepted: a calibrated finger bent slightly backwards reads a little below 0°. */
        public const val MIN_DEGREES: Double = -30.0

        /** Highest angle accepted: past any finger joint's travel, low enough to catch garbage. */
        public const val MAX_DEGREES: Double = 180.0
    }
}

private fun checkAngle(degrees: Double, field: String) =
    check(degrees.isFinite() && degrees in HandPose.MIN_DEGREES..HandPose.MAX_DEGREES, RejectionReason.INVALID_VALUE, field) {
        "expected an angle in ${HandPose.MIN_DEGREES}..${HandPose.MAX_DEGREES}°, got $degrees"
    }
