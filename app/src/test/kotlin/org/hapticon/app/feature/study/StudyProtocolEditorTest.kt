package org.hapticon.app.feature.study

import android.content.Context
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.RoomStudyRepository
import org.hapticon.app.study.StoredProtocol
import org.hapticon.core.HapticIcon
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ProtocolJson
import org.hapticon.study.design.OrderScheme
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The protocol editor: validation by the study module, saving, revisions, JSON import and export. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class StudyProtocolEditorTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val dispatcher = StandardTestDispatcher()
    private lateinit var db: HapticonDatabase
    private lateinit var repository: RoomStudyRepository
    private val custom = HapticIcon("tap", 0.01, 0.02, 0.8, 0.01, 60.0, 0.0, 1)
    private val icons = object : IconRepository {
        override fun icons(): Flow<List<HapticIcon>> = flowOf(HapticIcon.PRESETS + custom)
    }

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
        repository = RoomStudyRepository(db)
    }

    @After
    fun tearDown() {
        db.close()
        Dispatchers.resetMain()
    }

    /** The state once every queued update has run. */
    private fun ProtocolEditorViewModel.now(): ProtocolEditorUiState.Success {
        dispatcher.scheduler.advanceUntilIdle()
        return uiState.value as ProtocolEditorUiState.Success
    }

    private suspend fun editor(id: String) = ProtocolEditorViewModel(id, repository, icons).also { it.loaded.join() }

    @Test
    fun defaultProtocol_isReadOnly_andCannotBeOverwritten() = runTest(dispatcher) {
        val vm = editor(OriginatingStudy.ID)
        assertEquals(
            ProtocolEditorUiState.Error("protocol hapticon-icons cannot be edited; duplicate it first"),
            vm.uiState.first { it !is ProtocolEditorUiState.Loading },
        )
        assertEquals(
            "protocol hapticon-icons is read-only; duplicate it to edit",
            assertThrows(IllegalArgumentException::class.java) { kotlinx.coroutines.runBlocking { repository.saveProtocol(StoredProtocol.DEFAULT) } }.message,
        )
    }

    @Test
    fun edits_areValidatedByTheStudyModule_andSavedWithIconStickerDesignAndNoise() = runTest(dispatcher) {
        repository.saveProtocol(StoredProtocol(OriginatingStudy.PROTOCOL.copy(id = "mine")))
        val vm = editor("mine")

        vm.editTask(1) { it.copy(question = " ") }
        assertEquals("tasks[1].question: must not be blank", vm.now().problem)
        vm.editTask(1) { it.copy(question = "Does {nn} fit?") }
        assertEquals("tasks[1].question: unknown placeholder {nn}; use {n}, {label}, {icon}, {text}, {sticker}", vm.now().problem)
        vm.editTask(1) { it.copy(question = "Does icon {n} fit the text?") }
        assertNull(vm.now().problem)

        vm.setPoints(7)
        assertEquals(listOf("strongly disagree", "strongly agree"), vm.now().draft!!.labels)
        vm.editStimulus(0, 2) { it.copy(icon = custom, sticker = "sticker_wave", text = "tap tap") }
        vm.edit { it.copy(taskOrder = OrderScheme.RANDOM, seed = 99, masking = MaskingSetting(NoiseColor.WHITE, -24.0), title = "Mine") }
        vm.save().join()

        val saved = repository.protocol("mine")!!
        assertEquals(7, saved.protocol.scale.points)
        assertEquals("Mine", saved.protocol.title)
        assertEquals(OrderScheme.RANDOM, saved.protocol.taskOrder)
        assertEquals(99L, saved.seed)
        assertEquals(MaskingSetting(NoiseColor.WHITE, -24.0), saved.masking)
        assertEquals(custom, saved.protocol.tasks[0].stimuli[2].icon)
        assertEquals("sticker_wave", saved.protocol.tasks[0].stimuli[2].sticker)
        assertEquals(1, saved.protocol.revision)
        assertEquals("saved revision 1", vm.now().message)
    }

    @Test
    fun savingAfterSessionsRan_bumpsTheRevision_soOldSessionsKeepTheirMeaning() = runTest(dispatcher) {
        val mine = StoredProtocol(OriginatingStudy.PROTOCOL.copy(id = "mine"))
        repository.saveProtocol(mine)
        repository.startSession(mine, 1L)
        val vm = editor("mine")
        vm.edit { it.copy(title = "Mine, revised") }
        vm.save().join()
        assertEquals(2, repository.protocol("mine")!!.protocol.revision)
        assertEquals(1, repository.sessionsOf("mine").single().protocol.revision)
        assertEquals("saved revision 2", vm.now().message)
    }

    @Test
    fun json_exportsTheDraft_andImportsPastedJsonUnderTheSameId() = runTest(dispatcher) {
        repository.saveProtocol(StoredProtocol(OriginatingStudy.PROTOCOL.copy(id = "mine")))
        val vm = editor("mine")
        vm.exportJson()
        assertEquals(ProtocolJson.encode(OriginatingStudy.PROTOCOL.copy(id = "mine")), vm.now().json)

        vm.setJson(ProtocolJson.encode(OriginatingStudy.PROTOCOL.copy(id = "other", title = "Imported", tasks = OriginatingStudy.PROTOCOL.tasks.take(1), fixedFirst = emptyList())))
        vm.importJson()
        assertEquals("imported 1 tasks", vm.now().message)
        assertEquals("mine", vm.now().draft!!.id)
        assertEquals("Imported", vm.now().draft!!.title)

        vm.setJson("{\"schema\": \"hapticon.study\", \"version\": 1, \"id\": \"x\", \"title\": \"t\", \"scale\": {\"points\": 1}, \"tasks\": []}")
        vm.importJson()
        assertEquals("scale.points: must be in 2..11, was 1", vm.now().message)
        vm.setJson("{not json")
        vm.importJson()
        assertEquals("Imported", vm.now().draft!!.title)
        assertEquals(true, vm.now().message!!.startsWith("not JSON: "))
    }
}
