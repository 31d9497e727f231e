package org.hapticon.app.feature.gesture

import androidx.room.Room
import org.hapticon.core.platform.VibrationUsage
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.app.gesture.TestGestureSource
import org.hapticon.app.gesture.syntheticSource
import org.hapticon.app.gesture.testGestureComponent
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.PlaybackCapabilities
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.extraction.NoisyIconRenders
import org.hapticon.gesture.recognition.GestureLabel
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.util.Random

/** Record from a fake source, trim, fit and save: the recorder end to end. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class RecorderViewModelTest {
    @get:Rule
    val folder = TemporaryFolder()

    @get:Rule
    val main = MainDispatcherRule()
    private val dispatcher = main.dispatcher
    private lateinit var db: HapticonDatabase
    private val played = ArrayList<HapticIcon>()
    private val usages = ArrayList<VibrationUsage>()
    private val player = object : HapticPlayer {
        override val capabilities = PlaybackCapabilities(hasVibrator = false, hasAmplitudeControl = false, apiLevel = 35)

        override fun play(icon: HapticIcon, usage: VibrationUsage): Playback {
            played += icon
            usages += usage
            return Playback.Unsupported
        }

        override fun play(pattern: org.hapticon.core.pattern.HapticPattern, usage: VibrationUsage): Playback = Playback.Unsupported

        override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS

        override fun stop() = Unit
    }

    // Knock rendered by haptics-core at 8 kHz with noise at 30 dB: the fitter's documented operating point.
    private val knock = NoisyIconRenders.render(HapticIcon.KNOCK, 30.0, Random(1), sampleRate = 8000).toRecording()
    private val source = TestGestureSource.of(knock)

    @Before
    fun setUp() {
        // Room runs its queries on the test dispatcher, so advanceUntilIdle also finishes a save.
        db = Room.inMemoryDatabaseBuilder(ApplicationProvider.getApplicationContext(), HapticonDatabase::class.java)
            .allowMainThreadQueries().setQueryCoroutineContext(dispatcher).build()
    }

    @After
    fun tearDown() {
        db.close()
    }

    private fun viewModel(from: TestGestureSource = source) =
        RecorderViewModel(testGestureComponent(from, folder.root), RoomIconRepository(db.iconDao()), player, work = dispatcher)

    /** A recorder that recorded [take] from the sensor-board source. */
    private fun recorded(take: org.hapticon.gesture.Recording = knock): RecorderViewModel {
        val from = TestGestureSource.of(take)
        val viewModel = viewModel(from)
        viewModel.selectSource(GestureSourceKind.SENSOR_BOARD)
        viewModel.startRecording()
        from.play(take)
        viewModel.stopRecording()
        return viewModel
    }

    @Test
    fun recordTrimFitSave_knockBecomesACustomIconWithThreeRepetitions() = runTest(dispatcher) {
        val viewModel = recorded()
        val recorded = viewModel.ready()
        assertEquals(knock.frameCount, recorded.take!!.frameCount)
        assertEquals(listOf("vibration"), recorded.channels)
        assertEquals(false, recorded.recording)

        // Cut 0.1 s of the 0.25 s silence off each end.
        viewModel.setTrim(800, knock.frameCount - 800)
        viewModel.makeIcon()
        advanceUntilIdle()
        val fit = viewModel.ready().fit
        assertNotNull(viewModel.ready().message, fit)
        assertEquals(3, fit!!.icon.count)
        // The documented period tolerance at 30 dB: mean error below 1 ms.
        assertEquals(HapticIcon.KNOCK.period, fit.icon.period, 0.001)
        assertEquals(HapticIcon.KNOCK.note, fit.icon.note, 0.0)
        assertEquals(3, fit.report.onsets.size)

        viewModel.setIconName("my knock")
        viewModel.play()
        viewModel.saveIcon()
        advanceUntilIdle()

        assertEquals(listOf("my knock"), played.map { it.name })
        // A press in the open app: a touch.
        assertEquals(listOf(VibrationUsage.TOUCH), usages)
        val saved = db.iconDao().icons().first().single()
        assertEquals("my knock", saved.name)
        assertEquals(3, saved.count)
        assertEquals("my knock", viewModel.ready().savedIcon)
        val inPicker = RoomIconRepository(db.iconDao()).icons().first()
        assertEquals(fit.icon.copy(name = "my knock"), inPicker.last())
    }

    @Test
    fun fitSavedStrongest_halfAsStrongKnock_fitsHalfTheLevelOfTheStrongest_andSavesBoth() = runTest(dispatcher) {
        // The same knock at full and at half amplitude, saved; fitted as a batch the strongest is the reference
        // (as `hapticon fit --reference strongest`), so the soft one keeps its lower level instead of fitting to full.
        val component = testGestureComponent(source, folder.root)
        val soft = org.hapticon.gesture.Recording(knock.sampleRate, listOf(org.hapticon.gesture.Channel("vibration", "", DoubleArray(knock.frameCount) { knock.channels[0][it] * 0.5 })))
        component.recordings.save("loud", null, knock)
        component.recordings.save("soft", null, soft)
        val viewModel = RecorderViewModel(component, RoomIconRepository(db.iconDao()), player, work = dispatcher)
        advanceUntilIdle()
        assertEquals(listOf("loud", "soft"), viewModel.ready().savedRecordings.map { it.name })

        viewModel.fitSavedStrongest()
        advanceUntilIdle()
        val batch = viewModel.ready().batch
        assertNotNull(viewModel.ready().message, batch)
        assertEquals(listOf("loud", "soft"), batch!!.map { it.recordingName })
        assertEquals(listOf("loud", "soft"), batch.map { it.fit.icon.name })
        val (loud, quiet) = batch.map { it.fit.icon.level }
        // Level is the sustain against the strongest gesture's peak: halving the gesture halves it (fit tolerance 0.05).
        assertEquals(loud / 2, quiet, 0.05)
        assertTrue(batch.all { it.fit.report.levelReference.startsWith("the strongest gesture of the batch of 2") })

        viewModel.saveBatchIcons()
        advanceUntilIdle()
        assertEquals(setOf("loud", "soft"), db.iconDao().icons().first().map { it.name }.toSet())
    }

    @Test
    fun fitSavedStrongest_nothingSaved_saysSo() = runTest(dispatcher) {
        val viewModel = viewModel()
        advanceUntilIdle()
        viewModel.fitSavedStrongest()
        assertEquals("No saved recordings to fit", viewModel.ready().message)
        assertNull(viewModel.ready().batch)
    }

    @Test
    fun trim_isClampedToTheTakeAndTwoFrames() = runTest(dispatcher) {
        val viewModel = recorded()
        viewModel.setTrim(-5, Int.MAX_VALUE)
        assertEquals(0 to knock.frameCount, viewModel.ready().let { it.trimFrom to it.trimTo })
        viewModel.setTrim(knock.frameCount, knock.frameCount)
        assertEquals(knock.frameCount - 2 to knock.frameCount, viewModel.ready().let { it.trimFrom to it.trimTo })
        assertEquals(2, viewModel.ready().trimmed!!.frameCount)
    }

    @Test
    fun silentTake_fitSaysNoGestureAndShowsNoIcon() = runTest(dispatcher) {
        val silence = org.hapticon.gesture.Recording(8000.0, listOf(org.hapticon.gesture.Channel("vibration", "", DoubleArray(4000))))
        val viewModel = recorded(silence)
        viewModel.makeIcon()
        advanceUntilIdle()
        assertNull(viewModel.ready().fit)
        assertTrue(viewModel.ready().message!!, viewModel.ready().message!!.startsWith("no gesture found"))
    }

    @Test
    fun recordings_savedListedOpenedDeleted() = runTest(dispatcher) {
        val viewModel = recorded()
        viewModel.setTrim(0, 4000)
        viewModel.saveRecording("my tap", GestureLabel.parse("knock-gentle"))
        advanceUntilIdle()
        val saved = viewModel.ready().savedRecordings.single()
        assertEquals("my_tap.knock-gentle.csv", saved.id)
        assertEquals("my_tap", saved.name)
        assertEquals(GestureLabel.parse("knock-gentle"), saved.label)
        assertEquals(4000, saved.frames)

        viewModel.openRecording(saved.id)
        advanceUntilIdle()
        assertEquals(4000, viewModel.ready().take!!.frameCount)

        viewModel.deleteRecording(saved.id)
        advanceUntilIdle()
        assertEquals(emptyList<Any>(), viewModel.ready().savedRecordings)
    }

    @Test
    fun importFile_badCsvShowsTheReadersMessage() = runTest(dispatcher) {
        val viewModel = viewModel()
        viewModel.importFile({ "time_s,force_N\n0,1\n0.01,x\n".byteInputStream() }, "bad.csv")
        advanceUntilIdle()
        assertEquals("bad.csv:3: force_N 'x' is not a number", viewModel.ready().message)
        assertNull(viewModel.ready().take)
    }

    @Test
    fun importFile_wavBecomesTheTake() = runTest(dispatcher) {
        val bytes = java.io.ByteArrayOutputStream().also { org.hapticon.gesture.io.RecordingWav.write(knock, it) }.toByteArray()
        val viewModel = viewModel()
        viewModel.importFile({ bytes.inputStream() }, "knock.wav")
        advanceUntilIdle()
        assertEquals(knock.frameCount, viewModel.ready().take!!.frameCount)
        assertEquals("Imported knock.wav", viewModel.ready().message)
    }

    /** The state once the view model's flows have run (the main dispatcher is a test dispatcher): it must be ready. */
    private fun RecorderViewModel.ready(): RecorderUiState.Ready {
        dispatcher.scheduler.runCurrent()
        return uiState.value as? RecorderUiState.Ready ?: throw AssertionError("not ready: ${uiState.value}")
    }
}
