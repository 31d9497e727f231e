package org.hapticon.app.feature.study

import android.content.Context
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.RoomStudyRepository
import org.hapticon.app.study.SessionRecord
import org.hapticon.app.study.StoredProtocol
import org.hapticon.app.study.StudyExporter
import org.hapticon.app.study.TestHapticPlayer
import org.hapticon.app.study.TestMaskingNoise
import org.hapticon.app.study.TickingClock
import org.hapticon.core.HapticIcon
import org.hapticon.study.StudyStep
import org.hapticon.study.log.ChainVerification
import org.hapticon.study.log.HashChain
import org.hapticon.study.log.StudyEvent
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * A whole default-protocol session walked through [StudySessionViewModel] on a Room database file, and the same
 * session killed mid-task and resumed by a new ViewModel and repository on that file.
 */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class StudySessionWalkTest {
    @get:Rule val folder = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val dispatcher = StandardTestDispatcher()
    private val clock = TickingClock()
    private val player = TestHapticPlayer()
    private val noise = TestMaskingNoise()
    private val masking = MaskingSetting(NoiseColor.PINK, -30.0)
    private val protocol = StoredProtocol.DEFAULT.copy(masking = masking)
    private val databases = ArrayList<HapticonDatabase>()

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        context.deleteDatabase(DB)
    }

    @After
    fun tearDown() {
        databases.forEach { it.close() }
        Dispatchers.resetMain()
    }

    private fun open(): RoomStudyRepository =
        RoomStudyRepository(Room.databaseBuilder(context, HapticonDatabase::class.java, DB).build().also { databases += it })

    private fun viewModel(repository: RoomStudyRepository, sessionId: Long) =
        StudySessionViewModel(sessionId, repository, player, noise, clock)

    /** Participant 0's session of [repository], loaded, with its first task started. */
    private suspend fun startFirstTask(repository: RoomStudyRepository): Pair<SessionRecord, StudySessionViewModel> {
        val record = repository.startSession(protocol, clock())
        val vm = viewModel(repository, record.id)
        vm.loaded.join()
        vm.startTask().join()
        return record to vm
    }

    private fun StudySessionViewModel.active() = uiState.value as SessionUiState.Active

    private suspend fun StudySessionViewModel.rate(value: Int) {
        pressIcon().join()
        select(value).join()
        assertTrue(active().canContinue)
        next().join()
    }

    @Test
    fun defaultProtocol_participant1_walksEveryStepAndExportsTheExpectedRows() = runTest(dispatcher) {
        val repository = open()
        repository.startSession(protocol, clock()) // P000-A, so that the walked one is participant index 1
        val record = repository.startSession(protocol, clock())
        assertEquals("P001-D", record.participant)
        val vm = viewModel(repository, record.id)
        vm.loaded.join()

        val seen = ArrayList<String>()
        fun note() = when (val step = vm.active().step) {
            is StudyStep.TaskIntro -> seen += "intro ${step.task.id}"
            is StudyStep.Explore -> seen += "explore ${step.task.id}"
            is StudyStep.Trial -> seen += "trial ${step.task.id}/${step.stimulus.id}: ${step.question}"
            is StudyStep.TaskEnd -> seen += "end ${step.task.id}"
            StudyStep.Done -> seen += "done"
        }
        val answers = listOf(listOf(5, 4, 3, 2), listOf(1, 2, 3, 4), listOf(5, 5, 1, 1))
        for (task in answers) {
            note()
            vm.startTask().join()
            for (value in task) {
                note()
                // Next stays disabled until the icon was felt and a value chosen.
                assertFalse(vm.active().canContinue)
                val answered = vm.active().answered
                vm.next().join()
                assertEquals("Next before pressing the icon is ignored", answered, vm.active().answered)
                vm.rate(value)
            }
            note()
            vm.finishTask().join()
        }
        note()

        assertEquals(
            listOf(
                "intro icons",
                "trial icons/hit: Haptic icon 1 feels like hitting",
                "trial icons/knock: Haptic icon 2 feels like knocking",
                "trial icons/stroke: Haptic icon 3 feels like stroking",
                "trial icons/hug: Haptic icon 4 feels like hugging",
                "end icons",
                "intro stickers",
                "trial stickers/sticker_hit: This haptic icon enhances the touch effect of the sticker",
                "trial stickers/sticker_knock: This haptic icon enhances the touch effect of the sticker",
                "trial stickers/sticker_stroke: This haptic icon enhances the touch effect of the sticker",
                "trial stickers/sticker_hug: This haptic icon enhances the touch effect of the sticker",
                "end stickers",
                "intro text",
                "trial text/text_hit: This haptic icon enhances the effect of the text",
                "trial text/text_knock: This haptic icon enhances the effect of the text",
                "trial text/text_stroke: This haptic icon enhances the effect of the text",
                "trial text/text_hug: This haptic icon enhances the effect of the text",
                "end text",
                "done",
            ),
            seen,
        )
        assertEquals(12, vm.active().answered)
        assertEquals(List(3) { listOf(HapticIcon.HIT, HapticIcon.KNOCK, HapticIcon.STROKE, HapticIcon.HUG) }.flatten(), player.played)
        // The noise runs from each task's first trial to its end: once per task, never restarted per trial.
        assertEquals(List(3) { listOf("start PINK -30.0", "stop") }.flatten(), noise.calls)

        val entries = repository.entries(record.id)
        assertEquals(ChainVerification.Intact, HashChain.verify(entries))
        // 1 start + 3 × (task start + 4 × 5 trial events + task end) + session end.
        assertEquals(1 + 3 * 22 + 1, entries.size)
        assertEquals(StudyEvent.SessionEnded, entries.last().event)
        assertEquals(
            listOf("stimulus_shown", "icon_pressed", "playback_started", "playback_finished", "answer"),
            entries.subList(2, 7).map { it.type },
        )

        val export = StudyExporter(folder.root, clock = { 42L }).export(protocol.protocol, listOf(record to entries))
        val t = 1_700_000_000_000L
        val lines = listOf(
            "hapticon-icons,1,processing,P001-D,1,icons,1,1,hit,hit,,,Haptic icon 1 feels like hitting,5,4000,1,${t + 7_000}",
            "hapticon-icons,1,processing,P001-D,1,icons,1,2,knock,knock,,,Haptic icon 2 feels like knocking,4,4000,1,${t + 12_000}",
            "hapticon-icons,1,processing,P001-D,1,icons,1,3,stroke,stroke,,,Haptic icon 3 feels like stroking,3,4000,1,${t + 17_000}",
            "hapticon-icons,1,processing,P001-D,1,icons,1,4,hug,hug,,,Haptic icon 4 feels like hugging,2,4000,1,${t + 22_000}",
            "hapticon-icons,1,processing,P001-D,1,stickers,2,1,sticker_hit,hit,,sticker_hit,This haptic icon enhances the touch effect of the sticker,1,4000,1,${t + 29_000}",
            "hapticon-icons,1,processing,P001-D,1,stickers,2,2,sticker_knock,knock,,sticker_knock,This haptic icon enhances the touch effect of the sticker,2,4000,1,${t + 34_000}",
            "hapticon-icons,1,processing,P001-D,1,stickers,2,3,sticker_stroke,stroke,,sticker_stroke,This haptic icon enhances the touch effect of the sticker,3,4000,1,${t + 39_000}",
            "hapticon-icons,1,processing,P001-D,1,stickers,2,4,sticker_hug,hug,,sticker_hug,This haptic icon enhances the touch effect of the sticker,4,4000,1,${t + 44_000}",
            "hapticon-icons,1,processing,P001-D,1,text,3,1,text_hit,hit,Take that!,,This haptic icon enhances the effect of the text,5,4000,1,${t + 51_000}",
            "hapticon-icons,1,processing,P001-D,1,text,3,2,text_knock,knock,\"Hey, are you there?\",,This haptic icon enhances the effect of the text,5,4000,1,${t + 56_000}",
            "hapticon-icons,1,processing,P001-D,1,text,3,3,text_stroke,stroke,\"There, there. It'll be fine.\",,This haptic icon enhances the effect of the text,1,4000,1,${t + 61_000}",
            "hapticon-icons,1,processing,P001-D,1,text,3,4,text_hug,hug,I missed you so much!,,This haptic icon enhances the effect of the text,1,4000,1,${t + 66_000}",
        )
        val expected = (listOf(org.hapticon.study.export.ResponseCsv.HEADER) + lines).joinToString("") { "$it\r\n" }
        assertEquals(expected, export.csv)
        assertEquals(expected, export.csvFile.readText())
        assertEquals(12, export.rows)
        assertEquals(listOf("P001-D: log intact"), export.checks.map { "${it.participant}: ${it.summary}" })
    }

    @Test
    fun killedMidTask_newViewModelOnTheSameFile_resumesAtTheNextTrialWithNothingLost() = runTest(dispatcher) {
        val first = open()
        val (record, vm) = startFirstTask(first)
        // Participant 0's Williams row: stroke, hit, hug, knock.
        vm.rate(5) // stroke
        vm.rate(4) // hit
        vm.pressIcon().join() // hug felt, a value picked, but Next never pressed
        vm.select(2).join()
        val before = first.entries(record.id)
        databases.removeLast().close() // the process dies

        val second = open()
        val resumed = viewModel(second, record.id)
        resumed.loaded.join()

        val state = resumed.active()
        val step = state.step as StudyStep.Trial
        assertEquals("icons/hug/3", "${step.task.id}/${step.stimulus.id}/${step.trial}")
        assertEquals(2, state.answered)
        assertTrue("the press before the crash counts", state.iconPressed)
        assertNull("an unconfirmed choice is not an answer", state.selected)
        val after = second.entries(record.id)
        assertEquals(before, after.dropLast(1))
        assertEquals(StudyEvent.StimulusShown("icons", "hug"), after.last().event)
        assertEquals(ChainVerification.Intact, HashChain.verify(after))
        // The trial's noise starts again with the re-shown trial.
        assertEquals(listOf("start PINK -30.0", "start PINK -30.0"), noise.calls)

        resumed.select(3).join()
        resumed.next().join()
        assertEquals("icons/knock", (resumed.active().step as StudyStep.Trial).let { "${it.task.id}/${it.stimulus.id}" })
        val rows = org.hapticon.study.export.ResponseRows.of(protocol.protocol, second.entries(record.id))
        assertEquals(listOf("stroke=5", "hit=4", "hug=3"), rows.map { "${it.stimulus}=${it.response}" })
        // The hug trial's response time counts from its re-showing after the restart; its press before it counts.
        assertEquals(1_000L, rows[2].responseTimeMillis)
        assertEquals(1, rows[2].iconPresses)
    }

    @Test
    fun appInTheBackground_stopsTheNoise_andBackMidTaskRestartsIt() = runTest(dispatcher) {
        val (_, vm) = startFirstTask(open())
        vm.pause().join()
        vm.rate(3) // answering while paused does not start the noise
        vm.resume().join()
        assertEquals(listOf("start PINK -30.0", "stop", "start PINK -30.0"), noise.calls)
        repeat(3) { vm.rate(3) }
        assertTrue(vm.active().step is StudyStep.TaskEnd)
        vm.pause().join()
        vm.resume().join()
        assertEquals("no noise between tasks", listOf("start PINK -30.0", "stop", "start PINK -30.0", "stop"), noise.calls)
    }

    @Test
    fun rowEditedWithRawSql_exportSaysWhereAndTheSessionRefusesToContinue() = runTest(dispatcher) {
        val repository = open()
        val (record, vm) = startFirstTask(repository)
        vm.rate(2)
        val answer = repository.entries(record.id).single { it.type == "answer" }
        assertEquals(6L, answer.sequence)

        databases.single().openHelper.writableDatabase.execSQL(
            "UPDATE study_events SET payload = '{\"task\":\"icons\",\"stimulus\":\"stroke\",\"value\":5}' WHERE session_id = ? AND seq = 6",
            arrayOf<Any>(record.id),
        )

        val export = StudyExporter(folder.root).export(protocol.protocol, listOf(record to repository.entries(record.id)))
        assertEquals("log edited at row 6", export.checks.single().summary)
        val reopened = viewModel(repository, record.id)
        reopened.loaded.join()
        assertEquals(
            SessionUiState.Failed("this session cannot continue: cannot resume a broken log: edited at index 6: entry 6 does not match its hash"),
            reopened.uiState.value,
        )
    }

    private companion object {
        const val DB = "study-walk.db"
    }
}
