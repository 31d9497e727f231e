package org.hapticon.app.feature.chat

import androidx.compose.ui.semantics.SemanticsProperties
import org.hapticon.app.playback.usageVibrator
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.longClick
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToKey
import androidx.compose.ui.test.performTextInput
import androidx.compose.ui.test.performTouchInput
import androidx.room.Room
import kotlin.coroutines.EmptyCoroutineContext
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.patternFromJson
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.sync.ChatSync
import org.hapticon.app.sync.TestMessenger
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.VibrationRateLimiter
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
 * A pattern from the user's library chosen in the composer, all the way out: the tap, the stored row, the
 * outbox, and the version-2 message the messenger is handed (chat: UI → repository → outbox → broker).
 */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h1600dp")
class ComposerPatternSendTest {
    @get:Rule
    val compose = createComposeRule()

    private val fixture = ComposerFixture(compose, allowMainThreadQueries = false)
    private val vibrator = fixture.vibrator
    private val now = fixture.now
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val db = fixture.db
    private val repository = fixture.repository
    private lateinit var messenger: TestMessenger
    private lateinit var sync: ChatSync

    // Up to full in 20 ms, held 20 ms; the carrier sweeps 100 → 200 Hz (PatternPlaybackTest's ramp).
    private val ramp = HapticPattern(
        "ramp",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 1.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.04, 200.0)),
    )

    @Before
    fun setUp() {
        val patterns = RoomPatternRepository(db.patternDao(), clock = { now })
        runBlocking { patterns.save(ramp, source = "ramp.ahap") }
        val device = fixture.device
        messenger = TestMessenger("alice")
        sync = ChatSync(
            repository, repository, InMemoryChatSettings(ChatPreferences(userName = "alice")), { _, _, _ -> messenger },
            AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null }, renderContext = EmptyCoroutineContext),
            VibrationRateLimiter(Clock { now }), { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
            clock = { now },
        )
        sync.start()
        fixture.show(onSent = sync::wake, patterns = patterns.patterns().map { stored -> stored.map { it.pattern } })
        // The patterns come after the four presets, beyond a 400 dp screen's edge: scroll there as a user would.
        compose.waitUntil(5_000) {
            runCatching { compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:ramp") }.isSuccess
        }
    }

    @After
    fun tearDown() {
        // Stop the sync before closing the database it writes to.
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        fixture.close()
    }

    private fun <T> await(flow: Flow<T>, predicate: (T) -> Boolean): T = runBlocking { withTimeout(5_000) { flow.first(predicate) } }

    private fun stateOf(chip: SemanticsMatcher) =
        compose.onNode(chip).fetchSemanticsNode().config[SemanticsProperties.StateDescription]

    @Test
    fun pattern_longPressPreviewsTapReplacesTheIconAndSendTravelsAsVersion2() {
        await(messenger.state) { it == ConnectionState.Connected }
        compose.onNode(composerPatternChip("ramp")).performTouchInput { longClick() }
        compose.waitUntil(5_000) { lastVibration(vibrator) != null }
        // The preview is the pattern's own steps on this amplitude phone (API 35): 0.25, 0.75, then full.
        assertEquals(RecordedVibration(listOf(10L, 10L, 20L), listOf(64, 191, 255)), lastVibration(vibrator))
        assertEquals("not selected", stateOf(composerPatternChip("ramp")))

        // A message carries an icon or a pattern: choosing the pattern drops the icon chosen before.
        compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("hug")
        compose.onNode(composerIconChip("hug")).performClick()
        compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:ramp")
        compose.onNode(composerPatternChip("ramp")).performClick()
        assertEquals("selected", stateOf(composerPatternChip("ramp")))
        compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("hug")
        assertEquals("not selected", stateOf(composerIconChip("hug")))
        compose.onNode(hasSetTextAction()).performTextInput("feel this")
        compose.onNodeWithContentDescription("Send").performClick()

        val message = await(repository.messages("bob")) { it.isNotEmpty() }.single()
        assertEquals("feel this", message.text)
        assertNull(message.icon)
        assertEquals(ramp, message.pattern)
        // The stored row carries the pattern as pattern JSON, which reads back to the same pattern.
        val row = runBlocking { db.messageDao().message(message.id) }!!
        assertEquals(
            """{"schema":"hapticon.pattern","version":1,"name":"ramp",""" +
                """"amplitude":[{"time":0,"amplitude":0},{"time":0.02,"amplitude":1},{"time":0.04,"amplitude":1}],""" +
                """"frequency":[{"time":0,"hertz":100},{"time":0.04,"hertz":200}],"transients":[]}""",
            row.patternJson!!.filterNot { it.isWhitespace() }, // stored as the indented file text
        )
        assertEquals(ramp, patternFromJson(row.patternJson!!))
        assertNull(row.iconJson)

        // The outbox hands it to the messenger as version 2 with the pattern, and nothing else.
        compose.waitUntil(5_000) {
            // The ViewModel wakes the sync once it resumes on the main looper after Room's transaction.
            shadowOf(android.os.Looper.getMainLooper()).idle()
            messenger.sentMessages.value.isNotEmpty()
        }
        val (recipient, json) = messenger.sentMessages.value.single()
        assertEquals("bob", recipient)
        assertTrue(
            json,
            json.startsWith(
                """{"schema":"hapticon.message","version":2,"id":"${message.id}","sender":"alice","sentAt":$now,""" +
                    """"text":"feel this","sticker":null,"icon":null,"pattern":{"schema":"hapticon.pattern","version":1,"name":"ramp",""",
            ),
        )
        val decoded = (MessageCodec.decodeInbox(json.toByteArray()) as Decoded.Accepted).value as ChatMessage
        assertEquals(ramp, decoded.pattern)
        await(repository.messages("bob")) { it.single().state == MessageState.SENT }

        // The sent bubble offers the pattern like a received one, and the composer is cleared.
        compose.waitUntil(5_000) {
            compose.onAllNodes(feelChip("ramp")).fetchSemanticsNodes().isNotEmpty()
        }
        compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:ramp")
        assertEquals("not selected", stateOf(composerPatternChip("ramp")))
    }

    @Test
    fun pattern_tappedTwice_notAttached() {
        compose.onNode(composerPatternChip("ramp")).performClick()
        compose.onNode(composerPatternChip("ramp")).performClick()
        compose.onNode(hasSetTextAction()).performTextInput("plain")
        compose.onNodeWithContentDescription("Send").performClick()

        val message = await(repository.messages("bob")) { it.isNotEmpty() }.single()
        assertNull(message.pattern)
        assertNull(runBlocking { db.messageDao().message(message.id) }!!.patternJson)
    }
}
