package org.hapticon.app.feature.chat

import android.content.Context
import android.os.Looper
import android.os.strictmode.Violation
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.asCoroutineDispatcher
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.launch
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.PatternPlan
import org.hapticon.app.playback.PeerPitch
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.PlaybackCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.recordMainThreadViolations
import org.hapticon.app.stopRecordingMainThreadViolations
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.CountDownLatch
import java.util.concurrent.Executors
import kotlin.coroutines.CoroutineContext

/**
 * The composer's "how it will feel there" figure renders the chosen icon, so the ViewModel computes it in the
 * player's render context, never on the main thread; while it is being computed the line shows the
 * peer's renderer without a figure, and a figure is only ever shown beside the icon it was computed for. A chosen
 * pattern's preview resamples it within the envelope limits the peer publishes.
 */
@RunWith(RobolectricTestRunner::class)
class ComposerFigureTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
    private val renderThread = Executors.newSingleThreadExecutor { Thread(it, "test-render") }
    private val collector = Job()
    private val violations = CopyOnWriteArrayList<Violation>()

    // Holds the render thread busy while the test chooses icons.
    private val busy = CountDownLatch(1)

    /** Plays nothing; renders (here: the figure) on [renderThread]. */
    private val player = object : HapticPlayer {
        override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
        override val renderContext: CoroutineContext = renderThread.asCoroutineDispatcher()
        override fun play(icon: HapticIcon, usage: VibrationUsage): Playback = Playback.Unsupported
        override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback = Playback.Unsupported
        override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS
        override fun stop() {}
    }

    @After
    fun tearDown() {
        stopRecordingMainThreadViolations()
        busy.countDown()
        collector.cancel()
        renderThread.shutdownNow()
        db.close()
    }

    private fun idleUntil(what: String, condition: () -> Boolean) {
        val deadline = System.nanoTime() + 10_000_000_000L
        while (true) {
            shadowOf(Looper.getMainLooper()).idle()
            if (condition()) return
            check(System.nanoTime() < deadline) { "timed out waiting for $what" }
            Thread.sleep(5)
        }
    }

    /** The conversation with bob, who publishes [bob], played through [with]; and every Success state it emits. */
    private fun openConversation(
        bob: Capabilities,
        with: HapticPlayer = player,
    ): Pair<ConversationViewModel, CopyOnWriteArrayList<ConversationUiState.Success>> {
        val viewModel = ConversationViewModel(
            "bob", { "alice" }, OfflineFirstChatRepository(db), RoomIconRepository(db.iconDao()), with,
            MutableStateFlow(mapOf("bob" to bob)), onSent = {},
        )
        val states = CopyOnWriteArrayList<ConversationUiState.Success>()
        CoroutineScope(Dispatchers.Main + collector).launch {
            viewModel.uiState.collect { if (it is ConversationUiState.Success) states += it }
        }
        idleUntil("the conversation") { states.isNotEmpty() }
        return viewModel to states
    }

    @Test
    fun chosenIcon_figureComputedOffMain_neverShownBesideAnotherIcon() {
        val knockFigure = RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.KNOCK)
        val hitFigure = RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.HIT)
        val bob = Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 35)
        val (viewModel, states) = openConversation(bob, player)
        recordMainThreadViolations(violations)

        // The render thread is busy: both choices show the renderer at once, without a figure.
        renderThread.execute { busy.await() }
        viewModel.selectIcon(HapticIcon.KNOCK)
        idleUntil("knock chosen") { states.last().selectedIcon == HapticIcon.KNOCK }
        assertEquals(PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, null, pitch = NO_PITCH), states.last().peerFeel)
        viewModel.selectIcon(HapticIcon.HIT)
        idleUntil("hit chosen") { states.last().selectedIcon == HapticIcon.HIT }
        assertEquals(PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, null, pitch = NO_PITCH), states.last().peerFeel)

        busy.countDown()
        idleUntil("hit's figure") { states.last().peerFeel?.fidelityPercent != null }
        assertEquals(ConversationUiState.Success::class, states.last()::class)
        assertEquals(HapticIcon.HIT to PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, hitFigure, pitch = NO_PITCH), states.last().selectedIcon to states.last().peerFeel)
        // No state ever paired an icon with a figure computed for another one.
        for (state in states) {
            val percent = state.peerFeel?.fidelityPercent ?: continue
            assertEquals("figure beside ${state.selectedIcon?.name}", if (state.selectedIcon == HapticIcon.HIT) hitFigure else knockFigure, percent)
        }
        shadowOf(Looper.getMainLooper()).idle()
        assertTrue("rendered on the main thread: ${violations.map { it.message }}", violations.isEmpty())
    }

    /**
     * Control: the same ViewModel with a player that renders on the caller's thread (the [HapticPlayer.renderContext]
     * default) computes the figure on the main thread, and the policy and listener used above and by
     * `MainThreadStrictModeTest` name it, so the green run above means the figure was not computed on main.
     */
    @Test
    fun control_figureOnTheCallersThread_isCaughtOnTheMainThread() {
        val onCaller = object : HapticPlayer {
            override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
            override fun play(icon: HapticIcon, usage: VibrationUsage): Playback = Playback.Unsupported
            override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback = Playback.Unsupported
            override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS
            override fun stop() {}
        }
        val hitFigure = RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.HIT)
        val bob = Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 35)
        val (viewModel, states) = openConversation(bob, onCaller)
        recordMainThreadViolations(violations)

        viewModel.selectIcon(HapticIcon.HIT)
        idleUntil("hit's figure") { states.last().peerFeel?.fidelityPercent == hitFigure }
        shadowOf(Looper.getMainLooper()).idle()
        assertTrue("expected the figure's slow call, got ${violations.map { it.message }}", violations.isNotEmpty())
        assertEquals(setOf("fidelity of hit"), violations.map { it.message }.toSet())
    }

    /** The composer's state after choosing [pattern] in a conversation with [bob] (the capabilities bob publishes). */
    private fun peerFeelOfPattern(bob: Capabilities, pattern: HapticPattern): PeerFeel? {
        val (viewModel, states) = openConversation(bob, player)
        viewModel.selectPattern(pattern)
        idleUntil("${pattern.name} chosen") { states.last().selectedPattern == pattern }
        return states.last().peerFeel
    }

    @Test
    fun chosenPattern_peerPublishesNarrowEnvelopeLimits_previewResamplesWithThem() {
        // 4 points of at least 50 ms: the ramp's 7 segments are fitted into 4 (PatternEnvelope.of, as bob's phone runs it).
        val narrow = BOB_API36.copy(envelopeLimits = EnvelopeEffectInfo(4, 50, 1000, 4000))
        assertEquals(
            PeerFeel(
                RendererKind.ENVELOPE, null,
                pitch = "bob's phone (120–240 Hz): 150 Hz → plays 150 Hz",
                envelope = "bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50 ms–1 s each, 4 s in all)",
            ),
            peerFeelOfPattern(narrow, RAMP),
        )
        assertEquals(4, ((PeerPitch.planOf(narrow, RAMP) as PatternPlan.Envelope).envelope as PatternEnvelope.Waveform).points.size)
    }

    @Test
    fun chosenPattern_peerWithoutEnvelopeLimits_previewAssumesTheGuaranteedOnesAndSaysSo() {
        assertEquals(
            PeerFeel(
                RendererKind.ENVELOPE, null,
                pitch = "bob's phone (120–240 Hz): 150 Hz → plays 150 Hz",
                envelope = "bob's envelope: 7 control points (limits not published; assumed 16 points, 20 ms–1 s each, 16 s in all)",
            ),
            peerFeelOfPattern(BOB_API36, RAMP),
        )
    }

    private companion object {
        /** bob's Android 16 phone as a build before published envelope limits describes it. */
        val BOB_API36 = Capabilities(
            "bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0,
            envelopeEffects = true, frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.OCTAVES,
        )

        /** Seven straight segments of 100–200 ms, no two on one line: seven control points where 16 are allowed. */
        val RAMP = HapticPattern(
            "ramp",
            listOf(
                AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 0.5), AmplitudeKey(0.2, 0.8), AmplitudeKey(0.3, 0.95),
                AmplitudeKey(0.4, 1.0), AmplitudeKey(0.6, 1.0), AmplitudeKey(0.8, 0.4), AmplitudeKey(1.0, 0.0),
            ),
            listOf(FrequencyKey(0.0, 150.0)),
        )

        /** The pitch line for a peer that publishes no frequency range (an amplitude-waveform phone): shown from the first state, it needs no render. */
        const val NO_PITCH = "bob's phone has no pitch control: plays at its resonance"
    }
}
