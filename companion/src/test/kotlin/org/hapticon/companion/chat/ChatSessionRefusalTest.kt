package org.hapticon.companion.chat

import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.runBlocking
import org.hapticon.companion.cli.UsageException
import org.hapticon.messaging.BoundedDeduplicator
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.InboxGate
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.BufferedReader
import java.io.ByteArrayOutputStream
import java.io.PrintStream
import org.hapticon.testing.InMemoryOutbox
import java.io.StringReader
import java.util.concurrent.TimeUnit
import kotlin.concurrent.thread

/**
 * A refusal must end the chat with a non-zero exit even when the input ends before the first attempt settles,
 * or in the moment between the
 * messenger's state turning [ConnectionState.Failed] and its `connect` throwing ([MqttMessenger][org.hapticon.messaging.mqtt.MqttMessenger]
 * disconnects in between). Under load `ChatCommandTest.chat_wrongPassword_exitsTwoSayingSo` once exited 0 there.
 */
class ChatSessionRefusalTest {
    /** Stays connecting until the test [releases][release] it, then turns Failed and throws from [connect] a moment later. */
    /** A messenger that never gets connected: every publish fails as MqttMessenger's does then. */
    private abstract class NeverConnectedMessenger : Messenger {
        override suspend fun disconnect() = Unit
        override suspend fun send(recipient: String, message: ChatMessage) = throw MessagingException("not connected")
        override suspend fun send(recipient: String, receipt: Receipt) = throw MessagingException("not connected")
        override suspend fun send(recipient: String, pose: HandPose) = throw MessagingException("not connected")
        override suspend fun publishCapabilities(capabilities: Capabilities) = throw MessagingException("not connected")
    }

    private class SlowlyRefusingMessenger : NeverConnectedMessenger() {
        override val user = "alice"
        private val mutableState = MutableStateFlow<ConnectionState>(ConnectionState.Connecting(null))
        override val state: StateFlow<ConnectionState> = mutableState
        val release = CompletableDeferred<Unit>()

        override suspend fun connect(listener: InboxListener) {
            mutableState.value = ConnectionState.Connecting(lastFailure = null)
            release.await()
            mutableState.value = ConnectionState.Failed("bad user name or password")
            delay(100) // MqttMessenger disconnects between the two
            throw MessagingException("cannot connect to tcp://broker as alice: bad user name or password")
        }

    }

    @Test
    fun inputEndingBeforeTheFirstAttemptSettles_stillEndsWithTheRefusal() {
        val messenger = SlowlyRefusingMessenger()
        val err = ByteArrayOutputStream()
        val session = ChatSession(
            messenger, "bob", PrintStream(ByteArrayOutputStream()), PrintStream(err, true),
            gate = InboxGate(BoundedDeduplicator(), VibrationRateLimiter(Clock.MONOTONIC)), drainTimeoutMillis = 30_000, outbox = InMemoryOutbox(),
        )
        var thrown: Throwable? = null
        var returned = false
        // Empty input: it ends before the first attempt settles, and again before connect() throws.
        val run = thread {
            try {
                runBlocking { session.run(BufferedReader(StringReader(""))) }
                returned = true
            } catch (e: Throwable) {
                thrown = e
            }
        }
        // Long enough for the session to see the end of its input; without the wait it returned (exit 0) meanwhile.
        run.join(500)
        assertTrue("the chat ended before the refusal reached it", run.isAlive)
        messenger.release.complete(Unit)
        run.join(TimeUnit.SECONDS.toMillis(10))
        if (returned) fail("the chat ended normally after a refusal")
        assertTrue("expected the refusal, got $thrown", thrown is MessagingException || thrown is UsageException)
        assertEquals("cannot connect to tcp://broker as alice: bad user name or password", thrown!!.message)
    }

    /** Already failing to reach the broker ("still trying"): the end of the input does not wait for the next attempt. */
    private class UnreachableMessenger : NeverConnectedMessenger() {
        override val user = "alice"
        override val state: StateFlow<ConnectionState> = MutableStateFlow(ConnectionState.Connecting(lastFailure = "connection refused"))
        override suspend fun connect(listener: InboxListener) = CompletableDeferred<Unit>().await()
    }

    @Test
    fun inputEndingWhileTheBrokerIsUnreachable_endsWithoutWaitingForTheDrainTimeout() {
        val session = ChatSession(
            UnreachableMessenger(), "bob", PrintStream(ByteArrayOutputStream()), PrintStream(ByteArrayOutputStream()),
            gate = InboxGate(BoundedDeduplicator(), VibrationRateLimiter(Clock.MONOTONIC)), drainTimeoutMillis = 60_000, outbox = InMemoryOutbox(),
        )
        var returned = false
        val run = thread { runBlocking { session.run(BufferedReader(StringReader(""))) }; returned = true }
        run.join(TimeUnit.SECONDS.toMillis(20))
        assertTrue("the chat waited for an unreachable broker after its input ended", returned)
    }
}
