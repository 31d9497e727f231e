package org.hapticon.app.feature.gesture

import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.advanceTimeBy
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.gesture.FileSocialTouchModelStore
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.app.gesture.SendRecordingChatRepository
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.social.ContactFrame
import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchModel
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.io.File

/** Social touch on the pad: messages cut at a second's quiet, taught, trained with LogitBoost, classified and sent. */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class SocialTouchViewModelTest {
    @get:Rule
    val folder = TemporaryFolder()

    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val compose = createComposeRule()

    private val dispatcher = main.dispatcher
    private var now = 0.0
    private val chats = SendRecordingChatRepository(listOf("bob"))

    private fun viewModel(store: FileSocialTouchModelStore = FileSocialTouchModelStore(File(folder.root, "social.json"))) =
        SocialTouchViewModel(store, chats, user = { "alice" }, onSent = {}, clockSeconds = { now }, work = dispatcher)

    private fun SocialTouchViewModel.ready(): SocialTouchUiState.Ready {
        dispatcher.scheduler.runCurrent()
        return uiState.value as? SocialTouchUiState.Ready ?: throw AssertionError("not ready: ${uiState.value}")
    }

    /** [taps] light 0.1 s taps 0.2 s apart, from [start] s: a pat. */
    private fun pat(start: Double, taps: Int = 3): List<ContactFrame> = (0 until taps).flatMap { i ->
        val t = start + 0.3 * i
        listOf(ContactFrame(t, 0.3, 0.5, 0.5, 0.05), ContactFrame(t + 0.05, 0.35, 0.5, 0.5, 0.05), ContactFrame(t + 0.1, 0.0, 0.5, 0.5, 0.0))
    }

    /** One firm 1.5 s touch moving across the pad from [start] s: a hug-like squeeze. */
    private fun squeeze(start: Double): List<ContactFrame> =
        (0..30).map { ContactFrame(start + 0.05 * it, 0.9, 0.2 + 0.02 * it, 0.5, 0.4) } + ContactFrame(start + 1.55, 0.0, 0.8, 0.5, 0.0)

    /** Plays [frames] on the pad and waits the second of quiet that ends the message. */
    private fun TestScope.give(viewModel: SocialTouchViewModel, frames: List<ContactFrame>) {
        frames.forEach(viewModel::contact)
        now = frames.last().timeSeconds + SocialTouchMessages.DEFAULT_GAP_SECONDS
        advanceTimeBy(1_001)
        dispatcher.scheduler.runCurrent()
    }

    @Test
    fun messages_cutAfterASecondWithoutContact() {
        val cut = SocialTouchMessages()
        val frames = pat(10.0)
        frames.forEach(cut::offer)
        assertEquals(3, cut.touchesSoFar)
        val lifted = frames.last().timeSeconds
        assertNull(cut.endIfQuiet(lifted + 0.999))
        val message = cut.endIfQuiet(lifted + 1.0)!!
        assertEquals(3, message.touches)
        // A message runs from the first to the last frame in contact: 10.0 to 10.65 s.
        assertEquals(0.65, message.seconds, 1e-9)
        assertEquals(3.0, message.features[SocialTouchFeatures.NAMES.indexOf("touch_count")], 0.0)
        // The next message starts empty; nothing without a touch, and a NaN frame is skipped.
        assertNull(cut.finish())
        cut.offer(ContactFrame(20.0, Double.NaN, 0.5, 0.5, 0.1))
        assertNull(cut.finish())
    }

    @Test
    fun teachTwoClasses_trainsAStoredModel_thenRecognisesAndSendsTheMatchingIcon() = runTest(dispatcher) {
        val store = FileSocialTouchModelStore(File(folder.root, "social.json"))
        val viewModel = viewModel(store)
        advanceUntilIdle()
        assertEquals(emptyList<String>(), viewModel.ready().modelLabels)

        viewModel.setTeaching(true)
        var t = 0.0
        for ((label, gesture) in listOf("pat" to { s: Double -> pat(s) }, "hug" to { s: Double -> squeeze(s) })) {
            viewModel.setTeachLabel(label)
            repeat(4) {
                give(viewModel, gesture(t))
                t += 5.0
            }
        }
        assertEquals(mapOf("pat" to 4, "hug" to 4), viewModel.ready().examples)
        viewModel.train()
        advanceUntilIdle()
        assertEquals("Trained on 8 messages of 2 classes", viewModel.ready().message)
        assertEquals(listOf("pat", "hug"), store.model.value!!.labels)
        assertEquals(listOf("pat", "hug"), viewModel.ready().modelLabels)

        viewModel.setTeaching(false)
        viewModel.setSendEnabled(true)
        give(viewModel, squeeze(t))
        val result = viewModel.ready().latest!!
        assertEquals("hug", result.label)
        assertTrue("probability ${result.probability}", result.probability > 0.5)
        assertEquals(1, result.touches)
        advanceUntilIdle()
        assertEquals(HapticIcon.HUG, chats.sent.single().icon)
        assertEquals("hug", chats.sent.single().text)
        assertEquals("bob", chats.sent.single().conversation)

        give(viewModel, pat(t + 5.0))
        assertEquals("pat", viewModel.ready().latest!!.label)
        assertEquals("\"pat\" names no preset icon, so it was not sent", viewModel.ready().message)
        assertEquals(1, chats.sent.size)
    }

    @Test
    fun classifyFile_badCsvSaysWhere_goodCsvIsOneMessage() = runTest(dispatcher) {
        val store = FileSocialTouchModelStore(File(folder.root, "social.json"))
        // A model that splits on touch_count: 1 touch is "stroke", more is "pat".
        val examples = listOf(pat(0.0), pat(0.0, taps = 4), squeeze(0.0), squeeze(2.0)).map { SocialTouchFeatures.ofContacts(it.asSequence()) }
        store.save(SocialTouchModel(listOf("pat", "stroke"), LogitBoost.train(examples, intArrayOf(0, 0, 1, 1), 2)))
        val viewModel = viewModel(store)
        advanceUntilIdle()

        viewModel.classifyFile({ "time_s,intensity,x,y,area\n0,1,0.5,0.5,x\n".byteInputStream() }, "bad.csv")
        advanceUntilIdle()
        assertEquals("bad.csv:2: expected 5 finite numbers, got \"0,1,0.5,0.5,x\"", viewModel.ready().message)
        assertNull(viewModel.ready().latest)

        val csv = "time_s,intensity,x,y,area\n" + pat(0.0).joinToString("\n") { "${it.timeSeconds},${it.intensity},${it.x},${it.y},${it.area}" }
        viewModel.classifyFile({ csv.byteInputStream() }, "p1-pat-1.csv")
        advanceUntilIdle()
        val result = viewModel.ready().latest!!
        assertEquals("pat", result.label)
        assertEquals(3, result.touches)
        assertEquals("p1-pat-1.csv", result.source)
    }

    @Test
    fun importModel_badFileKeepsNoModelAndSaysWhy() = runTest(dispatcher) {
        val viewModel = viewModel()
        advanceUntilIdle()
        viewModel.importModel({ "{\"schema\":\"something-else\"}".byteInputStream() }, "model.json")
        advanceUntilIdle()
        assertEquals("model.json: model: schema must be \"hapticon.social-touch-model\"", viewModel.ready().message)
        assertEquals(emptyList<String>(), viewModel.ready().modelLabels)
    }

    @Test
    fun iconFor_namesAPresetAsAWholeWordOnly() {
        assertEquals(HapticIcon.HUG, SocialTouchViewModel.iconFor("hug"))
        assertEquals(HapticIcon.STROKE, SocialTouchViewModel.iconFor("Gentle-Stroke"))
        assertNull(SocialTouchViewModel.iconFor("hugging"))
        assertNull(SocialTouchViewModel.iconFor("surprise"))
    }

    @Test
    fun screen_showsTheLatestClassAndProbability() {
        val state = SocialTouchUiState.Ready(
            modelLabels = listOf("pat", "hug"),
            results = listOf(SocialTouchResult("hug", 0.87, 1, 1.6, "touch pad"), SocialTouchResult("pat", 0.9, 3, 0.7, "touch pad")),
        )
        compose.setContent { SocialTouchScreen(state, SocialTouchActions()) }
        compose.onNodeWithText("hug (87 %)").assertExists()
        compose.onNodeWithContentDescription("Recognised touch: hug").assertExists()
        compose.onNodeWithText("1 touch over 1.6 s · touch pad").assertExists()
        compose.onNodeWithText("pat (90 %) · 3 touches · touch pad").assertExists()
        compose.onNodeWithText("Model: 2 classes: pat, hug").assertExists()
    }
}
