package org.hapticon.app.feature.chat

import android.content.Context
import android.os.Bundle
import android.os.Vibrator
import android.view.View
import android.view.ViewGroup
import android.view.accessibility.AccessibilityManager
import android.view.accessibility.AccessibilityNodeInfo
import android.view.accessibility.AccessibilityNodeProvider
import androidx.activity.ComponentActivity
import androidx.compose.runtime.collectAsState
import androidx.compose.runtime.getValue
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.Capabilities
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * Sending and feeling an icon the way TalkBack does it: not through Compose's test finders but through the
 * Android accessibility layer TalkBack reads — the compose view's [AccessibilityNodeProvider], its virtual
 * [AccessibilityNodeInfo]s found by what TalkBack speaks (content description or text) and the standard actions
 * (ACTION_CLICK, ACTION_LONG_CLICK, ACTION_SET_TEXT) performed on them, with the labels TalkBack announces
 * ("double-tap to add to message", "double-tap and hold to feel knock here").
 */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h1600dp")
class TalkBackSendTest {
    @get:Rule
    val compose = createAndroidComposeRule<ComponentActivity>()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator = context.getSystemService(Vibrator::class.java)
    private lateinit var db: HapticonDatabase
    private lateinit var repository: OfflineFirstChatRepository

    @Before
    fun setUp() {
        // What TalkBack switches on: Compose builds its accessibility nodes only while a touch-exploring service runs.
        val accessibility = context.getSystemService(AccessibilityManager::class.java)
        shadowOf(accessibility).setEnabled(true)
        shadowOf(accessibility).setTouchExplorationEnabled(true)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).allowMainThreadQueries().build()
        repository = OfflineFirstChatRepository(db, clock = { 1_767_225_600_000 })
        val viewModel = ConversationViewModel(
            "bob", { "alice" }, repository, RoomIconRepository(db.iconDao()),
            AdaptiveHapticPlayer(vibrator, { DeviceCapabilities(true, true, 35) }, { null }),
            MutableStateFlow<Map<String, Capabilities>>(emptyMap()), {},
        )
        compose.setContent {
            val state by viewModel.uiState.collectAsState()
            ConversationScreen(
                state,
                ConversationActions(
                    onSend = { viewModel.send(it) }, onSelectIcon = viewModel::selectIcon, onSelectSticker = viewModel::selectSticker,
                    onPreview = viewModel::play, onFeel = viewModel::feel,
                ),
            )
        }
        compose.waitUntil(5_000) { talkBack().find("Message") != null }
    }

    @After
    fun tearDown() = db.close()

    private fun stored() = runBlocking { repository.messages("bob").first() }

    private fun talkBack() = TalkBack(composeView(compose.activity.window.decorView)!!)

    private fun composeView(view: View): View? {
        if (view.javaClass.name == "androidx.compose.ui.platform.AndroidComposeView") return view
        if (view is ViewGroup) for (i in 0 until view.childCount) composeView(view.getChildAt(i))?.let { return it }
        return null
    }

    @Test
    fun composerAndSend_throughAccessibilityActions_storeTheMessageWithItsIcon() {
        val knock = talkBack().find("Icon knock")!!
        assertEquals("Add to message", knock.actionLabel(AccessibilityNodeInfo.ACTION_CLICK))
        assertEquals("Feel knock here", knock.actionLabel(AccessibilityNodeInfo.ACTION_LONG_CLICK))
        assertEquals("not selected", knock.info.stateDescription)

        // Double-tap and hold: the preview plays on this phone and nothing is chosen.
        knock.perform(AccessibilityNodeInfo.ACTION_LONG_CLICK)
        compose.waitUntil(5_000) { lastVibration(vibrator) != null }
        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
        // Double-tap: chosen, and TalkBack now offers to remove it.
        knock.perform(AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitForIdle()
        val chosen = talkBack().find("Icon knock")!!
        assertEquals("selected", chosen.info.stateDescription)
        assertEquals("Remove from message", chosen.actionLabel(AccessibilityNodeInfo.ACTION_CLICK))

        talkBack().find("Message")!!.perform(
            AccessibilityNodeInfo.ACTION_SET_TEXT,
            Bundle().apply { putCharSequence(AccessibilityNodeInfo.ACTION_ARGUMENT_SET_TEXT_CHARSEQUENCE, "feel this") },
        )
        compose.waitForIdle()
        talkBack().find("Send")!!.perform(AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { stored().isNotEmpty() }

        val message = stored().single()
        assertEquals("feel this", message.text)
        assertEquals(HapticIcon.KNOCK, message.icon)
        // The composer is cleared for the next message.
        compose.waitUntil(5_000) { talkBack().find("Icon knock")?.info?.stateDescription == "not selected" }
    }

    @Test
    fun sentIcon_doubleTapThroughAccessibility_isFelt() {
        runBlocking { repository.send("alice", "bob", "hug", null, HapticIcon.HUG) }
        compose.waitUntil(5_000) { talkBack().find("Play haptic icon hug") != null }
        assertNull(lastVibration(vibrator))

        talkBack().find("Play haptic icon hug")!!.perform(AccessibilityNodeInfo.ACTION_CLICK)
        compose.waitUntil(5_000) { lastVibration(vibrator) != null }
        // The hug's own step waveform, as the player renders it for an amplitude-controlled vibrator.
        assertEquals(VibrationWaveform.render(HapticIcon.HUG).timings().toList(), lastVibration(vibrator)!!.timings)
    }

    /** A virtual node as TalkBack sees it, and the actions it can perform on it. */
    private class Node(private val provider: AccessibilityNodeProvider, val id: Int, val info: AccessibilityNodeInfo) {
        fun actionLabel(action: Int): String? = info.actionList.firstOrNull { it.id == action }?.label?.toString()

        fun perform(action: Int, arguments: Bundle? = null) {
            check(info.actionList.any { it.id == action }) { "${info.contentDescription ?: info.text} offers no action $action: ${info.actionList}" }
            check(provider.performAction(id, action, arguments)) { "action $action on ${info.contentDescription ?: info.text} failed" }
        }
    }

    /** Walks the compose view's virtual accessibility tree from its root, as an accessibility service does. */
    private class TalkBack(private val view: View) {
        private val provider = checkNotNull(view.accessibilityNodeProvider) { "no accessibility node provider: is accessibility on?" }

        /** The node TalkBack reads as [spoken] (its description or text starts so), preferring one that can be clicked. */
        fun find(spoken: String): Node? = nodes()
            .filter { listOfNotNull(it.info.contentDescription, it.info.text).any { t -> t.toString().startsWith(spoken) } }
            .sortedByDescending { node -> node.info.actionList.any { it.id == AccessibilityNodeInfo.ACTION_CLICK } }
            .firstOrNull()

        private fun nodes(): List<Node> {
            val found = ArrayList<Node>()
            val queue = ArrayDeque(listOf(AccessibilityNodeProvider.HOST_VIEW_ID))
            while (queue.isNotEmpty()) {
                val id = queue.removeFirst()
                val info = provider.createAccessibilityNodeInfo(id) ?: continue
                if (id != AccessibilityNodeProvider.HOST_VIEW_ID && info.isVisibleToUser) found += Node(provider, id, info)
                // getChildId is hidden API: a child's id packs the virtual descendant id into the upper 32 bits.
                for (i in 0 until info.childCount) queue += (CHILD_ID.invoke(info, i) as Long shr 32).toInt()
            }
            return found
        }

        private companion object {
            val CHILD_ID = AccessibilityNodeInfo::class.java.getMethod("getChildId", Int::class.javaPrimitiveType)
        }
    }
}
