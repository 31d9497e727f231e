package org.hapticon.app.feature.chat

import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.BrokerAddress

/**
 * What opening an invite link did: the contact added and the broker filled in, or the one-line reason
 * nothing changed. A link never replaces a broker already in use: switching brokers would cut the user
 * off from everyone on the old one, so that stays a deliberate change in Settings.
 */
sealed interface InviteOutcome {
    /** What the chats say about this outcome, in one line. */
    val message: String

    data class Added(val peer: String?, val brokerFilled: Boolean, val note: String?) : InviteOutcome {
        override val message: String
            get() = note ?: buildString {
                append(peer?.let { "$it added to your chats" } ?: "Invite opened")
                if (brokerFilled) append("; broker filled in")
            }
    }

    data class Rejected(val reason: String) : InviteOutcome {
        override val message: String get() = "Invite not used: $reason"
    }
}

/** Applies an opened invite link: validates it fully before changing anything. */
suspend fun applyInvite(text: String, repository: ChatRepository, settings: ChatSettingsRepository): InviteOutcome {
    val link = InviteLink.parse(text).getOrElse { return InviteOutcome.Rejected(it.message ?: "Not a Hapticon invite") }
    val prefs = settings.preferences.value
    if (link.user != null && link.user == prefs.userName) return InviteOutcome.Rejected("This is your own invite")
    val current = prefs.brokerUrl.takeIf { it.isNotEmpty() }?.let { runCatching { BrokerAddress.parse(it) }.getOrNull() }
    val fill = current == null
    if (fill) settings.update { it.copy(brokerUrl = link.broker.toString()) }
    link.user?.let { repository.startConversation(it) }
    val note = if (!fill && current != link.broker) "${link.user ?: "The invite"} uses ${link.broker}; you stay on $current (change it in Settings)" else null
    return InviteOutcome.Added(link.user, fill, note)
}
