package org.hapticon.messaging

import org.hapticon.core.platform.VibrationVerdict

/** Android's ringer mode (`AudioManager.RINGER_MODE_*`). */
public enum class RingerMode { SILENT, VIBRATE, NORMAL }

/**
 * What the user set for a conversation's notification channel (`NotificationChannel`, or the conversation's own channel
 * Android derives from it once the user changes the conversation's settings).
 *
 * @property alerting importance at least `IMPORTANCE_DEFAULT`: the user has not made the conversation silent or blocked it.
 * @property bypassesDnd `canBypassDnd()`: the user let this channel override Do Not Disturb.
 * @property importantConversation `isImportantConversation()`: the user marked the conversation as priority.
 * @property conversation the notification is a conversation (API 30+, with a long-lived shortcut), so the conversation
 *   rules of Do Not Disturb apply to it.
 */
public data class ChannelSettings(
    val alerting: Boolean,
    val bypassesDnd: Boolean = false,
    val importantConversation: Boolean = false,
    val conversation: Boolean = false,
)

/**
 * Do Not Disturb as Android applies it to a message notification (AOSP
 * `services/core/java/com/android/server/notification/ZenModeFiltering.java`, `shouldIntercept`):
 * - [Filter.ALL] (zen off) lets everything through; [Filter.NONE] nothing; [Filter.ALARMS] only alarms.
 * - [Filter.PRIORITY]: a channel that may bypass Do Not Disturb gets through (`PriorityExtractor` gives it package
 *   priority MAX); a conversation gets through when the policy allows conversations from anyone, or from priority
 *   conversations and this one is; a message (`CATEGORY_MESSAGE`) gets through when the policy allows messages from
 *   anyone. Messages allowed from contacts or starred contacts only do not match: the app's `Person` carries no
 *   contacts URI, so Android finds no contact affinity. Anything else is intercepted.
 *
 * @property messages who may send messages that get through (`Policy.priorityMessageSenders`); null when messages are
 *   not a priority category.
 * @property conversations which conversations get through (`Policy.priorityConversationSenders`, API 30+); null when none.
 */
public data class DoNotDisturb(
    val filter: Filter,
    val messages: Senders? = null,
    val conversations: ConversationSenders? = null,
) {
    /** `NotificationManager.getCurrentInterruptionFilter()`. */
    public enum class Filter { ALL, PRIORITY, NONE, ALARMS }

    /** `NotificationManager.Policy.PRIORITY_SENDERS_*`. */
    public enum class Senders { ANYONE, CONTACTS, STARRED }

    /** `NotificationManager.Policy.CONVERSATION_SENDERS_ANYONE` and `_IMPORTANT`. */
    public enum class ConversationSenders { ANYONE, IMPORTANT }

    /** Whether a message notification on [channel] gets through. */
    public fun letsThrough(channel: ChannelSettings): Boolean = when (filter) {
        Filter.ALL -> true
        Filter.NONE, Filter.ALARMS -> false
        Filter.PRIORITY -> channel.bypassesDnd ||
            (channel.conversation && (conversations == ConversationSenders.ANYONE ||
                (conversations == ConversationSenders.IMPORTANT && channel.importantConversation))) ||
            messages == Senders.ANYONE
    }

    public companion object {
        /** Do Not Disturb is off. */
        public val OFF: DoNotDisturb = DoNotDisturb(Filter.ALL)
    }
}

/** What the user and the phone set that bears on alerting for one arriving message: ringer, Do Not Disturb, the icon channel. */
public data class ArrivalConditions(
    val ringer: RingerMode,
    val doNotDisturb: DoNotDisturb,
    val iconChannel: ChannelSettings,
) {
    public companion object {
        /** A phone that rings, without Do Not Disturb, the conversation not silenced. */
        public val UNRESTRICTED: ArrivalConditions = ArrivalConditions(RingerMode.NORMAL, DoNotDisturb.OFF, ChannelSettings(alerting = true))
    }
}

/** Which of a conversation's two channels a message notification is posted on. */
public enum class AlertChannel {
    /** The conversation's message channel: Android rings and vibrates as the user set it, under its own ringer and DND. */
    MESSAGES,

    /** The conversation's icon channel: neither rings nor vibrates; the icon that follows is the alert. */
    ICONS,
}

/** How an arriving message alerts: the channel its notification goes to, and whether its icon plays after it. */
public enum class ArrivalAlert(public val channel: AlertChannel, public val playsIcon: Boolean) {
    /** Posted on the icon channel, then the icon plays: the message's only vibration. */
    ICON(AlertChannel.ICONS, true),

    /** Posted on the icon channel without playing: the user silenced the conversation, or its sender is over the rate limit. */
    QUIET(AlertChannel.ICONS, false),

    /** Posted on the message channel, no icon: Android alerts (or, silent or in Do Not Disturb, does not). */
    NOTIFICATION(AlertChannel.MESSAGES, false),
}

/** An [ArrivalAlert] and why, for the log. */
public data class ArrivalPlan(val alert: ArrivalAlert, val reason: String)

/**
 * Decides how an arriving message alerts, as a messenger whose message vibration is the haptic icon: the icon plays only
 * where a messenger's own vibration would, so a phone on silent or in Do Not Disturb gets neither the icon nor (Android's
 * doing) the ring. Android does not apply these to the icon itself: the vibrator silences only ringtone and notification
 * usages on silent and never looks at Do Not Disturb (`VibrationSettings.shouldVibrateForRingerModeLocked`), and a
 * received icon plays as a communication request.
 */
public object ArrivalAlerts {
    /**
     * The plan for a message that [carriesHaptic] (an icon or a pattern), with the user's [autoPlay] setting, under
     * [conditions], when Android's vibrator would answer [vibration] to a received icon now (the app's model of
     * `VibrationSettings`). [rateLimit] is asked last, only when the icon would otherwise play, so that a refusal for
     * another reason costs the sender nothing ([VibrationRateLimiter.tryAcquire]).
     */
    public fun plan(
        carriesHaptic: Boolean,
        autoPlay: Boolean,
        conditions: ArrivalConditions,
        vibration: VibrationVerdict,
        rateLimit: () -> VibrationDecision,
    ): ArrivalPlan {
        if (!carriesHaptic) return ArrivalPlan(ArrivalAlert.NOTIFICATION, "no icon")
        if (!autoPlay) return ArrivalPlan(ArrivalAlert.NOTIFICATION, "auto-play is off")
        if (conditions.ringer == RingerMode.SILENT) return ArrivalPlan(ArrivalAlert.NOTIFICATION, "the phone is on silent")
        if (!conditions.doNotDisturb.letsThrough(conditions.iconChannel)) return ArrivalPlan(ArrivalAlert.NOTIFICATION, "Do Not Disturb")
        if (!conditions.iconChannel.alerting) return ArrivalPlan(ArrivalAlert.QUIET, "the conversation is silenced")
        if (!vibration.plays) return ArrivalPlan(ArrivalAlert.NOTIFICATION, vibration.explanation)
        val limit = rateLimit()
        if (limit != VibrationDecision.VIBRATE) return ArrivalPlan(ArrivalAlert.QUIET, "rate limit: $limit")
        return ArrivalPlan(ArrivalAlert.ICON, "plays")
    }
}
