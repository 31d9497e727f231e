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
import android.graphics.Bitmap
import android.graphics.Canvas
import android.graphics.Color
import android.graphics.Paint
import android.media.AudioAttributes
import android.media.AudioManager
import android.os.Build
import android.provider.Settings
import androidx.core.app.NotificationCompat
import androidx.core.app.NotificationManagerCompat
import androidx.core.app.Person
import androidx.core.app.RemoteInput
import androidx.core.content.ContextCompat
import androidx.core.content.LocusIdCompat
import androidx.core.content.pm.ShortcutInfoCompat
import androidx.core.content.pm.ShortcutManagerCompat
import androidx.core.graphics.drawable.IconCompat
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.launch
import org.hapticon.app.R
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.messageUsage
import org.hapticon.app.playback.playMessageOffMain
import org.hapticon.messaging.AlertChannel
import org.hapticon.messaging.ArrivalAlert
import org.hapticon.messaging.ArrivalConditions
import org.hapticon.messaging.ChannelSettings
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.DisplayText
import org.hapticon.messaging.DoNotDisturb
import org.hapticon.messaging.RingerMode

/**
 * Announces arriving messages the way Android messengers do: one `MessagingStyle` notification per conversation, a
 * conversation in Android's sense (Android 11+ shows it in the Conversations section): a long-lived dynamic shortcut per
 * peer with its [Person] (a letter avatar) and [LocusIdCompat], which AOSP `ShortcutHelper.isConversationShortcut`
 * requires (long-lived and enabled). It shows the text and the icon's glyph and name (peer text neutralised:
 * [DisplayText]), with "Reply" (inline), "Mark as read" and "Feel again" actions; a tap opens the chat. Each message is
 * shown once: [show] ignores an id it already showed. Nothing is posted without the notification permission (Android
 * 13+) or with notifications off for the app.
 *
 * Each peer has two channels, so that the user can silence one person, and so that a message's icon is its only
 * vibration ([ArrivalAlert]):
 * - `chat-PEER`, the message channel: rings and vibrates as a messenger does, for messages whose icon does not play;
 * - `icons-PEER`, the icon channel: neither rings nor vibrates, for messages whose icon plays right after the notification.
 *   A sound would not do either: in vibrate mode Android demotes a channel's sound to its fallback vibration when the
 *   channel has none (AOSP `NotificationAttentionHelper.buzzBeepBlinkLocked`, "Demote sound to vibration"), which
 *   would buzz over the icon in the pocket; and an audible cue beside a haptic one is what the studies mask with noise.
 */
class MessageNotifier(
    private val context: Context,
    /** The time a message arrives, for the notification's `when` (a picture's test gives Robolectric's frozen clock). */
    private val now: () -> Long = System::currentTimeMillis,
    private val selfName: () -> String?,
) {
    private val manager = NotificationManagerCompat.from(context)
    private val lines = HashMap<String, ArrayDeque<ChatMessage>>()
    private val shown = LinkedHashSet<String>()
    private val shortcuts = HashSet<String>()
    // What a peer's notification repeats at every message, made once per peer (the avatar is drawn, the intents are
    // binder calls): arrival to touch waits for the notification (docs/performance.md, "Arrival to touch").
    private val parts = object : LinkedHashMap<String, PeerParts>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, PeerParts>) = size > MAX_PEERS_KEPT
    }
    // The channels known to exist: only this app deletes its channels, and it never does.
    private val channels = HashSet<String>()

    private class PeerParts(
        val person: Person,
        val open: PendingIntent,
        val reply: NotificationCompat.Action,
        val markRead: NotificationCompat.Action,
    )

    private fun partsOf(peer: String): PeerParts =
        parts.getOrPut(peer) { PeerParts(personOf(peer), openIntent(peer), replyAction(peer), markReadAction(peer)) }

    /** Whether a notification would be shown now. */
    fun canNotify(): Boolean {
        if (Build.VERSION.SDK_INT >= 33 &&
            ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) != PackageManager.PERMISSION_GRANTED
        ) return false
        return manager.areNotificationsEnabled()
    }

    /**
     * Posts (or extends) the conversation's notification with [message] on the channel [alert] names (the icon channel
     * when its icon plays next); false when nothing was posted.
     */
    @Synchronized
    fun show(message: ChatMessage, alert: ArrivalAlert = ArrivalAlert.NOTIFICATION): Boolean {
        if (message.id in shown) return false
        if (!canNotify()) return false
        shown += message.id
        if (shown.size > MAX_REMEMBERED) shown.remove(shown.first())
        val peer = message.sender
        val history = lines.getOrPut(peer) { ArrayDeque() }
        history.addLast(message)
        while (history.size > MAX_LINES) history.removeFirst()
        post(peer, history, alert.channel)
        return true
    }

    /** Removes [peer]'s notification (its conversation was opened). */
    @Synchronized
    fun clear(peer: String) {
        lines.remove(peer)
        manager.cancel(peer, NOTIFICATION_ID)
    }

    /**
     * The ringer, Do Not Disturb and [peer]'s icon channel now: what [ArrivalAlert] is decided on. Do Not Disturb is the
     * interruption filter with the policy in force (`getConsolidatedNotificationPolicy`, API 30+, else the user's default).
     */
    fun arrivalConditions(peer: String): ArrivalConditions {
        val audio = context.getSystemService(AudioManager::class.java)
        val ringer = when (audio?.ringerMode) {
            AudioManager.RINGER_MODE_SILENT -> RingerMode.SILENT
            AudioManager.RINGER_MODE_VIBRATE -> RingerMode.VIBRATE
            else -> RingerMode.NORMAL
        }
        return ArrivalConditions(ringer, doNotDisturb(), iconChannelSettings(peer))
    }

    private fun doNotDisturb(): DoNotDisturb {
        val system = context.getSystemService(NotificationManager::class.java) ?: return DoNotDisturb.OFF
        val filter = when (system.currentInterruptionFilter) {
            NotificationManager.INTERRUPTION_FILTER_PRIORITY -> DoNotDisturb.Filter.PRIORITY
            NotificationManager.INTERRUPTION_FILTER_NONE -> DoNotDisturb.Filter.NONE
            NotificationManager.INTERRUPTION_FILTER_ALARMS -> DoNotDisturb.Filter.ALARMS
            else -> return DoNotDisturb.OFF
        }
        val policy: NotificationManager.Policy? =
            (if (Build.VERSION.SDK_INT >= 30) system.consolidatedNotificationPolicy else null) ?: system.notificationPolicy
        val categories = policy?.priorityCategories ?: 0
        val messages = if (categories and NotificationManager.Policy.PRIORITY_CATEGORY_MESSAGES == 0) null else when (policy?.priorityMessageSenders) {
            NotificationManager.Policy.PRIORITY_SENDERS_ANY -> DoNotDisturb.Senders.ANYONE
            NotificationManager.Policy.PRIORITY_SENDERS_CONTACTS -> DoNotDisturb.Senders.CONTACTS
            else -> DoNotDisturb.Senders.STARRED
        }
        val conversations = if (Build.VERSION.SDK_INT < 30 || categories and NotificationManager.Policy.PRIORITY_CATEGORY_CONVERSATIONS == 0) {
            null
        } else {
            when (policy?.priorityConversationSenders) {
                NotificationManager.Policy.CONVERSATION_SENDERS_ANYONE -> DoNotDisturb.ConversationSenders.ANYONE
                NotificationManager.Policy.CONVERSATION_SENDERS_IMPORTANT -> DoNotDisturb.ConversationSenders.IMPORTANT
                else -> null
            }
        }
        return DoNotDisturb(filter, messages, conversations)
    }

    /**
     * What the user set for [peer]'s icon channel: the conversation's own channel where Android made one (API 30+, once
     * the user changed the conversation's settings), else the channel itself.
     */
    fun iconChannelSettings(peer: String): ChannelSettings {
        if (Build.VERSION.SDK_INT < 26) return ChannelSettings(alerting = true)
        val system = context.getSystemService(NotificationManager::class.java) ?: return ChannelSettings(alerting = true)
        val id = channelFor(peer, AlertChannel.ICONS)
        val channel = (if (Build.VERSION.SDK_INT >= 30) system.getNotificationChannel(id, shortcutId(peer)) else null)
            ?: system.getNotificationChannel(id) ?: return ChannelSettings(alerting = true)
        return ChannelSettings(
            alerting = channel.importance >= NotificationManager.IMPORTANCE_DEFAULT,
            bypassesDnd = channel.canBypassDnd(),
            importantConversation = Build.VERSION.SDK_INT >= 30 && channel.isImportantConversation,
            conversation = Build.VERSION.SDK_INT >= 30,
        )
    }

    @Suppress("MissingPermission") // canNotify() checked it.
    private fun post(peer: String, history: List<ChatMessage>, alertChannel: AlertChannel) {
        val channel = channelFor(peer, alertChannel)
        val peerParts = partsOf(peer)
        val them = peerParts.person
        pushShortcut(peer, them)
        val me = Person.Builder().setName(selfName() ?: "You").setKey("self").build()
        val style = NotificationCompat.MessagingStyle(me).setGroupConversation(false)
        for (m in history) style.addMessage(NotificationCompat.MessagingStyle.Message(lineOf(m), m.sentAtMillis, them))
        val latest = history.last()
        val builder = NotificationCompat.Builder(context, channel)
            .setSmallIcon(R.drawable.ic_notification)
            .setStyle(style)
            .setCategory(NotificationCompat.CATEGORY_MESSAGE)
            // When it arrived here: the sender's clock (each line's time) may be off.
            .setWhen(now())
            .setShortcutId(shortcutId(peer))
            .setLocusId(LocusIdCompat(shortcutId(peer)))
            .setAutoCancel(true)
            .setContentIntent(peerParts.open)
            .addAction(peerParts.reply)
            .addAction(peerParts.markRead)
        (latest.icon?.name ?: latest.pattern?.name)?.let { builder.addAction(feelAction(peer, latest.id, DisplayText.neutralise(it))) }
        manager.notify(peer, NOTIFICATION_ID, builder.build())
    }

    /** A notification line: the icon's or pattern's glyph and name, then the text (or "Sticker"), neutralised ([DisplayText]). */
    internal fun lineOf(m: ChatMessage): String = listOfNotNull(
        (m.icon?.name ?: m.pattern?.name)?.let { "〰 ${DisplayText.neutralise(it)}" },
        DisplayText.neutralise(m.text).takeIf { it.isNotBlank() } ?: m.sticker?.let { "Sticker: $it" },
    ).joinToString(" · ")

    /**
     * The person [peer] as notifications show them: the name, with a round letter avatar drawn no larger than Android
     * keeps it ([personIconPx]). `Notification.Builder.build` scales every larger sender icon of a MessagingStyle down,
     * at every build and for every line (AOSP `Notification.reduceImageSizes`; `NotificationTest`
     * `testBuild_ensureMessagingUserIsNotTooBig_resizesIcon`): at 216 px on a 144 px limit that was 7 of the
     * notification's 9 ms on the arrival path (docs/performance.md, "Arrival to touch").
     */
    internal fun personOf(peer: String): Person = Person.Builder()
        .setName(peer)
        .setKey(peer)
        .setIcon(IconCompat.createWithBitmap(avatarOf(peer, sizePx = minOf(AVATAR_PX, personIconPx), round = true)))
        .build()

    /**
     * The largest sender icon Android keeps in a notification, in pixels: the platform's
     * `notification_person_icon_max_size` (`_low_ram` on a low-RAM phone), as `Notification.reduceImageSizes` reads it;
     * 48 dp where the platform has no such dimension.
     */
    internal val personIconPx: Int by lazy {
        val system = android.content.res.Resources.getSystem()
        val lowRam = context.getSystemService(android.app.ActivityManager::class.java)?.isLowRamDevice == true
        val id = system.getIdentifier(if (lowRam) "notification_person_icon_max_size_low_ram" else "notification_person_icon_max_size", "dimen", "android")
        if (id != 0) system.getDimensionPixelSize(id) else (48 * context.resources.displayMetrics.density).toInt()
    }

    // The long-lived shortcut Android's Conversations section needs; pushed once per peer per process (it persists).
    private fun pushShortcut(peer: String, person: Person) {
        if (peer in shortcuts) return
        val shortcut = ShortcutInfoCompat.Builder(context, shortcutId(peer))
            .setShortLabel(peer)
            .setLongLived(true)
            .setPerson(person)
            .setLocusId(LocusIdCompat(shortcutId(peer)))
            // Launchers and the share sheet mask an adaptive icon to their own shape.
            .setIcon(IconCompat.createWithAdaptiveBitmap(avatarOf(peer)))
            .setIntent(openChatIntent(peer))
            .setCategories(setOf(SHORTCUT_CATEGORY))
            .build()
        if (ShortcutManagerCompat.pushDynamicShortcut(context, shortcut)) shortcuts += peer
    }

    private fun channelFor(peer: String, kind: AlertChannel): String {
        val id = channelId(peer, kind)
        if (Build.VERSION.SDK_INT >= 26 && id !in channels) {
            val system = context.getSystemService(NotificationManager::class.java)
            if (system.getNotificationChannel(id) == null) {
                system.createNotificationChannelGroup(NotificationChannelGroup(GROUP, "Chats"))
                system.createNotificationChannel(newChannel(id, peer, kind))
            }
            channels += id
        }
        return id
    }

    private fun openChatIntent(peer: String): Intent =
        Intent(context, context.chatHost.launchActivity).setAction(ACTION_OPEN_CHAT).putExtra(EXTRA_PEER, peer)
            .addFlags(Intent.FLAG_ACTIVITY_SINGLE_TOP)

    private fun openIntent(peer: String): PendingIntent = PendingIntent.getActivity(
        context, peer.hashCode(), openChatIntent(peer),
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
        /** An avatar's side: 108 dp at 2x, an adaptive icon's full size. */
        const val AVATAR_PX: Int = 216

        /** Peers whose notification parts (avatar, intents) are kept; the least recently notified is dropped beyond. */
        const val MAX_PEERS_KEPT: Int = 16
        const val GROUP: String = "chats"
        const val ACTION_OPEN_CHAT: String = "org.hapticon.app.OPEN_CHAT"
        const val ACTION_REPLY: String = "org.hapticon.app.REPLY"
        const val ACTION_FEEL: String = "org.hapticon.app.FEEL_AGAIN"
        const val ACTION_MARK_READ: String = "org.hapticon.app.MARK_READ"
        const val EXTRA_PEER: String = "peer"
        const val EXTRA_MESSAGE: String = "message"
        const val KEY_REPLY: String = "reply"
        /**
         * The category of the conversation shortcuts: the share target's in `res/xml/shortcuts.xml`, which makes them
         * sharing shortcuts (Direct Share offers each chat; AOSP `ShortcutService` matches a shortcut's categories
         * against the manifest's share targets).
         */
        const val SHORTCUT_CATEGORY: String = "org.hapticon.app.category.CONVERSATION"
        private const val MAX_LINES = 8
        private const val MAX_REMEMBERED = 500

        /** The id of [peer]'s conversation: its shortcut's and its [LocusIdCompat]'s (user names are valid ids as they are). */
        fun shortcutId(peer: String): String = "chat-$peer"

        /** The peer whose conversation shortcut [id] is ([shortcutId]), or null for another id. */
        fun peerOfShortcut(id: String?): String? = id?.takeIf { it.startsWith("chat-") }?.removePrefix("chat-")?.takeIf { it.isNotEmpty() }

        /** The id of [peer]'s channel of [kind]. */
        fun channelId(peer: String, kind: AlertChannel): String = when (kind) {
            AlertChannel.MESSAGES -> "chat-$peer"
            AlertChannel.ICONS -> "icons-$peer"
        }

        private fun newChannel(id: String, peer: String, kind: AlertChannel): NotificationChannel = when (kind) {
            // High importance: a heads-up, as a messenger's; the sound and vibration a messenger's too.
            AlertChannel.MESSAGES -> NotificationChannel(id, peer, NotificationManager.IMPORTANCE_HIGH).apply {
                group = GROUP
                description = "Messages from $peer whose haptic icon does not play on arrival"
                enableVibration(true)
                setSound(
                    Settings.System.DEFAULT_NOTIFICATION_URI,
                    AudioAttributes.Builder().setUsage(AudioAttributes.USAGE_NOTIFICATION).setContentType(AudioAttributes.CONTENT_TYPE_SONIFICATION).build(),
                )
            }
            // Heads-up, but silent and still: the icon that follows is the message's alert.
            AlertChannel.ICONS -> NotificationChannel(id, "$peer · haptic icons", NotificationManager.IMPORTANCE_HIGH).apply {
                group = GROUP
                description = "Messages from $peer whose haptic icon plays on arrival: the icon is the only vibration, so this channel neither rings nor vibrates"
                enableVibration(false)
                vibrationPattern = null
                setSound(null, null)
            }
        }

        /**
         * [peer]'s avatar: the first letter on a colour chosen by the name, as messengers show contacts without a photo.
         * Square for an adaptive icon (108 dp, the letter inside the 72 dp safe zone), which launchers mask to their shape;
         * [round] a disc on transparency, for the notification's person, which the shade shows as drawn.
         */
        internal fun avatarOf(peer: String, sizePx: Int = AVATAR_PX, round: Boolean = false): Bitmap {
            val bitmap = Bitmap.createBitmap(sizePx, sizePx, Bitmap.Config.ARGB_8888)
            val canvas = Canvas(bitmap)
            val background = AVATAR_COLORS[Math.floorMod(peer.hashCode(), AVATAR_COLORS.size)]
            if (round) {
                canvas.drawCircle(sizePx / 2f, sizePx / 2f, sizePx / 2f, Paint(Paint.ANTI_ALIAS_FLAG).apply { color = background })
            } else {
                canvas.drawColor(background)
            }
            val paint = Paint(Paint.ANTI_ALIAS_FLAG).apply {
                color = Color.WHITE
                textAlign = Paint.Align.CENTER
                textSize = sizePx * (if (round) 0.5f else 0.36f)
                isFakeBoldText = true
            }
            val letter = peer.first().uppercaseChar().toString()
            val baseline = sizePx / 2f - (paint.descent() + paint.ascent()) / 2f
            canvas.drawText(letter, sizePx / 2f, baseline, paint)
            return bitmap
        }

        // Material 800 tones: white text on each exceeds 4.5:1.
        private val AVATAR_COLORS = intArrayOf(
            0xFF1565C0.toInt(), 0xFF2E7D32.toInt(), 0xFFC62828.toInt(), 0xFF6A1B9A.toInt(),
            0xFF00695C.toInt(), 0xFFAD1457.toInt(), 0xFF4527A0.toInt(), 0xFF5D4037.toInt(),
        )
    }
}

/**
 * The notification's actions: "Mark as read" marks the conversation read and sends the read receipts
 * (kept for later while offline); "Reply" stores the typed text as an own message (the outbox sends it,
 * so a reply typed offline is not lost) and "Feel again" plays the message's icon or pattern through the normal
 * player as the peer's communication ([messageUsage]) and sends the felt receipt once Android played it. Both run in the background without opening the app.
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
                        // From the shade the app is in the background: only an allowed usage plays, and felt only if it did.
                        val playback = chat.player.playMessageOffMain(message.icon, message.pattern, messageUsage(message.outgoing))
                        if (!message.outgoing && playback is Playback.Playing) chat.sync.felt(peer, id)
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
