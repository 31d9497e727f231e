package org.hapticon.app.feature.chat

import android.accessibilityservice.AccessibilityServiceInfo
import android.graphics.Rect
import android.os.Bundle
import android.view.View
import android.view.ViewGroup
import android.view.accessibility.AccessibilityEvent
import android.view.accessibility.AccessibilityManager
import android.view.accessibility.AccessibilityNodeInfo
import android.view.accessibility.AccessibilityNodeProvider
import androidx.activity.ComponentActivity
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.ChatMessage
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * Sending and feeling an icon one level below [TalkBackSendTest]: through the `AccessibilityNodeInfo` tree TalkBack
 * itself reads, not Compose's merged semantics. With an accessibility service on and touch exploration enabled (as
 * TalkBack turns them on), the conversation screen runs in an activity and the test walks its Compose view's
 * [AccessibilityNodeProvider] from the host down, as the platform's `AccessibilityInteractionController` does for
 * TalkBack, and drives controls only with `performAction` on their virtual nodes.
 *
 * Controls are found by what TalkBack would say for them, worked out from the tree as TalkBack does:
 * - Compose exports the UNMERGED tree; a `mergeDescendants` node (every clickable, button, text field) is
 *   exported as `isScreenReaderFocusable` and TalkBack does the merging (androidx
 *   `compose/ui/ui/src/androidMain/kotlin/androidx/compose/ui/platform/accessibility/android_a11y_implementation_notes.md`,
 *   "Merging"). Such a node with children carries no `contentDescription` or role itself: Compose moves them to a
 *   "fake" rightmost child (same notes, "Fake nodes"; `AndroidComposeViewAccessibilityDelegateCompat
 *   .populateAccessibilityNodeInfoProperties` sets `contentDescription` only on a non-merging node or a leaf).
 * - TalkBack speaks a focused node's own description (its `contentDescription`, which overrides the subtree, else
 *   its text) followed by the descriptions of its visible children that are not focus stops themselves,
 *   recursively, joined with ", " (TalkBack `NodeSpeechRuleProcessor.appendDescriptionForTree`,
 *   `hasOverridingContentDescription`; `StringBuilderUtils.appendWithSeparator`). [spoken] is that rule.
 *
 * Robolectric's default `AccessibilityNodeInfo` shadow keeps no virtual child ids, so the real class is used: the
 * shadow reads the system property `robolectric.useRealAni` on every `obtain` (`ShadowAccessibilityNodeInfo
 * .useRealAni`), so this class sets it for its own tests only and restores it after.
 */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h1600dp")
class TalkBackNodeTreeTest {
    @get:Rule
    val compose = createAndroidComposeRule<ComponentActivity>()

    private val fixture = ComposerFixture(compose)
    private val felt = java.util.concurrent.CopyOnWriteArrayList<Pair<String, String>>()
    private var realAniBefore: String? = null

    @Before
    fun setUp() {
        realAniBefore = System.setProperty(REAL_ANI, "true")
        // What turning TalkBack on does to the accessibility manager the activity's views ask.
        val manager = compose.activity.getSystemService(AccessibilityManager::class.java)
        shadowOf(manager).setEnabledAccessibilityServiceList(listOf(AccessibilityServiceInfo()))
        shadowOf(manager).setTouchExplorationEnabled(true)
        shadowOf(manager).setEnabled(true)
        // The activity's own ComposeView (ComponentActivity.setContent), created after TalkBack is "on".
        fixture.show(onFelt = { peer, id -> felt += peer to id }, patterns = flowOf(listOf(RAMP)))
        compose.waitUntil(5_000) { focusStops().any { it.info.isEditable } }
    }

    @After
    fun tearDown() {
        fixture.close()
        if (realAniBefore == null) System.clearProperty(REAL_ANI) else System.setProperty(REAL_ANI, realAniBefore!!)
    }

    /** One virtual node of the Compose view: its id for the provider, the info TalkBack reads, its children. */
    private class Node(val id: Int, val info: AccessibilityNodeInfo, val children: List<Node>) {
        /**
         * A node TalkBack's focus lands on: screen-reader focusable (a merging node) or actionable
         * (TalkBack `AccessibilityNodeInfoUtils.isAccessibilityFocusable`).
         */
        val isFocusStop: Boolean
            get() = info.isVisibleToUser &&
                (info.isScreenReaderFocusable || info.isFocusable || info.isClickable || info.isLongClickable)

        /** What TalkBack says for this node, before its state and role (see the class comment). */
        val spoken: String
            get() {
                val description = info.contentDescription?.toString().orEmpty()
                if (description.isNotEmpty()) return description
                return (listOf(info.text?.toString().orEmpty()) +
                    children.filter { it.info.isVisibleToUser && !it.isFocusStop }.map { it.spoken })
                    .filter { it.isNotEmpty() }.joinToString(", ")
            }

        /**
         * The words drawn inside this node: its own text and its visible children's that are not focus stops, in the
         * order TalkBack reads them, joined as TalkBack joins them. A description is not drawn and so not included.
         */
        val visibleText: String
            get() = (listOf(info.text?.toString().orEmpty()) +
                children.filter { it.info.isVisibleToUser && !it.isFocusStop }.map { it.visibleText })
                .filter { it.isNotEmpty() }.joinToString(", ")

        fun all(): List<Node> = listOf(this) + children.flatMap { it.all() }

        fun actionLabel(action: Int): String? = info.actionList.firstOrNull { it.id == action }?.label?.toString()

        override fun toString() = "\"$spoken\" (#$id ${info.className}, text=${info.text}, hint=${info.hintText}, " +
            "cd=${info.contentDescription}, screenReaderFocusable=${info.isScreenReaderFocusable}, clickable=${info.isClickable})"
    }

    /** The view that hosts the Compose UI: the one in the activity's window that offers a node provider. */
    private fun composeView(): View {
        fun find(view: View): View? = when {
            view.accessibilityNodeProvider != null -> view
            view is ViewGroup -> (0 until view.childCount).firstNotNullOfOrNull { find(view.getChildAt(it)) }
            else -> null
        }
        return checkNotNull(find(compose.activity.window.decorView)) { "no view in the window offers an AccessibilityNodeProvider" }
    }

    private fun provider(): AccessibilityNodeProvider = composeView().accessibilityNodeProvider!!

    /**
     * The whole tree, walked from the host as the platform walks it: a child is named by a
     * `(virtualId << 32) | viewId` id (`AccessibilityNodeInfo.makeNodeId`), read with the framework's own `getChildId`.
     */
    private fun tree(): Node {
        val provider = provider()
        fun visit(id: Int): Node? {
            val info = provider.createAccessibilityNodeInfo(id) ?: return null
            val children = (0 until info.childCount).mapNotNull { visit(((GET_CHILD_ID.invoke(info, it) as Long) ushr 32).toInt()) }
            return Node(id, info, children)
        }
        var root: Node? = null
        compose.runOnUiThread { root = visit(AccessibilityNodeProvider.HOST_VIEW_ID) }
        return checkNotNull(root)
    }

    private fun focusStops(): List<Node> = tree().all().filter { it.isFocusStop }

    /** The one focus stop TalkBack speaks as [spoken]. */
    private fun control(spoken: String): Node = focusStops().let { stops ->
        val found = stops.filter { it.spoken == spoken }
        check(found.size == 1) { "expected one focus stop spoken \"$spoken\", found ${found.size} among ${stops.joinToString("\n")}" }
        found.single()
    }

    private fun perform(node: Node, action: Int, arguments: Bundle? = null) {
        var done = false
        compose.runOnUiThread { done = provider().performAction(node.id, action, arguments) }
        assertTrue("$node refused action $action", done)
        compose.waitForIdle()
    }

    /** A control TalkBack stops on and can activate, visible, at least 48 × 48 dp on screen. */
    private fun assertTalkBackTarget(node: Node) {
        assertTrue("$node is not screen-reader focusable", node.info.isScreenReaderFocusable)
        assertTrue("$node is not visible to the user", node.info.isVisibleToUser)
        assertTrue("$node is not enabled", node.info.isEnabled)
        val bounds = Rect().also { node.info.getBoundsInScreen(it) }
        val minimum = 48 * compose.activity.resources.displayMetrics.density
        assertTrue("$node is ${bounds.width()}×${bounds.height()} px, under 48 dp ($minimum px)", bounds.width() >= minimum && bounds.height() >= minimum)
    }

    @Test
    fun chooseTypeAndSend_throughTheNodeProvider_storeAndQueueTheMessage() {
        val field = control("Message")
        val knock = control("knock")
        val send = control("Send")
        assertEquals("android.widget.EditText", field.info.className)
        assertTrue(field.info.isEditable)
        for (control in listOf(field, knock, send)) assertTalkBackTarget(control)
        assertTrue(knock.info.isClickable && knock.info.isLongClickable && send.info.isClickable)
        // What TalkBack says after the name: the state, and the hints for double-tap and double-tap-and-hold.
        assertEquals("not selected", knock.info.stateDescription?.toString())
        assertEquals("Add to message", knock.actionLabel(AccessibilityNodeInfo.ACTION_CLICK))
        assertEquals("Feel knock here", knock.actionLabel(AccessibilityNodeInfo.ACTION_LONG_CLICK))

        // Double-tap: the knock goes with the message.
        perform(knock, AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { control("knock").info.stateDescription?.toString() == "selected" }
        assertEquals("Remove from message", control("knock").actionLabel(AccessibilityNodeInfo.ACTION_CLICK))

        // TalkBack's "paste"/braille/voice typing: the text field's ACTION_SET_TEXT.
        perform(field, AccessibilityNodeInfo.ACTION_SET_TEXT, Bundle().apply {
            putCharSequence(AccessibilityNodeInfo.ACTION_ARGUMENT_SET_TEXT_CHARSEQUENCE, "feel this")
        })
        compose.waitUntil(5_000) { focusStops().any { it.info.isEditable && it.info.text?.toString() == "feel this" } }
        // Typed, the field still says what it is: its text, then its name.
        assertEquals("feel this, Message", focusStops().single { it.info.isEditable }.spoken)
        perform(control("Send"), AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { fixture.stored().isNotEmpty() }

        val message = fixture.stored().single()
        assertEquals("feel this", message.text)
        assertEquals(HapticIcon.KNOCK, message.icon)
        assertEquals(MessageState.SENDING, message.state)
        assertEquals(listOf(message.id), runBlocking { fixture.db.outboxDao().pending() }.map { it.messageId })
        // The composer is emptied for the next message: the field speaks its name again, the knock is not chosen.
        compose.waitUntil(5_000) { control("knock").info.stateDescription?.toString() == "not selected" }
        assertEquals("", control("Message").info.text?.toString())
        // Choosing and sending played nothing on this phone.
        assertNull(lastVibration(fixture.vibrator))
    }

    @Test
    fun knockLongClicked_throughTheNodeProvider_isFeltHereWithItsOwnWaveform() {
        perform(control("knock"), AccessibilityNodeInfo.ACTION_LONG_CLICK)
        compose.waitUntil(5_000) { lastVibration(fixture.vibrator) != null }
        val knock = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK)
        assertEquals(RecordedVibration(knock.timings().toList(), knock.amplitudes().toList()), lastVibration(fixture.vibrator))
        // A preview chooses nothing.
        assertEquals("not selected", control("knock").info.stateDescription?.toString())
    }

    @Test
    fun receivedIcon_bubbleClickedThroughTheNodeProvider_playsItsWaveformAndTellsTheSender() {
        val hug = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_500_000, "hug", icon = HapticIcon.HUG)
        runBlocking { fixture.repository.receive(hug) }
        val spoken = "bob: hug, Feel hug, ${time(hug.sentAtMillis)}"
        compose.waitUntil(5_000) { focusStops().any { it.spoken == spoken } }
        val bubble = control(spoken)
        assertTalkBackTarget(bubble)
        assertTrue(bubble.info.isClickable)
        // "…, double-tap to Feel hug".
        assertEquals("Feel hug", bubble.actionLabel(AccessibilityNodeInfo.ACTION_CLICK))
        assertNull(lastVibration(fixture.vibrator))

        perform(bubble, AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { lastVibration(fixture.vibrator) != null }
        // The hug's own step waveform, timings and amplitudes, as the player renders it for this vibrator.
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.HUG)
        assertEquals(RecordedVibration(waveform.timings().toList(), waveform.amplitudes().toList()), lastVibration(fixture.vibrator))
        // Told once Android played it: after the vibration, not with the press.
        // After the play: its continuation runs on the main looper.
        compose.waitUntil(10_000) {
            org.robolectric.Shadows.shadowOf(android.os.Looper.getMainLooper()).idle()
            felt.isNotEmpty()
        }
        assertEquals(listOf("bob" to hug.id), felt.toList())
    }

    /**
     * WCAG 2.5.3 Label in Name: a voice-control user says what they see ("Feel hug"), so every chip's spoken name must
     * start with its visible words. Checked on every clickable focus stop with drawn words, for chips of each kind: the
     * composer's icons and pattern, a received icon and pattern, and an icon sent from here.
     */
    @Test
    fun everyChip_spokenNameStartsWithItsVisibleLabel() {
        runBlocking {
            fixture.repository.receive(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_500_000, "hug", icon = HapticIcon.HUG))
            fixture.repository.receive(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8e", "bob", 1_767_225_510_000, "ramp", pattern = RAMP))
        }
        perform(control("knock"), AccessibilityNodeInfo.ACTION_CLICK)
        perform(control("Message"), AccessibilityNodeInfo.ACTION_SET_TEXT, Bundle().apply {
            putCharSequence(AccessibilityNodeInfo.ACTION_ARGUMENT_SET_TEXT_CHARSEQUENCE, "for you")
        })
        perform(control("Send"), AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { focusStops().any { it.spoken.startsWith("You: for you, Feel knock, ") } }

        val checked = mutableMapOf<String, String>()
        fun checkVisibleChips() {
            for (stop in focusStops().filter { it.info.isClickable && it.visibleText.isNotEmpty() }) {
                assertTrue("$stop: spoken \"${stop.spoken}\" does not start with its visible words \"${stop.visibleText}\"", stop.spoken.startsWith(stop.visibleText))
                checked[stop.spoken] = stop.visibleText
            }
        }
        checkVisibleChips()
        // The pattern follows the four icons, past the 400 dp screen's edge: TalkBack's scroll action on the icon row.
        val row = tree().all().filter { node -> node.info.isScrollable && node.all().any { it.spoken == "knock" } }.minBy { it.all().size }
        while (focusStops().none { it.spoken == "ramp, pattern" }) perform(row, AccessibilityNodeInfo.ACTION_SCROLL_FORWARD)
        checkVisibleChips()

        // Each kind of composer chip was found by its drawn words, and TalkBack names it by them alone.
        val expected = mapOf("knock" to "knock", "hug" to "hug", "ramp, pattern" to "ramp, pattern")
        assertEquals(expected, checked.filterKeys { it in expected })
        // A message's "Feel …" chip is its bubble's action, and the bubble's name says the chip's words as drawn.
        for (words in listOf("Feel hug", "Feel ramp", "Feel knock")) {
            val bubble = focusStops().single { it.spoken.contains(", $words, ") }
            assertEquals(words, bubble.actionLabel(AccessibilityNodeInfo.ACTION_CLICK))
        }
    }

    /** The time under a bubble as the screen writes it (the fixture's screen uses the default zone and locale). */
    private fun time(millis: Long) = ChatClock().timeOfDay(millis)

    /**
     * TalkBack's stops as TalkBack finds them: [Node.isFocusStop] nodes, and also a node with words of its own that no
     * stop contains (TalkBack `AccessibilityNodeInfoUtils.shouldFocusNode`: text without a focusable ancestor is read
     * on its own).
     */
    private fun talkBackStops(node: Node, insideStop: Boolean = false): List<Node> {
        val own = node.info.isVisibleToUser && (node.isFocusStop ||
            (!insideStop && (!node.info.text.isNullOrEmpty() || !node.info.contentDescription.isNullOrEmpty())))
        return (if (own) listOf(node) else emptyList()) + node.children.flatMap { talkBackStops(it, insideStop || own) }
    }

    /**
     * The stops of the message list, top to bottom, by what TalkBack says for each: those under the smallest node that
     * holds every message's stop (the list), empty while there are none.
     */
    private fun messageListStops(): List<String> {
        fun isMessage(node: Node) = node.isFocusStop && (node.spoken.startsWith("You: ") || node.spoken.startsWith("bob: "))
        val nodes = tree().all()
        val count = nodes.count(::isMessage)
        val list = nodes.filter { node -> node.all().count(::isMessage) == count }.minByOrNull { it.all().size } ?: return emptyList()
        if (count == 0) return emptyList()
        return talkBackStops(list).filter { it !== list }.sortedBy { Rect().also(it.info::getBoundsInScreen).top }.map { it.spoken }
    }

    /**
     * Each message is ONE stop that says who wrote it, its words, its icon, the time and (own messages) the state;
     * nothing of a bubble (its time, its chip, its state mark) is a stop of its own. Delivered and read differ in words.
     */
    @Test
    fun eachBubble_isOneStop_sayingWhoWhatIconTimeAndState() {
        val hug = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_500_000, "Try this one", icon = HapticIcon.HUG)
        val own = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8e", "alice", 1_767_225_510_000, "Lovely")
        val second = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8f", "alice", 1_767_225_520_000, "And another")
        runBlocking {
            fixture.repository.receive(hug)
            fixture.repository.enqueue("bob", own)
            fixture.repository.enqueue("bob", second)
            fixture.repository.applyReceipt(org.hapticon.messaging.Receipt(own.id, "bob", org.hapticon.messaging.ReceiptState.READ, own.sentAtMillis + 1))
            fixture.repository.applyReceipt(org.hapticon.messaging.Receipt(second.id, "bob", org.hapticon.messaging.ReceiptState.DELIVERED, second.sentAtMillis + 1))
        }
        val expected = listOf(
            "bob: Try this one, Feel hug, ${time(hug.sentAtMillis)}",
            "You: Lovely, ${time(own.sentAtMillis)}, Read",
            "You: And another, ${time(second.sentAtMillis)}, Delivered",
        )
        compose.waitUntil(5_000) { messageListStops().containsAll(expected) }
        // Above them only the day's separator, read as it is.
        assertEquals(listOf(ChatClock().dayLabel(hug.sentAtMillis, System.currentTimeMillis())) + expected, messageListStops())
    }

    /**
     * A message arriving while the conversation is open is announced: a polite live region (TalkBack says it after
     * what it is saying, without moving the focus) changes to the message's words, and the view tells the accessibility
     * manager its content changed. Messages there when the screen opened, and the user's own, are not announced.
     */
    @Test
    fun messageArrivingWhileOpen_isAnnouncedByAPoliteLiveRegion() {
        fun announcer() = tree().all().single { it.info.liveRegion == View.ACCESSIBILITY_LIVE_REGION_POLITE && it.info.className == "android.view.View" }
        assertEquals(null, announcer().info.contentDescription)
        val manager = compose.activity.getSystemService(AccessibilityManager::class.java)
        val eventsBefore = shadowOf(manager).sentAccessibilityEvents.size

        val knock = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c90", "bob", 1_767_225_530_000, "on my way", icon = HapticIcon.KNOCK)
        runBlocking { fixture.repository.receive(knock) }
        compose.waitUntil(5_000) { announcer().info.contentDescription?.toString() == "bob: on my way, Feel knock" }
        compose.waitUntil(5_000) {
            shadowOf(manager).sentAccessibilityEvents.drop(eventsBefore).any { event ->
                event.eventType == AccessibilityEvent.TYPE_WINDOW_CONTENT_CHANGED &&
                    event.contentChangeTypes and AccessibilityEvent.CONTENT_CHANGE_TYPE_CONTENT_DESCRIPTION != 0
            }
        }

        // The user's own message is not announced: the live region keeps the last arrival's words.
        perform(control("Message"), AccessibilityNodeInfo.ACTION_SET_TEXT, Bundle().apply {
            putCharSequence(AccessibilityNodeInfo.ACTION_ARGUMENT_SET_TEXT_CHARSEQUENCE, "coming")
        })
        perform(control("Send"), AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { fixture.stored().size == 2 }
        compose.waitForIdle()
        assertEquals("bob: on my way, Feel knock", announcer().info.contentDescription?.toString())
    }

    private companion object {
        const val REAL_ANI = "robolectric.useRealAni"

        /** Up to full in 20 ms, held 20 ms, the carrier sweeping 100 → 200 Hz ([ComposerPatternSendTest]'s ramp). */
        val RAMP = HapticPattern(
            "ramp",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 1.0)),
            listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.04, 200.0)),
        )

        /** `AccessibilityNodeInfo.getChildId(int)`: hidden, the id the platform itself follows to a child. */
        val GET_CHILD_ID = AccessibilityNodeInfo::class.java.getMethod("getChildId", Int::class.javaPrimitiveType)
    }
}
