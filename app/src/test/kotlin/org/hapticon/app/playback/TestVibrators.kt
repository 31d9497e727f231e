package org.hapticon.app.playback

import android.app.ActivityManager
import android.content.Context
import android.os.Build
import android.os.PowerManager
import android.os.Process
import android.os.VibrationAttributes
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.platform.VibrationUsage
import org.robolectric.Shadows.shadowOf
import org.robolectric.shadows.ShadowVibrator

/**
 * [vibrator] as the app uses it ([UsageVibrator]): every vibration with its usage, judged by [AndroidVibrationGate] on
 * this Robolectric phone's own state (its process importance, screen, Battery Saver, settings), which a test sets through
 * the shadows ([setProcessImportance], `ShadowPowerManager`, `ShadowAudioManager`).
 */
fun usageVibrator(
    vibrator: Vibrator = ApplicationProvider.getApplicationContext<Context>().getSystemService(Vibrator::class.java),
    apiLevel: Int = Build.VERSION.SDK_INT,
): UsageVibrator = UsageVibrator(vibrator, AndroidVibrationGate(ApplicationProvider.getApplicationContext(), vibrator), apiLevel)

/** The usage Android recorded for the last vibration ([ShadowVibrator] keeps its `VibrationAttributes`), null before any. */
fun lastUsage(vibrator: Vibrator): VibrationUsage? {
    val attributes = shadowOf(vibrator).vibrationAttributesFromLastVibration as VibrationAttributes? ?: return null
    return VibrationUsage.entries.single { it.platformValue == attributes.usage }
}

/** The `AudioAttributes` usage the last vibration was sent with (the pre-33 path), as Android kept it in its `VibrationAttributes`. */
fun lastAudioUsage(vibrator: Vibrator): Int? {
    val shadow = shadowOf(vibrator)
    shadow.audioAttributesFromLastVibration?.let { return it.usage }
    // From API 33 Vibrator.vibrate(VibrationEffect, AudioAttributes) converts to VibrationAttributes, which keep the audio usage.
    val attributes = shadow.vibrationAttributesFromLastVibration as VibrationAttributes? ?: return null
    return VibrationAttributes::class.java.getMethod("getAudioUsage").invoke(attributes) as Int
}

/**
 * Makes this process report [importance] (`ActivityManager.getMyMemoryState`, which Robolectric answers from its process
 * list): [ActivityManager.RunningAppProcessInfo.IMPORTANCE_CACHED] is the app swiped away, IMPORTANCE_FOREGROUND the
 * open app.
 */
fun setProcessImportance(importance: Int) {
    val context = ApplicationProvider.getApplicationContext<Context>()
    val me = ActivityManager.RunningAppProcessInfo(context.packageName, Process.myPid(), arrayOf(context.packageName)).apply {
        this.importance = importance
    }
    shadowOf(context.getSystemService(ActivityManager::class.java)).setProcesses(listOf(me))
}

/** Turns the (Robolectric) screen on or off (`PowerManager.isInteractive`). */
fun setScreenOn(on: Boolean) {
    val context = ApplicationProvider.getApplicationContext<Context>()
    shadowOf(context.getSystemService(PowerManager::class.java)).setIsInteractive(on)
}
