package org.hapticon.core.platform

import org.hapticon.core.platform.AndroidVibrationRules.IMPORTANCE_CACHED
import org.hapticon.core.platform.AndroidVibrationRules.IMPORTANCE_FOREGROUND
import org.hapticon.core.platform.AndroidVibrationRules.IMPORTANCE_FOREGROUND_SERVICE
import org.hapticon.core.platform.AndroidVibrationRules.IMPORTANCE_TOP_SLEEPING
import org.hapticon.core.platform.AndroidVibrationRules.IMPORTANCE_VISIBLE
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class AndroidVibrationRulesTest {
    private data class Phone(
        override val hasVibrator: Boolean = true,
        override val processImportance: Int = IMPORTANCE_FOREGROUND,
        override val interactive: Boolean = true,
        override val batterySaver: Boolean = false,
        override val touchFeedbackEnabled: Boolean = true,
        override val ringerSilent: Boolean = false,
    ) : PhoneState

    private val open = Phone()
    private val swipedAway = Phone(processImportance = IMPORTANCE_CACHED)

    @Test
    fun platformValues_areVibrationAttributesConstants() {
        // VibrationAttributes: usage | usage class (1 alarm, 2 feedback, 3 media).
        assertEquals(65, VibrationUsage.COMMUNICATION_REQUEST.platformValue)
        assertEquals(18, VibrationUsage.TOUCH.platformValue)
        assertEquals(34, VibrationUsage.PHYSICAL_EMULATION.platformValue)
        assertEquals(49, VibrationUsage.NOTIFICATION.platformValue)
        assertEquals(listOf(1, 8, 13), AudioUsage.entries.map { it.platformValue })
    }

    @Test
    fun foreground_isImportanceUpToVisible_andTopOnlyWithTheScreenOn() {
        assertTrue(AndroidVibrationRules.isForeground(IMPORTANCE_FOREGROUND, interactive = true))
        // The open activity of a phone whose screen went off is TOP_SLEEPING: background.
        assertFalse(AndroidVibrationRules.isForeground(IMPORTANCE_FOREGROUND, interactive = false))
        assertFalse(AndroidVibrationRules.isForeground(IMPORTANCE_TOP_SLEEPING, interactive = false))
        // A foreground service ("Stay reachable") stays foreground with the screen off.
        assertTrue(AndroidVibrationRules.isForeground(IMPORTANCE_FOREGROUND_SERVICE, interactive = false))
        assertTrue(AndroidVibrationRules.isForeground(IMPORTANCE_VISIBLE, interactive = false))
        assertFalse(AndroidVibrationRules.isForeground(IMPORTANCE_VISIBLE + 1, interactive = true))
        assertFalse(AndroidVibrationRules.isForeground(IMPORTANCE_CACHED, interactive = true))
    }

    @Test
    fun background_onlyTheAllowlistedUsagesPlay() {
        val played = VibrationUsage.entries.filter { AndroidVibrationRules.verdict(it, swipedAway).plays }
        assertEquals(
            listOf(
                VibrationUsage.ALARM, VibrationUsage.RINGTONE, VibrationUsage.NOTIFICATION, VibrationUsage.COMMUNICATION_REQUEST,
                VibrationUsage.PHYSICAL_EMULATION, VibrationUsage.HARDWARE_FEEDBACK,
            ),
            played,
        )
        assertEquals(VibrationVerdict.BACKGROUND, AndroidVibrationRules.verdict(VibrationUsage.TOUCH, swipedAway))
        assertEquals(VibrationVerdict.BACKGROUND, AndroidVibrationRules.verdict(VibrationUsage.TOUCH, open.copy(interactive = false)))
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.TOUCH, open))
    }

    @Test
    fun batterySaver_dropsNotificationAndTouchButNotCommunicationRequest() {
        val saving = open.copy(batterySaver = true)
        assertEquals(VibrationVerdict.BATTERY_SAVER, AndroidVibrationRules.verdict(VibrationUsage.NOTIFICATION, saving))
        assertEquals(VibrationVerdict.BATTERY_SAVER, AndroidVibrationRules.verdict(VibrationUsage.TOUCH, saving))
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.COMMUNICATION_REQUEST, saving))
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.PHYSICAL_EMULATION, saving))
    }

    @Test
    fun silentRinger_silencesNotificationOnly_touchFeedbackOffSilencesTouchOnly() {
        val silent = open.copy(ringerSilent = true)
        assertEquals(VibrationVerdict.RINGER_SILENT, AndroidVibrationRules.verdict(VibrationUsage.NOTIFICATION, silent))
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.COMMUNICATION_REQUEST, silent))
        val noTouch = open.copy(touchFeedbackEnabled = false)
        assertEquals(VibrationVerdict.TOUCH_FEEDBACK_OFF, AndroidVibrationRules.verdict(VibrationUsage.TOUCH, noTouch))
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.PHYSICAL_EMULATION, noTouch))
        assertEquals(VibrationVerdict.NO_VIBRATOR, AndroidVibrationRules.verdict(VibrationUsage.COMMUNICATION_REQUEST, open.copy(hasVibrator = false)))
    }

    @Test
    fun effectiveUsage_audioAttributesBelowApi33AndOnTheHapticChannel() {
        val received = VibrationUsage.COMMUNICATION_REQUEST
        assertEquals(received, AndroidVibrationRules.effectiveUsage(received, VibrationRoute.VIBRATOR, 33))
        // USAGE_NOTIFICATION_COMMUNICATION_INSTANT, which VibrationAttributes.Builder(AudioAttributes) makes NOTIFICATION.
        assertEquals(AudioUsage.NOTIFICATION_COMMUNICATION_INSTANT, AndroidVibrationRules.audioUsageFor(received))
        assertEquals(VibrationUsage.NOTIFICATION, AndroidVibrationRules.effectiveUsage(received, VibrationRoute.VIBRATOR, 32))
        assertEquals(VibrationUsage.NOTIFICATION, AndroidVibrationRules.effectiveUsage(received, VibrationRoute.AUDIO_HAPTIC_CHANNEL, 36))
        assertEquals(VibrationUsage.TOUCH, AndroidVibrationRules.effectiveUsage(VibrationUsage.PHYSICAL_EMULATION, VibrationRoute.VIBRATOR, 26))
        assertEquals(VibrationUsage.PHYSICAL_EMULATION, AndroidVibrationRules.effectiveUsage(VibrationUsage.PHYSICAL_EMULATION, VibrationRoute.VIBRATOR, 35))
        // So a received icon still plays from the background below API 33, but not in Battery Saver there.
        val old = AndroidVibrationRules.effectiveUsage(received, VibrationRoute.VIBRATOR, 30)
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(old, swipedAway))
        assertEquals(VibrationVerdict.BATTERY_SAVER, AndroidVibrationRules.verdict(old, swipedAway.copy(batterySaver = true)))
    }

    @Test
    fun verdict_readsOnlyWhatItsUsageNeeds() {
        // A sensor loop asks 20 times a second: physical emulation needs only the vibrator, no binder call for the rest.
        val reads = mutableListOf<String>()
        val state = object : PhoneState {
            override val hasVibrator: Boolean get() = true.also { reads += "vibrator" }
            override val processImportance: Int get() = IMPORTANCE_CACHED.also { reads += "importance" }
            override val interactive: Boolean get() = false.also { reads += "interactive" }
            override val batterySaver: Boolean get() = true.also { reads += "batterySaver" }
            override val touchFeedbackEnabled: Boolean get() = true.also { reads += "touch" }
            override val ringerSilent: Boolean get() = true.also { reads += "ringer" }
        }
        assertEquals(VibrationVerdict.PLAYS, AndroidVibrationRules.verdict(VibrationUsage.PHYSICAL_EMULATION, state))
        assertEquals(listOf("vibrator"), reads)
    }
}
