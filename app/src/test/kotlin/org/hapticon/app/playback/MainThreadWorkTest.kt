package org.hapticon.app.playback

import android.os.Looper
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.IconRepository
import org.hapticon.app.feature.icons.IconsViewModel
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import java.util.concurrent.CountDownLatch
import java.util.concurrent.Executors
import java.util.concurrent.TimeUnit
import kotlin.coroutines.CoroutineContext

/**
 * An icon press must not render on the main thread. A [ThreadRecordingPlayer] double records the
 * thread each `play` (the rendering) runs on; its render context is a named thread of its own, as the real
 * players' is `Dispatchers.Default`.
 */
@RunWith(RobolectricTestRunner::class)
class MainThreadWorkTest {
    private val renderThread = Executors.newSingleThreadExecutor { Thread(it, "test-render") }

    @After
    fun tearDown() = renderThread.shutdownNow().let { }

    /** Records where it was asked to render; "plays" every icon for 10 ms. */
    private inner class ThreadRecordingPlayer : HapticPlayer {
        val renderedOn = ArrayList<String>()
        val onMainLooper = ArrayList<Boolean>()
        val played = CountDownLatch(1)
        override val renderContext: CoroutineContext = renderThread.asCoroutineDispatcher()
        override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

        override fun play(icon: HapticIcon, usage: VibrationUsage): Playback {
            renderedOn += Thread.currentThread().name
            onMainLooper += Looper.myLooper() == Looper.getMainLooper()
            played.countDown()
            return Playback.Playing(RendererKind.AMPLITUDE_WAVEFORM, 10, Fidelity(0.0, 0.0, "exact"))
        }

        override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback {
            renderedOn += "${Thread.currentThread().name}: pattern ${pattern.name}"
            return Playback.Unsupported
        }

        override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS

        override fun stop() {}
    }

    @Test
    fun iconPress_onTheMainThread_rendersOnTheRenderThread() {
        assertTrue(Looper.myLooper() == Looper.getMainLooper()) // a Robolectric test runs on the main looper
        val player = ThreadRecordingPlayer()
        val icons = object : IconRepository {
            override fun icons() = flowOf(HapticIcon.PRESETS)
        }
        val viewModel = IconsViewModel(icons, player)
        viewModel.play(HapticIcon.KNOCK) // what the Icons screen's press calls, on the main thread
        shadowOf(Looper.getMainLooper()).idle()
        assertTrue("not played", player.played.await(5, TimeUnit.SECONDS))
        assertEquals(listOf("test-render"), player.renderedOn)
        assertEquals(listOf(false), player.onMainLooper)
    }

    private val pattern = HapticPattern("ramp", listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0)), listOf(FrequencyKey(0.0, 150.0)))

    /** playMessageOffMain: a message's icon, else its pattern, rendered on the player's render thread; nothing for neither. */
    @Test
    fun playMessageOffMain_iconElsePatternOnTheRenderThread() = runBlocking {
        val player = ThreadRecordingPlayer()
        assertEquals(Playback.Playing(RendererKind.AMPLITUDE_WAVEFORM, 10, Fidelity(0.0, 0.0, "exact")), player.playMessageOffMain(HapticIcon.KNOCK, null, VibrationUsage.TOUCH))
        assertEquals(Playback.Unsupported, player.playMessageOffMain(null, pattern, VibrationUsage.TOUCH))
        assertEquals(null, player.playMessageOffMain(null, null, VibrationUsage.TOUCH))
        assertEquals(listOf("test-render", "test-render: pattern ramp"), player.renderedOn)
    }

    @Test
    fun realPlayers_renderContext_isTheDefaultPoolNotTheCaller() {
        val vibrator = androidx.test.core.app.ApplicationProvider.getApplicationContext<android.content.Context>()
            .getSystemService(android.os.Vibrator::class.java)
        assertEquals(Dispatchers.Default, VibratorHapticPlayer(usageVibrator(vibrator)).renderContext)
        assertEquals(Dispatchers.Default, AdaptiveHapticPlayer(usageVibrator(vibrator), { DeviceCapabilities(true, true, 35) }, { null }).renderContext)
    }
}
