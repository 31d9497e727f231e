package org.hapticon.app.playback

import android.app.ActivityManager.RunningAppProcessInfo
import android.content.Context
import android.os.PowerManager
import android.os.VibrationEffect
import android.os.Vibrator
import android.provider.Settings
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.HapticIcon
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import java.io.File

/**
 * Every vibration carries its usage, and one Android would ignore is not sent: the attributes Robolectric's vibrator
 * records ([lastUsage], [lastAudioUsage]) and the phone state Android's vibrator service reads, set through the shadows.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class UsageVibratorTest {
    @get:Rule val folder = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator: Vibrator = context.getSystemService(Vibrator::class.java)
    private val effect = VibrationEffect.createWaveform(longArrayOf(20, 30), intArrayOf(255, 0), -1)

    @Before
    fun setUp() {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        setProcessImportance(RunningAppProcessInfo.IMPORTANCE_FOREGROUND)
    }

    @Test
    fun api33AndLater_theUsageTravelsAsVibrationAttributes() {
        for (usage in listOf(VibrationUsage.TOUCH, VibrationUsage.COMMUNICATION_REQUEST, VibrationUsage.PHYSICAL_EMULATION)) {
            assertEquals(VibrationVerdict.PLAYS, usageVibrator(vibrator).vibrate(effect, usage))
            assertEquals(usage, lastUsage(vibrator))
        }
    }

    @Test
    fun belowApi33_theUsageTravelsAsAudioAttributes() {
        // The pre-33 call (Vibrator.vibrate(VibrationEffect, AudioAttributes)) on this API 35 runtime, which converts the
        // audio attributes exactly as VibrationAttributes.Builder(AudioAttributes) does on a phone.
        val legacy = usageVibrator(vibrator, apiLevel = 32)
        legacy.vibrate(effect, VibrationUsage.COMMUNICATION_REQUEST)
        // The app asks for USAGE_NOTIFICATION_COMMUNICATION_INSTANT; from API 33 AudioAttributes.Builder.build() remaps
        // the deprecated notification usages to USAGE_NOTIFICATION (an API 26–32 phone keeps 8). Either is NOTIFICATION
        // to the vibrator, which lets it play from the background.
        assertEquals(android.media.AudioAttributes.USAGE_NOTIFICATION, lastAudioUsage(vibrator))
        assertEquals(VibrationUsage.NOTIFICATION, lastUsage(vibrator))
        legacy.vibrate(effect, VibrationUsage.TOUCH)
        assertEquals(android.media.AudioAttributes.USAGE_ASSISTANCE_SONIFICATION, lastAudioUsage(vibrator))
        assertEquals(VibrationUsage.TOUCH, lastUsage(vibrator))
    }

    @Test
    fun appSwipedAway_aTouchIsNotSentButAReceivedIconIs() {
        setProcessImportance(RunningAppProcessInfo.IMPORTANCE_CACHED)
        val usageVibrator = usageVibrator(vibrator)

        assertEquals(VibrationVerdict.BACKGROUND, usageVibrator.vibrate(effect, VibrationUsage.TOUCH))
        assertNull(lastVibration(vibrator))
        assertEquals(VibrationVerdict.PLAYS, usageVibrator.vibrate(effect, VibrationUsage.COMMUNICATION_REQUEST))
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
        // A sensor's rendering also plays from the background (physical emulation).
        assertEquals(VibrationVerdict.PLAYS, usageVibrator.verdict(VibrationUsage.PHYSICAL_EMULATION))
    }

    @Test
    fun openAppScreenOff_isTopSleeping_butAForegroundServiceStaysForeground() {
        setScreenOn(false)
        assertEquals(VibrationVerdict.BACKGROUND, usageVibrator(vibrator).verdict(VibrationUsage.TOUCH))
        setProcessImportance(RunningAppProcessInfo.IMPORTANCE_FOREGROUND_SERVICE) // "Stay reachable" running
        assertEquals(VibrationVerdict.PLAYS, usageVibrator(vibrator).verdict(VibrationUsage.TOUCH))
    }

    @Test
    fun batterySaver_dropsTouchAndTheOldNotificationRouteButNotACommunicationRequest() {
        shadowOf(context.getSystemService(PowerManager::class.java)).setIsPowerSaveMode(true)
        assertEquals(VibrationVerdict.BATTERY_SAVER, usageVibrator(vibrator).verdict(VibrationUsage.TOUCH))
        assertEquals(VibrationVerdict.PLAYS, usageVibrator(vibrator).verdict(VibrationUsage.COMMUNICATION_REQUEST))
        assertEquals(VibrationVerdict.BATTERY_SAVER, usageVibrator(vibrator, apiLevel = 32).verdict(VibrationUsage.COMMUNICATION_REQUEST))
    }

    @Test
    fun touchFeedbackOff_aTouchIsNotSent() {
        Settings.System.putInt(context.contentResolver, Settings.System.HAPTIC_FEEDBACK_ENABLED, 0)
        assertEquals(VibrationVerdict.TOUCH_FEEDBACK_OFF, usageVibrator(vibrator).vibrate(effect, VibrationUsage.TOUCH))
        assertNull(lastVibration(vibrator))
        assertEquals(VibrationVerdict.PLAYS, usageVibrator(vibrator).verdict(VibrationUsage.COMMUNICATION_REQUEST))
    }

    @Test
    fun player_aPlayAndroidWouldIgnore_isIgnoredWithItsReason() {
        setProcessImportance(RunningAppProcessInfo.IMPORTANCE_CACHED)
        val player = AdaptiveHapticPlayer(usageVibrator(vibrator), { DeviceCapabilities(true, true, 35) }, { null })

        assertEquals(Playback.Ignored(VibrationVerdict.BACKGROUND), player.play(HapticIcon.KNOCK, VibrationUsage.TOUCH))
        assertNull(lastVibration(vibrator))
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, (player.play(HapticIcon.KNOCK, VibrationUsage.COMMUNICATION_REQUEST) as Playback.Playing).renderer)
        assertEquals(PROCESSING_KNOCK, lastVibration(vibrator))
        assertEquals(VibrationVerdict.PLAYS, player.verdict(VibrationUsage.COMMUNICATION_REQUEST))
    }

    @Test
    fun audioCoupled_aReceivedIconInBatterySaver_leavesTheHapticChannelForTheVibrator() {
        // The haptic channel of an instant-message stream is NOTIFICATION to the vibrator, which Battery Saver drops;
        // the vibrator's COMMUNICATION_REQUEST is not dropped, so the icon plays there.
        val played = ArrayList<Pair<File, VibrationUsage>>()
        val output = object : AudioCoupledOutput {
            override val isAvailable = true
            override fun play(wav: File, usage: VibrationUsage) { played += wav to usage }
            override fun stop() = Unit
        }
        val audioPhone = DeviceCapabilities(true, true, 35, hapticPlaybackSupported = true, hapticGeneratorAvailable = true)
        val player = AdaptiveHapticPlayer(usageVibrator(vibrator), { audioPhone }, { null }, output, IconAudioCache(folder.newFolder("audio")))

        assertEquals(RendererKind.AUDIO_COUPLED, (player.play(HapticIcon.KNOCK, VibrationUsage.COMMUNICATION_REQUEST) as Playback.Playing).renderer)
        assertEquals(listOf(VibrationUsage.COMMUNICATION_REQUEST), played.map { it.second })

        shadowOf(context.getSystemService(PowerManager::class.java)).setIsPowerSaveMode(true)
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, (player.play(HapticIcon.KNOCK, VibrationUsage.COMMUNICATION_REQUEST) as Playback.Playing).renderer)
        assertEquals(1, played.size)
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
    }
}
