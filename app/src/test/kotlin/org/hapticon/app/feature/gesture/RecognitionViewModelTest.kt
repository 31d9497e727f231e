package org.hapticon.app.feature.gesture

import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.gesture.GestureChannel
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.SendRecordingChatRepository
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.app.gesture.TestGestureSource
import org.hapticon.app.gesture.syntheticSource
import org.hapticon.app.gesture.testGestureComponent
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.PersonalTrainer
import org.hapticon.gesture.synthetic.SyntheticGestures
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
 * Live recognition with a personal model of one simulated person (test-fixtures' synthetic gestures):
 * one message per squeeze (hug), none for the resting hand, and the rate limit.
 */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class RecognitionViewModelTest {
    @get:Rule
    val folder = TemporaryFolder()

    @get:Rule
    val main = MainDispatcherRule()
    private val dispatcher = main.dispatcher
    private val person = SyntheticGestures.people(1, seed = 3).single()
    private val none = GestureLabel.NONE
    private val hugGentle = GestureLabel.parse("hug-gentle")
    private val hugEnergetic = GestureLabel.parse("hug-energetic")
    private val knockGentle = GestureLabel.parse("knock-gentle")
    private val source = syntheticSource()
    private val chats = SendRecordingChatRepository(listOf("bob"))
    private var wakes = 0

    /** A model from five takes (0–4) of each label, stored where the view model finds it. */
    private fun TestScope.viewModel(minInterval: Double = RecognitionViewModel.MIN_SEND_INTERVAL_SECONDS): RecognitionViewModel {
        val gestures = testGestureComponent(source, folder.root)
        val takes = listOf(none, hugGentle, hugEnergetic, knockGentle).flatMap { label -> (0 until 5).map { SyntheticGestures.perform(person, label, it).labelled } }
        gestures.models.save(PersonalTrainer().train(takes))
        val viewModel = RecognitionViewModel(gestures, chats, user = { "alice" }, onSent = { wakes++ }, minSendIntervalSeconds = minInterval, work = dispatcher)
        advanceUntilIdle()
        viewModel.selectSource(GestureSourceKind.SENSOR_BOARD)
        viewModel.setSendEnabled(true)
        viewModel.start()
        assertTrue(viewModel.ready().message ?: "", viewModel.ready().running)
        return viewModel
    }

    /** Unseen takes (5 and on) of [labels], one after another, as one stream. */
    private fun stream(vararg labels: GestureLabel) =
        SyntheticGestures.concatenate(labels.mapIndexed { i, label -> SyntheticGestures.perform(person, label, 5 + i) }).recording

    @Test
    fun squeezes_oneHugMessagePerSqueezeToTheChosenPeer() = runTest(dispatcher) {
        val viewModel = viewModel()
        source.play(stream(none, hugEnergetic, none, hugGentle, none, hugEnergetic, none))
        advanceUntilIdle()

        assertEquals(3, chats.sent.size)
        assertEquals(List(3) { HapticIcon.HUG }, chats.sent.map { it.icon })
        assertEquals(List(3) { "bob" }, chats.sent.map { it.conversation })
        assertEquals(List(3) { "alice" }, chats.sent.map { it.sender })
        assertEquals(3, wakes)
        assertEquals(3, viewModel.ready().sent.size)
        assertEquals("bob", viewModel.ready().peer)
        viewModel.stop()
        assertFalse(viewModel.ready().running)
    }

    @Test
    fun restingHand_sendsNothing() = runTest(dispatcher) {
        val viewModel = viewModel()
        source.play(stream(none, none, none, none, none, none))
        advanceUntilIdle()

        assertEquals(0, chats.sent.size)
        assertEquals(none, viewModel.ready().decision)
        assertNull(viewModel.ready().lastEvent)
    }

    @Test
    fun rateLimit_secondSqueezeInsideTheIntervalIsNotSent() = runTest(dispatcher) {
        // The stream below is about 20 s long: with a 60 s limit only the first squeeze goes out.
        viewModel(minInterval = 60.0)
        source.play(stream(none, hugEnergetic, none, hugGentle, none, hugEnergetic, none))
        advanceUntilIdle()

        assertEquals(1, chats.sent.size)
    }

    @Test
    fun sendSwitchOff_recognisesButSendsNothing() = runTest(dispatcher) {
        val viewModel = viewModel()
        viewModel.setSendEnabled(false)
        source.play(stream(none, hugEnergetic, none))
        advanceUntilIdle()

        assertEquals(0, chats.sent.size)
        assertEquals(hugEnergetic.gesture, viewModel.ready().lastEvent?.gesture)
    }

    @Test
    fun sourceWithOtherChannels_saysWhichTheModelNeeds() = runTest(dispatcher) {
        val gestures = testGestureComponent(TestGestureSource(listOf(GestureChannel("pressure")), 100.0), folder.root)
        gestures.models.save(PersonalTrainer().train(listOf(SyntheticGestures.perform(person, none, 0).labelled)))
        val viewModel = RecognitionViewModel(gestures, chats, user = { "alice" }, onSent = {}, work = dispatcher)
        advanceUntilIdle()
        viewModel.selectSource(GestureSourceKind.SENSOR_BOARD)
        viewModel.start()

        assertFalse(viewModel.ready().running)
        assertEquals("The model needs channels force, accel_x, accel_y, accel_z; Test source gives pressure", viewModel.ready().message)
    }

    /** The state once the view model's flows have run (the main dispatcher is a test dispatcher): it must be ready. */
    private fun RecognitionViewModel.ready(): RecognitionUiState.Ready {
        dispatcher.scheduler.runCurrent()
        return uiState.value as? RecognitionUiState.Ready ?: throw AssertionError("not ready: ${uiState.value}")
    }
}
