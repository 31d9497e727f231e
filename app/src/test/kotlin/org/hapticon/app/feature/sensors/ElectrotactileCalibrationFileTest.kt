package org.hapticon.app.feature.sensors

import org.hapticon.app.data.ElectrodeLevelsStore
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.IOException
import java.time.Instant
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * The app keeps the electrotactile calibration in the CLI's file format (`hapticon.electrotactile-calibration` v1),
 * and moves it in and out through files: a finished calibration is stored, exported byte for byte, a CLI file is
 * imported with its participant and time, and a bad file is refused with one line while the stored one stays.
 */
@RunWith(RobolectricTestRunner::class)
class ElectrotactileCalibrationFileTest {
    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val folder = TemporaryFolder()

    private val now = Instant.parse("2026-11-27T00:12:03Z")

    private fun store() = ElectrodeLevelsStore(File(folder.root, ElectrodeLevelsStore.FILE_NAME), File(folder.root, ElectrodeLevelsStore.LEGACY_FILE_NAME)) { now }

    private fun ElectrotactileCalibrationViewModel.state(): ElectrotactileUiState {
        main.dispatcher.scheduler.advanceUntilIdle()
        return uiState.value
    }

    private fun ElectrotactileCalibrationViewModel.stored(): StoredCalibration? {
        main.dispatcher.scheduler.advanceUntilIdle()
        return storedCalibration.value
    }

    private fun viewModel(store: ElectrodeLevelsStore) = ElectrotactileCalibrationViewModel(TestStimulatorLink(ready = true), store, io = main.dispatcher)

    /** What `hapticon board calibrate --save --participant P07` writes for these steps. */
    private val fromTheCli = StoredCalibration(ElectrotactileCalibrationResult(listOf(61, 62, 63, 64, 65, 66, 67, 68, 90)), Instant.parse("2026-11-20T09:30:00Z"), "P07")

    @Test
    fun finishedCalibration_isStoredInTheCliFormat_andExportedByteForByte() {
        val store = store()
        val viewModel = viewModel(store)
        assertNull(viewModel.stored())
        repeat(9) { viewModel.clearAndPainFree() }
        viewModel.wholeArrayOk()
        val done = viewModel.state() as ElectrotactileUiState.Done
        assertEquals("Saved: the compliance study stimulates at these levels", done.message)
        assertFalse(done.problem)
        assertEquals(List(9) { 60 }, viewModel.stored()!!.result.steps)

        val file = File(folder.root, "electrotactile-calibration.json")
        val text = file.readText()
        assertTrue(text, text.startsWith("{\n  \"schema\": \"hapticon.electrotactile-calibration\",\n  \"version\": 1,\n"))
        assertEquals(StoredCalibration(ElectrotactileCalibrationResult(List(9) { 60 }), now), CalibrationFile.decode(file.readBytes()))
        assertEquals(List(9) { 60 }, store.load())

        val out = ByteArrayOutputStream()
        viewModel.exportTo { out }
        assertEquals("Exported the calibration of 2026-11-27 00:12 UTC (0.810 mA)", viewModel.state().message)
        assertArrayEquals(file.readBytes(), out.toByteArray())
    }

    @Test
    fun importingACliFile_storesItWithItsParticipantAndTime() {
        val store = store()
        val viewModel = viewModel(store)
        viewModel.importFrom { ByteArrayInputStream(CalibrationFile.encode(fromTheCli).toByteArray()) }
        val state = viewModel.state()
        assertEquals(
            "Imported P07's calibration of 2026-11-20 09:30 UTC (0.824–1.215 mA): the compliance study now stimulates at these levels",
            state.message,
        )
        assertFalse(state.problem)
        assertEquals(fromTheCli, viewModel.stored())
        assertEquals(fromTheCli, store.stored())
        // The calibration in progress on the screen is untouched: the import replaces only what the study uses.
        assertEquals(0, (state as ElectrotactileUiState.Electrode).electrode)
    }

    @Test
    fun badFiles_areRefusedWithOneLine_andTheStoredCalibrationStays() {
        val store = store()
        store.save(List(9) { 70 })
        val before = File(folder.root, ElectrodeLevelsStore.FILE_NAME).readBytes()
        val viewModel = viewModel(store)
        val pastTheCap = CalibrationFile.encode(fromTheCli).replace("\"step\": 64,", "\"step\": 201,")
        val cases = listOf(
            pastTheCap.toByteArray() to "Not imported: electrodes[3].step: must be in 0..200 (2.7 mA), was 201",
            "60,60,60,60,60,60,60,60,60".toByteArray() to "Not imported: not valid JSON: ",
            ByteArray(CalibrationFile.MAX_BYTES + 1) { ' '.code.toByte() } to "Not imported: larger than 16384 bytes: not a calibration file",
        )
        for ((bytes, expected) in cases) {
            viewModel.importFrom { ByteArrayInputStream(bytes) }
            val state = viewModel.state()
            assertTrue("${state.message} should start with $expected", state.message!!.startsWith(expected))
            assertFalse(state.message, state.message!!.contains('\n'))
            assertTrue(state.problem)
            assertEquals(List(9) { 70 }, viewModel.stored()!!.result.steps)
            assertArrayEquals(before, File(folder.root, ElectrodeLevelsStore.FILE_NAME).readBytes())
        }
        viewModel.importFrom { null }
        assertEquals("Not imported: the file could not be opened", viewModel.state().message)
        viewModel.exportTo { throw IOException("disk full") }
        assertEquals("Not exported: disk full", viewModel.state().message)
        assertTrue(viewModel.state().problem)
    }

    @Test
    fun exportWithNothingStored_saysSoAndWritesNothing() {
        val viewModel = viewModel(store())
        var opened = false
        viewModel.exportTo {
            opened = true
            ByteArrayOutputStream()
        }
        assertEquals("Nothing to export: finish a calibration or import one first", viewModel.state().message)
        assertFalse("no file is created for nothing", opened)
    }

    @Test
    fun theEarlierOneLineFile_isReadUntilTheFirstSaveInTheNewFormat() {
        File(folder.root, ElectrodeLevelsStore.LEGACY_FILE_NAME).writeText("61,62,63,64,65,66,67,68,69")
        val store = store()
        assertEquals((61..69).toList(), store.load())
        assertEquals((61..69).toList(), viewModel(store).stored()!!.result.steps)
        File(folder.root, ElectrodeLevelsStore.LEGACY_FILE_NAME).writeText("61,62,63,64,65,66,67,68,201")
        assertNull("past the cap in the old file reads as none", store.load())
        store.save(List(9) { 60 })
        assertEquals(List(9) { 60 }, store.load())
    }
}
