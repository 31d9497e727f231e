package org.hapticon.app.feature.chat

import android.os.Looper
import androidx.compose.ui.test.junit4.createComposeRule
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.PROCESSING_KNOCK
import org.hapticon.app.playback.lastUsage
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

/** A press on a bubble: the usage it plays with, and a felt receipt only for a received icon Android played. */
@RunWith(RobolectricTestRunner::class)
class FeelReceiptTest {
    @get:Rule val compose = createComposeRule()
    private val fixture = ComposerFixture(compose)
    private val felt = CopyOnWriteArrayList<Pair<String, String>>()
    private val viewModel = ConversationViewModel(
        "bob", { "alice" }, fixture.repository, RoomIconRepository(fixture.db.iconDao()), fixture.player(),
        MutableStateFlow<Map<String, Capabilities>>(emptyMap()), onSent = {}, onFelt = { peer, id -> felt += peer to id },
    )

    @After
    fun tearDown() = fixture.close()

    private fun received(): StoredMessage {
        runBlocking { fixture.repository.receive(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", fixture.now, "", icon = HapticIcon.KNOCK)) }
        return fixture.stored().single { !it.outgoing }
    }

    // Waits for the play, rendered off the main thread, and its continuation on the main thread.
    private fun settle(millis: Long = 5_000, until: () -> Boolean) {
        val deadline = System.currentTimeMillis() + millis
        while (!until() && System.currentTimeMillis() < deadline) {
            shadowOf(Looper.getMainLooper()).idle()
            Thread.sleep(10)
        }
        shadowOf(Looper.getMainLooper()).idle()
    }

    @Test
    fun receivedIcon_playsAsTheSendersCommunication_andIsFeltOnceItPlayed() {
        val message = received()
        viewModel.feel(message)
        settle { felt.isNotEmpty() }

        assertEquals(PROCESSING_KNOCK, lastVibration(fixture.vibrator))
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(fixture.vibrator))
        assertEquals(listOf("bob" to message.id), felt.toList())
    }

    @Test
    fun ownIcon_isATouch_andTellsNobody() {
        val own = runBlocking { fixture.repository.send("alice", "bob", "", icon = HapticIcon.KNOCK) }
        viewModel.feel(own)
        settle { lastVibration(fixture.vibrator) != null }

        assertEquals(VibrationUsage.TOUCH, lastUsage(fixture.vibrator))
        assertEquals(emptyList<Pair<String, String>>(), felt.toList())
    }

    @Test
    fun receivedIcon_thatAndroidWouldNotPlay_isNotFelt() {
        // The phone's vibrator is gone (Android's NO_VIBRATOR): nothing plays, so nothing is felt.
        shadowOf(fixture.vibrator).setHasVibrator(false)
        val message = received()
        viewModel.feel(message)
        settle(millis = 1_000) { false } // the whole second: a receipt would have had time to arrive

        assertNull(lastVibration(fixture.vibrator))
        assertEquals(emptyList<Pair<String, String>>(), felt.toList())
    }
}
