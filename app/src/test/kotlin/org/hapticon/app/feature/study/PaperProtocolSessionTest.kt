package org.hapticon.app.feature.study

import android.content.Context
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.app.playback.usageVibrator
import android.os.Vibrator
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.app.playback.PAPER_KNOCK
import org.hapticon.app.playback.PROCESSING_KNOCK
import org.hapticon.app.playback.VibratorHapticPlayer
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.RoomStudyRepository
import org.hapticon.app.study.StoredProtocol
import org.hapticon.app.study.TestHapticPlayer
import org.hapticon.app.study.TestMaskingNoise
import org.hapticon.app.study.TickingClock
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.study.LikertScale
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.StudyStep
import org.hapticon.study.log.StudyEvent
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

/** The paper's procedure in the Study tab: built in and read-only, the four icons together, then the items. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class PaperProtocolSessionTest {
    @get:Rule val rule = createComposeRule()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val dispatcher = StandardTestDispatcher()
    private val clock = TickingClock()
    private val player = TestHapticPlayer()
    private val noise = TestMaskingNoise()
    private lateinit var db: HapticonDatabase

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).allowMainThreadQueries().build()
    }

    @After
    fun tearDown() {
        db.close()
        Dispatchers.resetMain()
    }

    @Test
    fun repository_listsThePaperProtocolBuiltInReadOnlyWithWhiteNoise() = runTest(dispatcher) {
        val repository = RoomStudyRepository(db)
        val protocols = repository.protocols().first()
        assertEquals(listOf(OriginatingStudy.ID, OriginatingStudy.PAPER_ID), protocols.map { it.protocol.id })
        val paper = repository.protocol(OriginatingStudy.PAPER_ID)!!
        assertTrue(paper.readOnly)
        assertEquals(NoiseColor.WHITE, paper.masking.color)
        val copy = paper.copy(readOnly = false)
        val refused = runCatching { repository.saveProtocol(copy) }.exceptionOrNull()
        assertEquals("the id hapticon-icons-paper belongs to a built-in protocol; choose another id", refused?.message)
    }

    @Test
    fun session_paperProtocol_fourIconsPressedFreelyThenTheItemsByNumber() = runTest(dispatcher) {
        val repository = RoomStudyRepository(db)
        val record = repository.startSession(StoredProtocol.PAPER, clock())
        val vm = StudySessionViewModel(record.id, repository, player, noise, clock)
        vm.loaded.join()
        vm.startTask().join()
        val explore = (vm.uiState.value as SessionUiState.Active).step as StudyStep.Explore
        assertEquals(listOf("stroke", "hit", "knock", "hug"), explore.stimuli.map { it.id })
        // White noise plays while the icons are on screen.
        assertEquals(listOf("start WHITE ${record.masking.levelDbfs}"), noise.calls)
        // Pressed freely: hug twice, then stroke; nothing moves the screen on but the button.
        vm.pressIcon("hug").join()
        vm.pressIcon("hug").join()
        vm.pressIcon("stroke").join()
        val active = vm.uiState.value as SessionUiState.Active
        assertTrue(active.step is StudyStep.Explore)
        assertEquals(setOf("hug", "stroke"), active.pressedStimuli)
        assertEquals(listOf(HapticIcon.HUG, HapticIcon.HUG, HapticIcon.STROKE), player.played)
        // Each the participant's press in the open app: a touch.
        assertEquals(List(3) { VibrationUsage.TOUCH }, player.usages)
        // The built-in paper protocol's stimuli are Processing-exact, as the participants felt them.
        assertEquals(List(3) { EnvelopeModel.PROCESSING }, player.models)
        vm.finishExploring().join()
        val first = (vm.uiState.value as SessionUiState.Active).step as StudyStep.Trial
        assertEquals("Haptic icon 1 feels like stroking", first.question)
        // Stroke was felt on the shared screen, so its item can be answered at once.
        vm.select(4).join()
        assertTrue((vm.uiState.value as SessionUiState.Active).canContinue)
        vm.next().join()
        assertEquals("Haptic icon 2 feels like hitting", ((vm.uiState.value as SessionUiState.Active).step as StudyStep.Trial).question)
        val events = repository.entries(record.id).map { it.event }
        assertEquals(3, events.count { it is StudyEvent.IconPressed })
        assertTrue(events.contains(StudyEvent.ExplorationEnded("icons")))
        assertEquals(StudyEvent.Answer("icons", "stroke", 4), events.last { it is StudyEvent.Answer })
    }

    @Test
    fun session_protocolsEnvelopeModel_isTheWaveformTheVibratorPlays() = runTest(dispatcher) {
        // The real vibrator player on Robolectric's vibrator: a paper-model protocol plays the paper's trapezoids,
        // a processing one (the default) what the study's participants felt.
        val vibrator = context.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        val vibratorPlayer = VibratorHapticPlayer(usageVibrator(vibrator))
        val repository = RoomStudyRepository(db)
        for ((model, expected) in listOf(EnvelopeModel.PAPER to PAPER_KNOCK, EnvelopeModel.PROCESSING to PROCESSING_KNOCK)) {
            val protocol = StoredProtocol.PAPER.protocol.copy(id = "knock-${model.name.lowercase()}", envelopeModel = model)
            val record = repository.startSession(StoredProtocol.PAPER.copy(protocol = protocol, readOnly = false), clock())
            val vm = StudySessionViewModel(record.id, repository, vibratorPlayer, noise, clock)
            vm.loaded.join()
            vm.startTask().join()
            vm.pressIcon("knock").join()
            assertEquals("$model", expected, lastVibration(vibrator))
            assertEquals("$model", VibrationUsage.TOUCH, org.hapticon.app.playback.lastUsage(vibrator))
            val events = repository.entries(record.id).map { it.event }
            assertTrue("$model", events.contains(StudyEvent.PlaybackStarted("icons", "knock")))
        }
    }

    @Test
    fun sessionScreen_exploreStep_showsTheFourNumberedIconsAndGoesOnToTheQuestions() {
        val task = OriginatingStudy.PAPER_PROTOCOL.tasks.first()
        val state = SessionUiState.Active(
            participant = "P000-A", step = StudyStep.Explore(task, 1, task.stimuli), scale = LikertScale.AGREEMENT_5,
            answered = 0, trials = 12, selected = null, iconPressed = false, playing = false, pressedStimuli = setOf("hit"),
        )
        val pressed = ArrayList<String>()
        var finished = 0
        rule.setContent {
            HapticonTheme {
                SessionScreen(state, SessionActions(onPressStimulus = { pressed += it }, onFinishExploring = { finished++ }), pinError = null)
            }
        }
        for (n in 1..4) rule.onNodeWithContentDescription("Play haptic icon $n").assertExists()
        rule.onNodeWithContentDescription("Play haptic icon 3").performScrollTo().performClick()
        rule.onNodeWithContentDescription("Play haptic icon 1").performScrollTo().performClick()
        assertEquals(listOf("knock", "stroke"), pressed)
        // Icon 2 (hit) was felt already, the others not yet.
        rule.onNodeWithContentDescription("Play haptic icon 2").assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, "felt"))
        rule.onNodeWithContentDescription("Play haptic icon 4").assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, "not felt yet"))
        rule.onNodeWithText("Go to the questions").performScrollTo().performClick()
        assertEquals(1, finished)
    }
}
