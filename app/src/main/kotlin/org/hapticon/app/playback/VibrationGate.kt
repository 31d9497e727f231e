package org.hapticon.app.playback

import android.content.Context
import android.os.Vibrator
import org.hapticon.core.platform.AndroidVibrationRules
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict

/** What Android would do now with a vibration it judges by a usage ([AndroidVibrationRules.effectiveUsage]). */
fun interface VibrationGate {
    fun verdict(effectiveUsage: VibrationUsage): VibrationVerdict
}

/**
 * [VibrationGate] on this phone: [AndroidVibrationRules] over the state Android's vibrator service reads, each value
 * read from the system only when the rule for the usage needs it ([AndroidPhoneState]).
 */
class AndroidVibrationGate(private val context: Context, private val vibrator: Vibrator) : VibrationGate {
    override fun verdict(effectiveUsage: VibrationUsage): VibrationVerdict =
        AndroidVibrationRules.verdict(effectiveUsage, AndroidPhoneState(context.applicationContext, vibrator))
}
