package org.hapticon.app.playback

import android.app.ActivityManager
import android.content.Context
import android.media.AudioManager
import android.os.PowerManager
import android.os.Vibrator
import android.provider.Settings
import org.hapticon.core.platform.PhoneState

/** [PhoneState] read from Android's services when asked. */
class AndroidPhoneState(private val context: Context, private val vibrator: Vibrator) : PhoneState {
    override val hasVibrator: Boolean get() = vibrator.hasVibrator()

    override val processImportance: Int
        get() = ActivityManager.RunningAppProcessInfo().also(ActivityManager::getMyMemoryState).importance

    override val interactive: Boolean get() = context.getSystemService(PowerManager::class.java)?.isInteractive ?: true

    override val batterySaver: Boolean get() = context.getSystemService(PowerManager::class.java)?.isPowerSaveMode ?: false

    override val touchFeedbackEnabled: Boolean
        get() = Settings.System.getInt(context.contentResolver, Settings.System.HAPTIC_FEEDBACK_ENABLED, 1) != 0

    override val ringerSilent: Boolean
        get() = context.getSystemService(AudioManager::class.java)?.ringerMode == AudioManager.RINGER_MODE_SILENT
}
