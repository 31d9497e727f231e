package org.hapticon.app.gesture

import java.io.File
import org.hapticon.app.feature.gesture.RecordingPlotSource
import org.hapticon.testing.TestUsbDevices
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.PersonalTrainer
import org.hapticon.sensor.live.ChannelHistory
import org.hapticon.sensor.live.SensorSession
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** Recording and model files, imports, the bounded recording buffer and the sensor-board source's edges. */
@RunWith(RobolectricTestRunner::class)
class GestureStorageTest {
    @get:Rule
    val folder = TemporaryFolder()

    private fun recording(vararg values: Double) = Recording(100.0, listOf(Channel("force", "N", values)))

    @Test
    fun recordingStore_savesAsCsvNamedWithLabelAndReadsBack() {
        val store = FileRecordingStore(File(folder.root, "recordings"))
        val take = recording(0.0, 1.5, 3.0)
        val saved = store.save("my squeeze!", GestureLabel.parse("hug_energetic"), take)
        store.save("plain", null, take)

        assertEquals(SavedRecording("my_squeeze_.hug-energetic.csv", "my_squeeze_", GestureLabel.parse("hug-energetic"), 3, 0.03), saved)
        assertEquals(listOf("my_squeeze_", "plain"), store.list().map { it.name })
        assertNull(store.list().last().label)
        assertArrayEquals(doubleArrayOf(0.0, 1.5, 3.0), store.load(saved.id).channel("force")!!.toDoubleArray(), 0.0)
        assertEquals("N", store.load(saved.id).channels.single().unit)
        assertTrue(store.delete(saved.id))
        assertFalse(store.delete(saved.id))
        assertEquals(listOf("plain"), store.list().map { it.name })
    }

    @Test
    fun recordingStore_rejectsBlankOrLongNamesAndForeignPaths() {
        val store = FileRecordingStore(folder.root)
        assertEquals("a recording needs a name", assertThrows(IllegalArgumentException::class.java) { store.save("  ", null, recording(0.0, 1.0)) }.message)
        assertThrows(IllegalArgumentException::class.java) { store.save("x".repeat(65), null, recording(0.0, 1.0)) }
        assertEquals("no recording ../secret.csv", assertThrows(IllegalArgumentException::class.java) { store.load("../secret.csv") }.message)
        assertFalse(store.delete("../secret.csv"))
        // A file that is not a recording is not listed.
        File(folder.root, "junk.csv").writeText("not,a,recording")
        assertEquals(emptyList<SavedRecording>(), store.list())
    }

    @Test
    fun modelStore_savesAndAFreshStoreReadsIt_aBrokenFileIsNoModel() {
        val file = File(folder.root, "model.json")
        assertNull(FileGestureModelStore(file).model.value)
        val person = SyntheticGestures.people(1).single()
        val model = PersonalTrainer().train(listOf(SyntheticGestures.perform(person, GestureLabel.NONE, 0).labelled))
        val store = FileGestureModelStore(file)
        store.save(model)
        assertEquals(model, store.model.value)
        assertEquals(model.encode(), FileGestureModelStore(file).model.value!!.encode())
        file.writeText("{")
        assertNull(FileGestureModelStore(file).model.value)
    }

    @Test
    fun import_csvWavEmptyAndTooLarge() {
        assertEquals(2, RecordingImport.read("time_s,force_N\n0,1\n0.01,2\n".byteInputStream(), "a.csv").frameCount)
        assertEquals("a.csv is empty", assertThrows(IllegalArgumentException::class.java) { RecordingImport.read(ByteArray(0).inputStream(), "a.csv") }.message)
        val huge = object : java.io.InputStream() {
            override fun read(): Int = 'x'.code
        }
        assertEquals("big.csv is larger than 64 MiB", assertThrows(IllegalArgumentException::class.java) { RecordingImport.read(huge, "big.csv") }.message)
        val riff = "RIFF".toByteArray() + ByteArray(8)
        assertTrue(assertThrows(IllegalArgumentException::class.java) { RecordingImport.read(riff.inputStream(), "bad.wav") }.message!!.startsWith("bad.wav: "))
    }

    @Test
    fun buffer_keepsAtMostMaxFramesAndPlotsEachFrame() {
        val history = ChannelHistory(capacity = 16)
        val buffer = RecordingBuffer(listOf(GestureChannel("a"), GestureChannel("b", "g")), 10.0, maxFrames = 3, history = history)
        assertNull(buffer.toRecording())
        for (i in 0 until 5) buffer.onFrame(doubleArrayOf(i.toDouble(), -i.toDouble()))
        assertTrue(buffer.full)
        val recording = buffer.toRecording()!!
        assertArrayEquals(doubleArrayOf(0.0, 1.0, 2.0), recording.channel("a")!!.toDoubleArray(), 0.0)
        assertEquals("g", recording.channel("b")!!.unit)
        assertEquals(3L, history.written)
        assertThrows(IllegalArgumentException::class.java) { RecordingBuffer(listOf(GestureChannel("a")), Double.NaN, 3) }
        assertThrows(IllegalArgumentException::class.java) { RecordingBuffer(emptyList(), 10.0, 3) }
    }

    @Test
    fun plotSource_spansTheWholeTakeAndDecimatesToTheOutput() {
        val take = recording(0.0, 1.0, 2.0, 3.0, 4.0)
        val xs = FloatArray(3)
        val ys = FloatArray(3)
        assertEquals(3, RecordingPlotSource(take).copyRecent(0, 1L, xs, ys))
        assertArrayEquals(floatArrayOf(0f, 0.5f, 1f), xs, 0f)
        assertArrayEquals(floatArrayOf(0f, 2f, 4f), ys, 0f)
        assertEquals(0, RecordingPlotSource(take).copyRecent(1, 1L, xs, ys))
    }

    @Test
    fun sensorBoard_withoutAStreamSaysWhereToConnect_namesMadeSafe() {
        val source = SensorSessionGestureSource(SensorSession(TestUsbDevices()))
        assertEquals(emptyList<GestureChannel>(), source.channels)
        val e = assertThrows(IllegalStateException::class.java) { source.start {} }
        assertEquals("No sensor board is streaming: connect one in the Sensors tab and let it run for a second", e.message)
        assertEquals(listOf("force_N", "ch1", "a_b", "a_b_2"), SensorSessionGestureSource.safeNames(listOf("force N", " ", "a,b", "a b")))
    }
}
