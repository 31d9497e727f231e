package org.hapticon.app.feature.gesture

import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.gesture.FileGestureModelStore
import org.hapticon.app.gesture.GestureChannel
import org.hapticon.app.gesture.GestureSpans
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.app.gesture.TestGestureSource
import org.hapticon.app.gesture.syntheticSource
import org.hapticon.app.gesture.testGestureComponent
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.io.File

/** The teach flow: takes in, a trained and stored model out; model import. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class TeachViewModelTest {
    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val folder = TemporaryFolder()
    private val dispatcher = main.dispatcher
    private val person = SyntheticGestures.people(1, seed = 3).single()
    private val hug = GestureLabel.parse("hug-gentle")
    private val source = syntheticSource()

    @Test
    fun recordedTakes_trainAStoredModelWithValidationAccuracy() = runTest(dispatcher) {
        val gestures = testGestureComponent(source, folder.root)
        var clock = 0L
        val viewModel = TeachViewModel(gestures, work = dispatcher, nanoTime = { clock.also { clock += 42_000_000 } })
        viewModel.selectSource(org.hapticon.app.gesture.GestureSourceKind.SENSOR_BOARD)
        assertEquals(listOf(GestureLabel.NONE, hug), viewModel.ready().labels)
        // Record the takes the way the screen does: start, the source plays the take, stop.
        while (true) {
            val label = viewModel.ready().next ?: break
            val take = (viewModel.ready().recorded[label] ?: 0)
            viewModel.startTake()
            source.play(SyntheticGestures.perform(person, label, take).labelled.recording)
            viewModel.stopTake()
        }
        assertEquals(10 to 10, viewModel.ready().progress)
        viewModel.train()
        advanceUntilIdle()

        val result = viewModel.ready().result
        assertNotNull(viewModel.ready().message, result)
        assertEquals(listOf(GestureLabel.NONE, hug), result!!.labels)
        assertEquals(42L, result.trainingMillis)
        assertTrue("validation ${result.validationAccuracy}", result.validationAccuracy!! >= 0.9)
        assertTrue("training ${result.trainingAccuracy}", result.trainingAccuracy >= 0.99)
        // Stored: a fresh store over the same file reads it back.
        val stored = FileGestureModelStore(File(folder.root, "gesture-model.json")).model.value
        assertEquals(listOf(GestureLabel.NONE, hug), stored!!.labels)
        assertEquals(SyntheticGestures.CHANNELS, stored.channels)
    }

    @Test
    fun importModel_badFileShowsWhyAndKeepsNoModel() = runTest(dispatcher) {
        val gestures = testGestureComponent(source, folder.root)
        val viewModel = TeachViewModel(gestures, work = dispatcher)
        viewModel.importModel({ "{\"schema\":\"something-else\"}".byteInputStream() }, "model.json")
        advanceUntilIdle()
        assertEquals("model.json: model: schema must be \"hapticon.gesture-model\", was \"something-else\"", viewModel.ready().message)
        assertNull(viewModel.ready().model)
        assertNull(gestures.models.model.value)

        viewModel.importModel({ "".byteInputStream() }, "empty.json")
        advanceUntilIdle()
        assertEquals("empty.json: empty.json is empty", viewModel.ready().message)
    }

    @Test
    fun importModel_aTrainedModelFileIsStored() = runTest(dispatcher) {
        val gestures = testGestureComponent(source, folder.root)
        val model = org.hapticon.gesture.recognition.PersonalTrainer().train(listOf(SyntheticGestures.perform(person, hug, 0).labelled))
        val viewModel = TeachViewModel(gestures, work = dispatcher)
        viewModel.importModel({ model.encode().byteInputStream() }, "model.json")
        advanceUntilIdle()
        assertEquals("Imported model.json", viewModel.ready().message)
        assertEquals(model.labels, gestures.models.model.value!!.labels)
    }

    @Test
    fun gestureSpans_findTheHugInsideTheRest() {
        val take = SyntheticGestures.perform(person, hug, 0)
        val truth = take.labelled.spans.single()
        val found = GestureSpans.find(take.labelled.recording)!!
        // Within 0.2 s (20 frames) of the true span at each end: the ramps are soft.
        assertEquals(truth.from.toDouble(), found.first.toDouble(), 20.0)
        assertEquals(truth.to.toDouble(), (found.last + 1).toDouble(), 20.0)
    }

    @Test
    fun gestureSpans_constantOrEmptyRecordingHasNoSpan() {
        val flat = org.hapticon.gesture.Recording(100.0, listOf(org.hapticon.gesture.Channel("force", "N", DoubleArray(50) { 1.0 })))
        assertNull(GestureSpans.find(flat))
        val empty = org.hapticon.gesture.Recording(100.0, listOf(org.hapticon.gesture.Channel("force", "N", DoubleArray(0))))
        assertNull(GestureSpans.find(empty))
    }

    /** The state once the view model's flows have run (the main dispatcher is a test dispatcher): it must be ready. */
    private fun TeachViewModel.ready(): TeachUiState.Ready {
        dispatcher.scheduler.runCurrent()
        return uiState.value as? TeachUiState.Ready ?: throw AssertionError("not ready: ${uiState.value}")
    }
}
