package org.hapticon.app.sync

import android.content.Intent
import android.os.Bundle
import android.os.Looper
import android.os.Vibrator
import androidx.core.app.RemoteInput
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.app.HapticonApplication
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.playback.lastUsage
import org.hapticon.app.playback.setProcessImportance
import org.hapticon.app.playback.setScreenOn
import org.hapticon.core.platform.AndroidVibrationRules
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.messaging.ChatMessage
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/** The message notification's actions, delivered as Android delivers them (a broadcast to the receiver). */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class NotificationActionTest {
    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val chat = app.container.chat!!

    private fun broadcast(intent: Intent) {
        app.sendBroadcast(intent.setClass(app, NotificationActionReceiver::class.java))
        shadowOf(Looper.getMainLooper()).idle()
    }

    private fun awaitTrue(what: String, condition: suspend () -> Boolean) = runBlocking {
        withTimeoutOrNull(10_000) { while (!condition()) delay(20) } ?: throw AssertionError("timed out waiting for $what")
    }

    @Test
    fun reply_typedInTheNotification_storedAsOwnMessageInTheOutbox() {
        chat.settings.update { it.copy(userName = "alice") }
        val intent = Intent(MessageNotifier.ACTION_REPLY).putExtra(MessageNotifier.EXTRA_PEER, "bob")
        RemoteInput.addResultsToIntent(
            arrayOf(RemoteInput.Builder(MessageNotifier.KEY_REPLY).build()), intent,
            Bundle().apply { putCharSequence(MessageNotifier.KEY_REPLY, "on my way") },
        )
        broadcast(intent)

        awaitTrue("the reply") { chat.repository.messages("bob").first().isNotEmpty() }
        val stored = runBlocking { chat.repository.messages("bob").first() }.single()
        assertEquals("on my way", stored.text)
        assertEquals(true, stored.outgoing)
        assertEquals(MessageState.SENDING, stored.state)
    }

    @Test
    fun markAsRead_withoutOpeningTheApp_readAndTheReadReceiptKeptForTheSender() {
        chat.settings.update { it.copy(userName = "alice") }
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8e", "bob", 1_767_225_600_000, "are you there?")
        runBlocking { chat.repository.receive(message) }
        assertEquals(1, runBlocking { chat.repository.conversations().first() }.single().unread)

        broadcast(Intent(MessageNotifier.ACTION_MARK_READ).putExtra(MessageNotifier.EXTRA_PEER, "bob"))

        awaitTrue("read") { chat.repository.conversations().first().single().unread == 0 }
        // No broker in this test: the read receipt waits in Room for the next connection.
        awaitTrue("the owed receipt") { chat.repository.pendingReceipts().isNotEmpty() }
        val owed = runBlocking { chat.repository.pendingReceipts() }.single()
        assertEquals(listOf("bob", message.id, "READ"), listOf(owed.peer, owed.receipt.messageId, owed.receipt.state.name))
    }

    @Test
    fun feelAgain_playsTheMessagesIconThroughThePlayer() {
        val vibrator = app.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_600_000, "", icon = HapticIcon.KNOCK)
        runBlocking { chat.repository.receive(message) }

        broadcast(Intent(MessageNotifier.ACTION_FEEL).putExtra(MessageNotifier.EXTRA_PEER, "bob").putExtra(MessageNotifier.EXTRA_MESSAGE, message.id))

        awaitTrue("the vibration") { lastVibration(vibrator) != null }
        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
        // The sender's icon, replayed: a communication request, as on arrival.
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
    }

    private fun owedFelt(id: String) = runBlocking { chat.repository.pendingReceipts() }.filter { it.receipt.messageId == id && it.receipt.state.name == "FELT" }

    @Test
    fun feelAgain_fromTheShadeWithTheAppSwipedAwayAndTheScreenOff_playsAndIsFelt() {
        chat.settings.update { it.copy(userName = "alice") }
        val vibrator = app.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        // What Android's vibrator sees of a process woken by the shade's broadcast: not foreground, screen off.
        setProcessImportance(AndroidVibrationRules.IMPORTANCE_CACHED)
        setScreenOn(false)
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c9a", "bob", 1_767_225_600_000, "", icon = HapticIcon.KNOCK)
        runBlocking { chat.repository.receive(message) }

        broadcast(Intent(MessageNotifier.ACTION_FEEL).putExtra(MessageNotifier.EXTRA_PEER, "bob").putExtra(MessageNotifier.EXTRA_MESSAGE, message.id))

        awaitTrue("the vibration") { lastVibration(vibrator) != null }
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
        // No broker here: the felt receipt waits in Room for the next connection.
        awaitTrue("the owed felt receipt") { owedFelt(message.id).isNotEmpty() }
    }

    @Test
    fun feelAgain_whenAndroidWouldNotPlay_noFeltReceipt() {
        chat.settings.update { it.copy(userName = "alice") }
        val vibrator = app.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasVibrator(false)
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c9b", "bob", 1_767_225_600_000, "", icon = HapticIcon.KNOCK)
        runBlocking { chat.repository.receive(message) }

        broadcast(Intent(MessageNotifier.ACTION_FEEL).putExtra(MessageNotifier.EXTRA_PEER, "bob").putExtra(MessageNotifier.EXTRA_MESSAGE, message.id))
        Thread.sleep(1_000) // time enough for a receipt to be queued, were one sent

        assertEquals(null, lastVibration(vibrator))
        assertEquals(emptyList<Any>(), owedFelt(message.id))
    }

    @Test
    fun feelAgain_patternMessage_playsThePatternThroughThePlayer() {
        val vibrator = app.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        val ramp = HapticPattern(
            "ramp",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 1.0)),
            listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.04, 200.0)),
        )
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8f", "bob", 1_767_225_600_000, "", pattern = ramp)
        runBlocking { chat.repository.receive(message) }
        assertEquals("〰 ramp", chat.notifier!!.lineOf(message))

        broadcast(Intent(MessageNotifier.ACTION_FEEL).putExtra(MessageNotifier.EXTRA_PEER, "bob").putExtra(MessageNotifier.EXTRA_MESSAGE, message.id))

        awaitTrue("the vibration") { lastVibration(vibrator) != null }
        // The pattern's drive envelope in 10 ms steps (0.25 and 0.75 of the rise, then full), as PatternPlaybackTest plays it.
        assertEquals(RecordedVibration(listOf(10L, 10L, 20L), listOf(64, 191, 255)), lastVibration(vibrator))
    }
}
