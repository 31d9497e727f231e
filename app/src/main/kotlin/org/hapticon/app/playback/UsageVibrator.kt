package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import android.os.VibrationAttributes
import android.os.VibrationEffect
import android.os.Vibrator
import android.util.Log
import androidx.annotation.RequiresApi
import org.hapticon.core.platform.AndroidVibrationRules
import org.hapticon.core.platform.VibrationRoute
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict

/**
 * The phone's [vibrator] where every vibration carries the usage it is: `VibrationAttributes` from API 33
 * (`Vibrator.vibrate(VibrationEffect, VibrationAttributes)`), the `AudioAttributes` of
 * [AndroidVibrationRules.audioUsageFor] below it. Before each vibration [gate] is asked what Android will do with it;
 * one Android would ignore is not sent, and the caller learns why ([vibrate] returns the verdict), so nothing is
 * reported as felt that Android dropped. [apiLevel] is the platform's, or a lower one to take the pre-33 path.
 */
class UsageVibrator(
    val vibrator: Vibrator,
    private val gate: VibrationGate,
    private val apiLevel: Int = Build.VERSION.SDK_INT,
) {
    /** What Android would do now with a vibration of [usage] sent by [route]. */
    fun verdict(usage: VibrationUsage, route: VibrationRoute = VibrationRoute.VIBRATOR): VibrationVerdict =
        gate.verdict(AndroidVibrationRules.effectiveUsage(usage, route, apiLevel))

    /** Plays [effect] as [usage] when Android will ([verdict]); returns the verdict. */
    fun vibrate(effect: VibrationEffect, usage: VibrationUsage): VibrationVerdict {
        val verdict = verdict(usage)
        if (!verdict.plays) {
            Log.i(TAG, "not vibrating ($usage): ${verdict.explanation}")
            return verdict
        }
        if (apiLevel >= 33 && Build.VERSION.SDK_INT >= 33) {
            Api33.vibrate(vibrator, effect, usage)
        } else {
            @Suppress("DEPRECATION") // the only way to carry a usage below API 33
            vibrator.vibrate(effect, audioAttributesOf(usage))
        }
        return verdict
    }

    fun cancel() = vibrator.cancel()

    fun hasVibrator(): Boolean = vibrator.hasVibrator()

    fun hasAmplitudeControl(): Boolean = vibrator.hasAmplitudeControl()

    @RequiresApi(33)
    private object Api33 {
        fun vibrate(vibrator: Vibrator, effect: VibrationEffect, usage: VibrationUsage) =
            vibrator.vibrate(effect, VibrationAttributes.createForUsage(usage.platformValue))
    }

    companion object {
        private const val TAG = "UsageVibrator"

        /** The phone's default vibrator, judged by this phone's [AndroidVibrationGate]. */
        fun create(context: Context): UsageVibrator {
            val vibrator = defaultVibrator(context)
            return UsageVibrator(vibrator, AndroidVibrationGate(context, vibrator))
        }
    }
}

/** The `AudioAttributes` that carry [usage] where Android takes audio attributes (below API 33). */
fun audioAttributesOf(usage: VibrationUsage): android.media.AudioAttributes = android.media.AudioAttributes.Builder()
    .setUsage(AndroidVibrationRules.audioUsageFor(usage).platformValue)
    .setContentType(android.media.AudioAttributes.CONTENT_TYPE_SONIFICATION)
    .build()
