package org.hapticon.messaging.mqtt

import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessageLimits
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics

/** Turns what arrives on a topic into an [InboxEvent]; never throws. Transport-independent, so testable alone. */
internal object InboxDecoding {
    fun decode(user: String, topic: String, payload: ByteArray): InboxEvent {
        if (topic == Topics.inbox(user)) {
            return when (val decoded = MessageCodec.decodeInbox(payload)) {
                is Decoded.Accepted -> when (val value = decoded.value) {
                    is ChatMessage -> InboxEvent.MessageReceived(value)
                    is Receipt -> InboxEvent.ReceiptReceived(value)
                    is HandPose -> InboxEvent.HandPoseReceived(value)
                }
                is Decoded.Rejected -> InboxEvent.Rejected(topic, decoded)
            }
        }
        val owner = Topics.capabilitiesOwner(topic)
            ?: return InboxEvent.Rejected(topic, Decoded.Rejected(RejectionReason.UNEXPECTED_TOPIC, null, "not an inbox or capabilities topic of $user"))
        return when (val decoded = MessageCodec.decodeCapabilities(payload)) {
            is Decoded.Accepted -> if (decoded.value.user == owner) {
                InboxEvent.CapabilitiesReceived(decoded.value)
            } else {
                // Only the owner may write its topic (the ACL says so); a mismatch is a forgery or a bug.
                InboxEvent.Rejected(
                    topic,
                    Decoded.Rejected(RejectionReason.INVALID_VALUE, "user", "capabilities of ${decoded.value.user} on the topic of $owner"),
                )
            }
            is Decoded.Rejected -> InboxEvent.Rejected(topic, decoded)
        }
    }

    fun oversized(topic: String, size: Int): InboxEvent = InboxEvent.Rejected(
        topic,
        Decoded.Rejected(RejectionReason.PAYLOAD_TOO_LARGE, null, "$size bytes exceed the limit of ${MessageLimits.MAX_PAYLOAD_BYTES}"),
    )
}
