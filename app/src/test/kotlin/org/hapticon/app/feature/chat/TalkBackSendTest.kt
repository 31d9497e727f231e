package org.hapticon.app.feature.chat

import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.semantics.getOrNull
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.SemanticsNodeInteraction
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.performSemanticsAction
import androidx.compose.ui.text.AnnotatedString
import androidx.room.Room
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.ChatMessage
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config

/**
 * Sending and feeling an icon as TalkBack does it: every control is found only by what TalkBack speaks (its
 * content description and role, in the merged tree TalkBack focuses) and driven only by its accessibility
 * actions ([SemanticsActions.OnClick], [SemanticsActions.SetText]) — no touch, no test tag — through the
 * ViewModel into Room and the outbox, and back out to the vibrator.
 */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h1600dp")
class TalkBackSendTest {
    @get:Rule
    val compose = createComposeRule()

    private val fixture = ComposerFixture(compose)
    private val felt = java.util.concurrent.CopyOnWriteArrayList<Pair<String, String>>()

    @Before
    fun setUp() = fixture.show(onFelt = { peer, id -> felt += peer to id })

    @After
    fun tearDown() = fixture.close()

    private fun stored() = fixture.stored()

    /** The one control TalkBack names as [name] matches, with [role]: it must be a focusable merged node. */
    private fun control(name: SemanticsMatcher, role: Role) =
        compose.onNode(name and SemanticsMatcher.expectValue(SemanticsProperties.Role, role))

    private fun SemanticsNodeInteraction.clickLabel(): String? =
        fetchSemanticsNode().config.getOrNull(SemanticsActions.OnClick)?.label

    private fun SemanticsNodeInteraction.longClickLabel(): String? =
        fetchSemanticsNode().config.getOrNull(SemanticsActions.OnLongClick)?.label

    private fun SemanticsNodeInteraction.state(): String? =
        fetchSemanticsNode().config.getOrNull(SemanticsProperties.StateDescription)

    @Test
    fun iconChoiceAndSend_throughAccessibilityActions_storeAndQueueTheMessage() {
        val knock = control(composerIconChip("knock"), Role.Button)
        // What TalkBack announces: "knock, not selected, button, double-tap to add to message, double-tap and hold to feel knock here".
        assertEquals("Add to message", knock.clickLabel())
        assertEquals("Feel knock here", knock.longClickLabel())
        assertEquals("not selected", knock.state())

        knock.performSemanticsAction(SemanticsActions.OnClick)
        compose.waitForIdle()
        assertEquals("selected", control(composerIconChip("knock"), Role.Button).state())
        assertEquals("Remove from message", control(composerIconChip("knock"), Role.Button).clickLabel())

        compose.onNode(hasContentDescription("Message") and hasSetTextAction())
            .performSemanticsAction(SemanticsActions.SetText) { it(AnnotatedString("feel this")) }
        control(hasContentDescription("Send"), Role.Button).performSemanticsAction(SemanticsActions.OnClick)
        compose.waitUntil(5_000) { stored().isNotEmpty() }

        val message = stored().single()
        assertEquals("feel this", message.text)
        assertEquals(HapticIcon.KNOCK, message.icon)
        assertEquals(MessageState.SENDING, message.state)
        assertEquals(listOf(message.id), runBlocking { fixture.db.outboxDao().pending() }.map { it.messageId })
        // The composer is cleared for the next message: nothing chosen any more.
        compose.waitUntil(5_000) { control(composerIconChip("knock"), Role.Button).state() == "not selected" }
        // Choosing and sending played nothing on this phone.
        assertNull(lastVibration(fixture.vibrator))
    }

    @Test
    fun receivedIcon_throughItsBubblesAccessibilityAction_isFelt() {
        val hug = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_500_000, "hug", icon = HapticIcon.HUG)
        runBlocking { fixture.repository.receive(hug) }
        // The bubble is one stop for TalkBack ("bob: hug, Feel hug, 23:58"); its double-tap feels the hug.
        val bubble = hasContentDescription("bob: hug, Feel hug, ", substring = true) and hasClickAction()
        compose.waitUntil(5_000) { compose.onAllNodes(bubble).fetchSemanticsNodes().isNotEmpty() }
        assertEquals("Feel hug", compose.onNode(bubble).clickLabel())
        assertNull(lastVibration(fixture.vibrator))

        compose.onNode(bubble).performSemanticsAction(SemanticsActions.OnClick)
        compose.waitUntil(5_000) { lastVibration(fixture.vibrator) != null }
        // The hug's own step waveform, as the player renders it for an amplitude-controlled vibrator.
        assertEquals(VibrationWaveform.amplitudeSteps(HapticIcon.HUG).timings().toList(), lastVibration(fixture.vibrator)!!.timings)
        // And bob is told it was felt (the felt receipt the sync sends).
        // Told once Android played it: after the vibration, not with the press (the play's continuation on the main looper).
        compose.waitUntil(10_000) {
            org.robolectric.Shadows.shadowOf(android.os.Looper.getMainLooper()).idle()
            felt.isNotEmpty()
        }
        assertEquals(listOf("bob" to hug.id), felt.toList())
    }
}
