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
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.KeyNews
import org.hapticon.messaging.e2e.Opened

/** Turns what arrives on a topic into an [InboxEvent]; never throws. Transport-independent, so testable alone. */
internal object InboxDecoding {
    /**
     * With [e2e], inbox payloads must be sealed and open (see [EndToEnd.open]) and key topics are learnt;
     * without it, a sealed payload is named as such rather than rejected as an unknown schema. Returns null
     * for a key that needs no one's attention (first seen or unchanged). An inbox message that arrives [retained]
     * (the broker replays a retained message at every subscription, MQTT 3.1.1 §3.3.1.3) is refused unread: the
     * embedded broker refuses such publishes, Mosquitto cannot (docs/security.md). On other topics [retained] is
     * passed on with capabilities ([InboxEvent.CapabilitiesReceived.retained]).
     */
    fun decode(user: String, topic: String, payload: ByteArray, e2e: EndToEnd? = null, retained: Boolean = false): InboxEvent? {
        val sender = Topics.inboxSender(user, topic)
        if (sender != null && retained) {
            return InboxEvent.Rejected(topic, Decoded.Rejected(RejectionReason.RETAINED, null, "a retained message from $sender: replayed by the broker, not shown"))
        }
        if (sender != null) {
            val plaintext = when {
                e2e != null -> when (val opened = e2e.open(sender, payload)) {
                    is Opened.Plain -> opened.plaintext
                    is Opened.Refused -> return InboxEvent.Rejected(topic, Decoded.Rejected(opened.reason, null, opened.detail))
                }
                EndToEnd.looksSealed(payload) -> return InboxEvent.Rejected(
                    topic,
                    Decoded.Rejected(RejectionReason.ENCRYPTED, null, "end-to-end encrypted payload from $sender: this client has no keys to open it (turn end-to-end encryption on)"),
                )
                else -> payload
            }
            return when (val decoded = MessageCodec.decodeInbox(plaintext)) {
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
        val keyOwner = Topics.keysOwner(topic)
        if (keyOwner != null && e2e != null) {
            return when (val news = e2e.learn(keyOwner, payload)) {
                is KeyNews.Changed -> InboxEvent.Rejected(
                    topic,
                    Decoded.Rejected(
                        RejectionReason.KEY_CHANGED,
                        null,
                        "$keyOwner's key changed (safety number now ${news.newSafetyNumber}, was ${news.pinnedSafetyNumber}); the pinned key stays until you trust the new one",
                    ),
                )
                is KeyNews.Invalid -> InboxEvent.Rejected(topic, Decoded.Rejected(RejectionReason.FORGED, null, news.detail))
                is KeyNews.Pinned, KeyNews.Unchanged -> null // nothing for the listener: the key is there for sealing
            }
        }
        val owner = Topics.capabilitiesOwner(topic)
            ?: return InboxEvent.Rejected(topic, Decoded.Rejected(RejectionReason.UNEXPECTED_TOPIC, null, "not an inbox or capabilities topic of $user"))
        return when (val decoded = MessageCodec.decodeCapabilities(payload)) {
            is Decoded.Accepted -> if (decoded.value.user == owner) {
                InboxEvent.CapabilitiesReceived(decoded.value, retained)
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
