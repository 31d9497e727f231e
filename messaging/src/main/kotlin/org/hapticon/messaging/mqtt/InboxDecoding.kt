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
        val sender = Topics.inboxSender(user, topic)
        if (sender != null) {
            return when (val decoded = MessageCodec.decodeInbox(payload)) {
                is Decoded.Accepted -> {
                    // The topic's sender is the broker's word (its ACL lets a user publish only under its own
                    // name); the payload's is the sender's claim. A disagreement is a forgery or a bug.
                    val (event, claimed, field) = when (val value = decoded.value) {
                        is ChatMessage -> Triple(InboxEvent.MessageReceived(value), value.sender, "sender")
                        is Receipt -> Triple(InboxEvent.ReceiptReceived(value), value.from, "from")
                        is HandPose -> Triple(InboxEvent.HandPoseReceived(value), value.from, "from")
                    }
                    if (claimed == sender) {
                        event
                    } else {
                        InboxEvent.Rejected(topic, Decoded.Rejected(RejectionReason.INVALID_VALUE, field, "$field $claimed on the topic of $sender"))
                    }
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
