package org.hapticon.app.sync

import android.Manifest
import android.app.NotificationChannel
import android.app.NotificationChannelGroup
import android.app.NotificationManager
import android.app.PendingIntent
import android.content.BroadcastReceiver
import android.content.Context
import android.content.Intent
import android.content.pm.PackageManager
import android.os.Build
import androidx.core.app.NotificationCompat
import androidx.core.app.NotificationManagerCompat
import androidx.core.app.Person
import androidx.core.app.RemoteInput
import androidx.core.content.ContextCompat
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.launch
import org.hapticon.app.playback.playOffMain
import org.hapticon.app.R
import org.hapticon.messaging.ChatMessage

/**
 * Announces arriving messages the way Android messengers do: one `MessagingStyle` notification per
 * conversation, on that conversation's own channel (so the user can silence one person), showing the
 * text and the icon's glyph and name, with "Reply" (inline), "Mark as read" and "Feel again" actions. Each message is
 * shown once: [show] ignores an id it already showed. Nothing is posted without the notification
 * permission (Android 13+) or with notifications off for the app.
 */
class MessageNotifier(private val context: Context, private val selfName: () -> String?) {
    private val manager = NotificationManagerCompat.from(context)
    private val lines = HashMap<String, ArrayDeque<ChatMessage>>()
    private val shown = LinkedHashSet<String>()

    /** Whether a notification would be shown now. */
    fun canNotify(): Boolean {
        if (Build.VERSION.SDK_INT >= 33 &&
            ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) != PackageManager.PERMISSION_GRANTED
        ) return false
        return manager.areNotificationsEnabled()
    }

    /** Posts (or extends) the conversation's notification with [message]; false when nothing was posted. */
    @Synchronized
    fun show(message: ChatMessage): Boolean {
        if (message.id in shown) return false
        if (!canNotify()) return false
        shown += message.id
        if (shown.size > MAX_REMEMBERED) shown.remove(shown.first())
        val peer = message.sender
        val history = lines.getOrPut(peer) { ArrayDeque() }
        history.addLast(message)
        while (history.size > MAX_LINES) history.removeFirst()
        post(peer, history)
        return true
    }

    /** Removes [peer]'s notification (its conversation was opened). */
    @Synchronized
    fun clear(peer: String) {
        lines.remove(peer)
        manager.cancel(peer, NOTIFICATION_ID)
    }

    @Suppress("MissingPermission") // canNotify() checked it.
    private fun post(peer: String, history: List<ChatMessage>) {
        val channel = channelFor(peer)
        val me = Person.Builder().setName(selfName() ?: "You").setKey("self").build()
        val them = Person.Builder().setName(peer).setKey(peer).build()
        val style = NotificationCompat.MessagingStyle(me)
        for (m in history) style.addMessage(NotificationCompat.MessagingStyle.Message(lineOf(m), m.sentAtMillis, them))
        val latest = history.last()
        val builder = NotificationCompat.Builder(context, channel)
            .setSmallIcon(R.drawable.ic_notification)
            .setStyle(style)
            .setCategory(NotificationCompat.CATEGORY_MESSAGE)
            .setAutoCancel(true)
            .setContentIntent(openIntent(peer))
            .addAction(replyAction(peer))
            .addAction(markReadAction(peer))
        (latest.icon?.name ?: latest.pattern?.name)?.let { builder.addAction(feelAction(peer, latest.id, it)) }
        manager.notify(peer, NOTIFICATION_ID, builder.build())
    }

    /** A notification line: the icon's or pattern's glyph and name, then the text (or "Sticker"). */
    internal fun lineOf(m: ChatMessage): String = listOfNotNull(
        (m.icon?.name ?: m.pattern?.name)?.let { "〰 $it" },
        m.text.takeIf { it.isNotEmpty() } ?: m.sticker?.let { "Sticker: $it" },
    ).joinToString(" · ")

    private fun channelFor(peer: String): String {
        val id = "chat-$peer"
        if (Build.VERSION.SDK_INT >= 26) {
            val system = context.getSystemService(NotificationManager::class.java)
            if (system.getNotificationChannel(id) == null) {
                system.createNotificationChannelGroup(NotificationChannelGroup(GROUP, "Chats"))
                system.createNotificationChannel(
                    NotificationChannel(id, peer, NotificationManager.IMPORTANCE_HIGH).apply {
                        group = GROUP
                        description = "Messages from $peer"
                    },
                )
            }
        }
        return id
    }

    private fun openIntent(peer: String): PendingIntent = PendingIntent.getActivity(
        context, peer.hashCode(),
        Intent(context, context.chatHost.launchActivity).setAction(ACTION_OPEN_CHAT).putExtra(EXTRA_PEER, peer)
            .addFlags(Intent.FLAG_ACTIVITY_SINGLE_TOP),
        PendingIntent.FLAG_UPDATE_CURRENT or PendingIntent.FLAG_IMMUTABLE,
    )

    private fun replyAction(peer: String): NotificationCompat.Action {
        val input = RemoteInput.Builder(KEY_REPLY).setLabel("Reply to $peer").build()
        // Mutable: the system writes the typed reply into the intent.
        val flags = PendingIntent.FLAG_UPDATE_CURRENT or (if (Build.VERSION.SDK_INT >= 31) PendingIntent.FLAG_MUTABLE else 0)
        val intent = PendingIntent.getBroadcast(
            context, peer.hashCode(),
            Intent(context, NotificationActionReceiver::class.java).setAction(ACTION_REPLY).putExtra(EXTRA_PEER, peer),
            flags,
        )
        return NotificationCompat.Action.Builder(R.drawable.ic_notification, "Reply", intent)
            .addRemoteInput(input)
            .setSemanticAction(NotificationCompat.Action.SEMANTIC_ACTION_REPLY)
            .setAllowGeneratedReplies(true)
            .build()
    }

    // As in Google Messages and Signal: read without opening the app; the sender gets the read receipts.
    private fun markReadAction(peer: String): NotificationCompat.Action {
        val intent = PendingIntent.getBroadcast(
            context, peer.hashCode(),
            Intent(context, NotificationActionReceiver::class.java).setAction(ACTION_MARK_READ).putExtra(EXTRA_PEER, peer),
            PendingIntent.FLAG_UPDATE_CURRENT or PendingIntent.FLAG_IMMUTABLE,
        )
        return NotificationCompat.Action.Builder(R.drawable.ic_notification, "Mark as read", intent)
            .setSemanticAction(NotificationCompat.Action.SEMANTIC_ACTION_MARK_AS_READ)
            .setShowsUserInterface(false)
            .build()
    }

    private fun feelAction(peer: String, messageId: String, iconName: String): NotificationCompat.Action {
        val intent = PendingIntent.getBroadcast(
            context, messageId.hashCode(),
            Intent(context, NotificationActionReceiver::class.java).setAction(ACTION_FEEL)
                .putExtra(EXTRA_PEER, peer).putExtra(EXTRA_MESSAGE, messageId),
            PendingIntent.FLAG_UPDATE_CURRENT or PendingIntent.FLAG_IMMUTABLE,
        )
        return NotificationCompat.Action.Builder(R.drawable.ic_notification, "Feel $iconName again", intent).build()
    }

    companion object {
        const val NOTIFICATION_ID: Int = 1
        const val GROUP: String = "chats"
        const val ACTION_OPEN_CHAT: String = "org.hapticon.app.OPEN_CHAT"
        const val ACTION_REPLY: String = "org.hapticon.app.REPLY"
        const val ACTION_FEEL: String = "org.hapticon.app.FEEL_AGAIN"
        const val ACTION_MARK_READ: String = "org.hapticon.app.MARK_READ"
        const val EXTRA_PEER: String = "peer"
        const val EXTRA_MESSAGE: String = "message"
        const val KEY_REPLY: String = "reply"
        private const val MAX_LINES = 8
        private const val MAX_REMEMBERED = 500
    }
}

/**
 * The notification's actions: "Mark as read" marks the conversation read and sends the read receipts
 * (kept for later while offline); "Reply" stores the typed text as an own message (the outbox sends it,
 * so a reply typed offline is not lost) and "Feel again" plays the message's icon or pattern through the normal
 * player and sends the felt receipt. Both run in the background without opening the app.
 */
class NotificationActionReceiver : BroadcastReceiver() {
    override fun onReceive(context: Context, intent: Intent) {
        val chat = context.chatHost.chat ?: return
        val peer = intent.getStringExtra(MessageNotifier.EXTRA_PEER) ?: return
        val pending = goAsync()
        CoroutineScope(SupervisorJob() + Dispatchers.Default).launch {
            try {
                when (intent.action) {
                    MessageNotifier.ACTION_REPLY -> {
                        val text = RemoteInput.getResultsFromIntent(intent)?.getCharSequence(MessageNotifier.KEY_REPLY)?.toString()
                        val user = chat.settings.preferences.value.userName
                        if (!text.isNullOrBlank() && user != null) {
                            chat.repository.send(user, peer, text)
                            chat.sync.wake()
                        }
                        chat.notifier?.clear(peer)
                    }
                    MessageNotifier.ACTION_MARK_READ -> {
                        chat.sync.markRead(peer)
                        chat.notifier?.clear(peer)
                    }
                    MessageNotifier.ACTION_FEEL -> {
                        val id = intent.getStringExtra(MessageNotifier.EXTRA_MESSAGE) ?: return@launch
                        val message = chat.repository.message(id) ?: return@launch
                        val icon = message.icon
                        val pattern = message.pattern
                        when {
                            icon != null -> chat.player.playOffMain(icon)
                            pattern != null -> chat.player.playOffMain(pattern)
                            else -> return@launch
                        }
                        if (!message.outgoing) chat.sync.felt(peer, id)
                    }
                }
            } catch (e: Exception) {
                android.util.Log.w("NotificationAction", "${intent.action} for $peer failed: ${e.message}")
            } finally {
                pending.finish()
            }
        }
    }
}
