package org.hapticon.app.feature.chat

import org.hapticon.app.data.database.StoredMessage

/** One row of a conversation: a message bubble, or the separator before a day's first message. */
sealed interface ConversationItem {
    val key: String

    data class Bubble(val message: StoredMessage, val time: String) : ConversationItem {
        override val key: String get() = message.id
    }

    data class DaySeparator(val label: String, override val key: String) : ConversationItem
}

/** The rows for [messages] (oldest first) newest first, as the bottom-anchored (reversed) list shows them. */
fun conversationItems(messages: List<StoredMessage>, clock: ChatClock, nowMillis: Long): List<ConversationItem> {
    val rows = ArrayList<ConversationItem>(messages.size + 4)
    for ((i, message) in messages.withIndex()) {
        val previous = messages.getOrNull(i - 1)
        if (previous == null || clock.differentDays(previous.sentAtMillis, message.sentAtMillis)) {
            rows += ConversationItem.DaySeparator(clock.dayLabel(message.sentAtMillis, nowMillis), "day-${message.id}")
        }
        rows += ConversationItem.Bubble(message, clock.timeOfDay(message.sentAtMillis))
    }
    rows.reverse()
    return rows
}
