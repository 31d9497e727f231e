package org.hapticon.core.platform

/**
 * Why a vibration is made, as Android's `VibrationAttributes` names it. [platformValue] is the platform constant
 * (`VibrationAttributes.USAGE_*`: the usage class in the low nibble — 1 alarm, 2 feedback, 3 media; AOSP
 * `core/java/android/os/VibrationAttributes.java`). Android decides by the usage whether a vibration plays at all
 * ([AndroidVibrationRules]) and how strong it is (the user's intensity setting for that usage).
 *
 * The app gives every vibration the usage it is (docs/messaging.md, "Android's rules for vibrating"):
 * [COMMUNICATION_REQUEST] for a received icon or pattern however it is played, [TOUCH] for a press on the
 * user's own icons in the open app, [PHYSICAL_EMULATION] for what a sensor renders under the user's finger.
 */
public enum class VibrationUsage(public val platformValue: Int) {
    UNKNOWN(0x00),
    ALARM(0x11),
    RINGTONE(0x21),
    NOTIFICATION(0x31),
    COMMUNICATION_REQUEST(0x41),
    TOUCH(0x12),
    PHYSICAL_EMULATION(0x22),
    HARDWARE_FEEDBACK(0x32),
    ACCESSIBILITY(0x42),
    MEDIA(0x13),
}

/**
 * The `android.media.AudioAttributes` usages the app hands Android where a vibration travels under audio attributes:
 * `Vibrator.vibrate(VibrationEffect, AudioAttributes)` below API 33 (there is no `VibrationAttributes` overload before
 * it) and the haptic channel of audio-coupled playback. [platformValue] is `AudioAttributes.USAGE_*`, which Media3's
 * `C.USAGE_*` equal.
 */
public enum class AudioUsage(public val platformValue: Int) {
    MEDIA(1),
    NOTIFICATION_COMMUNICATION_INSTANT(8),
    ASSISTANCE_SONIFICATION(13),
    ;

    /**
     * The vibration usage Android derives from this audio usage and judges the vibration by:
     * `VibrationAttributes.Builder(AudioAttributes)` maps the `USAGE_NOTIFICATION_COMMUNICATION_*` usages to
     * NOTIFICATION, ASSISTANCE_SONIFICATION to TOUCH and MEDIA to MEDIA. (From API 33 `AudioAttributes.Builder.build()`
     * already turns the deprecated `USAGE_NOTIFICATION_COMMUNICATION_*` into `USAGE_NOTIFICATION`: the same vibration usage.)
     */
    public val vibrationUsage: VibrationUsage
        get() = when (this) {
            MEDIA -> VibrationUsage.MEDIA
            NOTIFICATION_COMMUNICATION_INSTANT -> VibrationUsage.NOTIFICATION
            ASSISTANCE_SONIFICATION -> VibrationUsage.TOUCH
        }
}

/** How a vibration reaches the actuator: the vibrator service, or the haptic channel of an audio stream. */
public enum class VibrationRoute { VIBRATOR, AUDIO_HAPTIC_CHANNEL }

/**
 * What Android knows about the phone when it judges a vibration. Properties are read when [AndroidVibrationRules.verdict]
 * needs them, so an implementation may read each from the system lazily (a sensor loop asks at 20 Hz and needs only
 * [hasVibrator]).
 */
public interface PhoneState {
    /** `Vibrator.hasVibrator()`. */
    public val hasVibrator: Boolean

    /** This process's `ActivityManager.RunningAppProcessInfo.importance` (`IMPORTANCE_*`: smaller is more important). */
    public val processImportance: Int

    /** `PowerManager.isInteractive()`: the screen is on. */
    public val interactive: Boolean

    /** `PowerManager.isPowerSaveMode()`: Battery Saver is on. */
    public val batterySaver: Boolean

    /** `Settings.System.HAPTIC_FEEDBACK_ENABLED` is not 0: the user left touch feedback on. */
    public val touchFeedbackEnabled: Boolean

    /** `AudioManager.getRingerMode()` is `RINGER_MODE_SILENT`. */
    public val ringerSilent: Boolean
}

/** Android's answer to one vibration: it [plays], or it is ignored for the reason given. */
public enum class VibrationVerdict(public val plays: Boolean, public val explanation: String) {
    PLAYS(true, "plays"),
    NO_VIBRATOR(false, "this phone has no vibrator"),
    BACKGROUND(false, "Android ignores this kind of vibration from an app in the background"),
    BATTERY_SAVER(false, "Battery Saver is on: Android plays no vibration of this kind"),
    TOUCH_FEEDBACK_OFF(false, "touch feedback is off in Android's vibration settings"),
    RINGER_SILENT(false, "the phone is on silent"),
}

/**
 * A model of the checks Android's vibrator service runs on every vibration before it reaches the actuator, in its
 * order (AOSP `services/core/java/com/android/server/vibrator/VibrationSettings.java`, `shouldIgnoreVibration`):
 *
 * 1. **Background.** A vibration from a process that is not in the foreground is ignored unless its usage is in
 *    `BACKGROUND_PROCESS_USAGE_ALLOWLIST`: ringtone, alarm, notification, communication request, hardware feedback and
 *    physical emulation ([BACKGROUND_ALLOWED]). Foreground is `VibrationUidObserver.isUidForeground`: process state ≤
 *    `PROCESS_STATE_IMPORTANT_FOREGROUND` ([isForeground]).
 * 2. **Battery Saver.** Only `BATTERY_SAVER_USAGE_ALLOWLIST` plays: ringtone, alarm, communication request, physical
 *    emulation and hardware feedback ([BATTERY_SAVER_ALLOWED]; notification is not in it).
 * 3. **User settings.** A usage whose intensity the user turned off is ignored; of those settings the app can read only
 *    touch feedback (`HAPTIC_FEEDBACK_ENABLED` off turns TOUCH off). The per-usage intensity settings are not public,
 *    so a usage the user switched off in Settings › Vibration is not caught here (the device check sees it).
 * 4. **Ringer mode.** `shouldVibrateForRingerModeLocked`: only ringtone and notification vibrations are silenced in
 *    silent mode; a communication request is not, which is why the app applies the ringer itself before it plays a
 *    received icon (messaging's `ArrivalAlerts`).
 *
 * Android 12's `VibrationSettings.shouldVibrateForUid` (foreground or usage class ALARM) and `shouldVibrateForPowerMode`
 * (ringtone, alarm, communication request) give the same answers for the usages the app uses. Before API 33 the app's
 * vibrations carry `AudioAttributes` ([effectiveUsage]), which Android 8–11 judge by the same lists under their audio
 * names (a `USAGE_NOTIFICATION_COMMUNICATION_*` audio usage counts as a notification, `VibratorService.isNotification`).
 */
public object AndroidVibrationRules {
    /** `ActivityManager.RunningAppProcessInfo.IMPORTANCE_FOREGROUND`: process state TOP (or BOUND_TOP). */
    public const val IMPORTANCE_FOREGROUND: Int = 100

    /** `IMPORTANCE_FOREGROUND_SERVICE`: the process runs a foreground service ("Stay reachable"). */
    public const val IMPORTANCE_FOREGROUND_SERVICE: Int = 125

    /** `IMPORTANCE_VISIBLE`: process state IMPORTANT_FOREGROUND, the last state Android's vibrator counts as foreground. */
    public const val IMPORTANCE_VISIBLE: Int = 200

    /** `IMPORTANCE_TOP_SLEEPING`: the top activity's process while the screen is off. */
    public const val IMPORTANCE_TOP_SLEEPING: Int = 325

    /** `IMPORTANCE_CACHED`: a process with nothing running (the app swiped away, a receiver finished). */
    public const val IMPORTANCE_CACHED: Int = 400

    /** `VibrationSettings.BACKGROUND_PROCESS_USAGE_ALLOWLIST`. */
    public val BACKGROUND_ALLOWED: Set<VibrationUsage> = setOf(
        VibrationUsage.RINGTONE, VibrationUsage.ALARM, VibrationUsage.NOTIFICATION,
        VibrationUsage.COMMUNICATION_REQUEST, VibrationUsage.HARDWARE_FEEDBACK, VibrationUsage.PHYSICAL_EMULATION,
    )

    /** `VibrationSettings.BATTERY_SAVER_USAGE_ALLOWLIST`. */
    public val BATTERY_SAVER_ALLOWED: Set<VibrationUsage> = setOf(
        VibrationUsage.RINGTONE, VibrationUsage.ALARM, VibrationUsage.COMMUNICATION_REQUEST,
        VibrationUsage.PHYSICAL_EMULATION, VibrationUsage.HARDWARE_FEEDBACK,
    )

    /**
     * Whether Android's vibrator counts this process as foreground. `RunningAppProcessInfo.procStateToImportance` maps
     * process states ≤ IMPORTANT_FOREGROUND to the importances FOREGROUND, FOREGROUND_SERVICE and VISIBLE, so those are
     * foreground. An importance of FOREGROUND read while the screen is off is taken as TOP_SLEEPING, which it becomes
     * once the screen is off: the top activity of a sleeping phone is background to the vibrator. A foreground service
     * keeps its importance with the screen off.
     */
    public fun isForeground(importance: Int, interactive: Boolean): Boolean = when {
        importance > IMPORTANCE_VISIBLE -> false
        importance <= IMPORTANCE_FOREGROUND -> interactive
        else -> true
    }

    /** The audio usage that carries [usage] where Android takes `AudioAttributes` ([AudioUsage]). */
    public fun audioUsageFor(usage: VibrationUsage): AudioUsage = when (usage) {
        // An instant message: allowed from the background as a notification on every Android version.
        VibrationUsage.COMMUNICATION_REQUEST, VibrationUsage.NOTIFICATION -> AudioUsage.NOTIFICATION_COMMUNICATION_INSTANT
        VibrationUsage.MEDIA -> AudioUsage.MEDIA
        // No audio usage maps to physical emulation; sonification (touch) is the nearest.
        else -> AudioUsage.ASSISTANCE_SONIFICATION
    }

    /**
     * The usage Android judges a vibration of [usage] by: [usage] itself on the vibrator from API 33 (the
     * `VibrationAttributes` overload), else the one it derives from the audio attributes that carry it ([audioUsageFor]).
     */
    public fun effectiveUsage(usage: VibrationUsage, route: VibrationRoute, apiLevel: Int): VibrationUsage =
        if (route == VibrationRoute.VIBRATOR && apiLevel >= 33) usage else audioUsageFor(usage).vibrationUsage

    /** What Android does with a vibration it judges by [usage] ([effectiveUsage]) on a phone in [state]. */
    public fun verdict(usage: VibrationUsage, state: PhoneState): VibrationVerdict = when {
        !state.hasVibrator -> VibrationVerdict.NO_VIBRATOR
        usage !in BACKGROUND_ALLOWED && !isForeground(state.processImportance, state.interactive) -> VibrationVerdict.BACKGROUND
        usage !in BATTERY_SAVER_ALLOWED && state.batterySaver -> VibrationVerdict.BATTERY_SAVER
        usage == VibrationUsage.TOUCH && !state.touchFeedbackEnabled -> VibrationVerdict.TOUCH_FEEDBACK_OFF
        (usage == VibrationUsage.RINGTONE || usage == VibrationUsage.NOTIFICATION) && state.ringerSilent -> VibrationVerdict.RINGER_SILENT
        else -> VibrationVerdict.PLAYS
    }
}
