package org.hapticon.messaging.mqtt

import kotlinx.coroutines.async
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.ID_1
import org.hapticon.messaging.ID_2
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessageLimits
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.NEW_YEAR_2026
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.logging.Handler
import java.util.logging.LogRecord
import java.util.logging.Logger

class MqttMessengerTest {
    @get:Rule
    val fixture = BrokerFixture()

    // The broker is shared; every test has its own users, so nothing carries over between tests.
    private val alice = uniqueUser("alice")
    private val bob = uniqueUser("bob")
    private val hello = ChatMessage(ID_1, alice, NEW_YEAR_2026, "hello", sticker = "hug", icon = HapticIcon.KNOCK)

    @Test
    fun send_toAConnectedPeer_arrivesDecodedWithItsIcon() = runBlocking {
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        val bobInbox = CollectingListener()
        fixture.connected(bob, bobInbox)
        aliceMessenger.send(bob, hello)
        assertEquals(InboxEvent.MessageReceived(hello), bobInbox.awaitEvent())
    }

    @Test
    fun handPoses_streamIntoThePartnersInboxInOrder() = runBlocking {
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        val bobInbox = CollectingListener()
        fixture.connected(bob, bobInbox)
        val poses = (0 until 3).map { HandPose(alice, 10.0 * it, 30.9 + it, NEW_YEAR_2026 + 33L * it) }

        for (pose in poses) aliceMessenger.send(bob, pose)

        assertEquals(poses.map { InboxEvent.HandPoseReceived(it) }, bobInbox.awaitEvents(3))
    }

    @Test
    fun receipts_deliveredThenRead_flowBackToTheSender() = runBlocking {
        val aliceInbox = CollectingListener()
        val aliceMessenger = fixture.connected(alice, aliceInbox)
        val bobInbox = CollectingListener()
        val bobMessenger = fixture.connected(bob, bobInbox)
        aliceMessenger.send(bob, hello)
        val received = (bobInbox.awaitEvent() as InboxEvent.MessageReceived).message
        bobMessenger.send(received.sender, Receipt(received.id, bob, ReceiptState.DELIVERED, NEW_YEAR_2026 + 10))
        bobMessenger.send(received.sender, Receipt(received.id, bob, ReceiptState.READ, NEW_YEAR_2026 + 20))
        assertEquals(
            listOf(
                InboxEvent.ReceiptReceived(Receipt(ID_1, bob, ReceiptState.DELIVERED, NEW_YEAR_2026 + 10)),
                InboxEvent.ReceiptReceived(Receipt(ID_1, bob, ReceiptState.READ, NEW_YEAR_2026 + 20)),
            ),
            aliceInbox.awaitEvents(2),
        )
    }

    @Test
    fun publishCapabilities_ofAnotherUser_throws() {
        val bobMessenger = fixture.connected(bob, CollectingListener())
        assertThrows(IllegalArgumentException::class.java) {
            runBlocking { bobMessenger.publishCapabilities(Capabilities(alice, RendererKind.NONE, false)) }
        }
    }

    @Test
    fun hostilePayloads_areRejectedWithReasons_andTheInboxKeepsWorking() {
        val bobInbox = CollectingListener()
        fixture.connected(bob, bobInbox)
        val malloryName = uniqueUser("mallory")
        val mallory = fixture.rawClient(malloryName)
        val inbox = Topics.inbox(bob, malloryName) // the only way into bob's inbox the ACL leaves mallory
        mallory.publishQos1(inbox, "{\"schema\":".toByteArray())
        mallory.publishQos1(inbox, ByteArray(100_000) { 'x'.code.toByte() })
        mallory.publishQos1(inbox, """{"schema":"hapticon.message","version":7,"sender":"$malloryName"}""".toByteArray())
        mallory.publishQos1(inbox, String(MessageCodec.encode(hello), Charsets.UTF_8).replace("\"text\":\"hello\"", "\"text\":42").toByteArray())
        // alice's message (payload sender alice) under mallory's name: a forgery the receiver drops.
        mallory.publishQos1(inbox, MessageCodec.encode(hello))
        mallory.publishQos1(inbox, MessageCodec.encode(Receipt(ID_2, alice, ReceiptState.READ, NEW_YEAR_2026)))
        val own = hello.copy(id = ID_2, sender = malloryName)
        mallory.publishQos1(inbox, MessageCodec.encode(own))
        val events = bobInbox.awaitEvents(7)
        val rejections = events.take(6).map { (it as InboxEvent.Rejected).rejection.let { r -> r.reason to r.field } }
        assertEquals(
            "$events",
            listOf(
                RejectionReason.MALFORMED_JSON to null,
                RejectionReason.PAYLOAD_TOO_LARGE to null,
                RejectionReason.UNSUPPORTED_VERSION to "version",
                RejectionReason.WRONG_TYPE to "text",
                RejectionReason.INVALID_VALUE to "sender",
                RejectionReason.INVALID_VALUE to "from",
            ),
            rejections,
        )
        // The forged payload claims an alice (the exact suffix depends on the shared broker's user counter).
        val forgery = (events[4] as InboxEvent.Rejected).rejection.detail
        assertTrue("$events", Regex("sender alice-\\d+ on the topic of ${Regex.escape(malloryName)}").matches(forgery))
        assertEquals(InboxEvent.MessageReceived(own), events[6])
    }

    @Test
    fun oversizedPayload_isRejectedFromItsSizeAlone() {
        val bobInbox = CollectingListener()
        fixture.connected(bob, bobInbox)
        val malloryName = uniqueUser("mallory")
        fixture.rawClient(malloryName).publishQos1(Topics.inbox(bob, malloryName), ByteArray(MessageLimits.MAX_PAYLOAD_BYTES + 1))
        assertEquals(
            InboxEvent.Rejected(
                Topics.inbox(bob, malloryName),
                Decoded.Rejected(RejectionReason.PAYLOAD_TOO_LARGE, null, "65537 bytes exceed the limit of 65536"),
            ),
            bobInbox.awaitEvent(),
        )
    }

    @Test
    fun listenerThatThrows_isLoggedAndDoesNotStallTheInbox() = runBlocking {
        val logged = mutableListOf<LogRecord>()
        val logger = Logger.getLogger(MqttMessenger::class.java.name)
        val capture = object : Handler() {
            override fun publish(record: LogRecord) {
                synchronized(logged) { logged += record }
            }
            override fun flush() = Unit
            override fun close() = Unit
        }
        logger.addHandler(capture)
        logger.useParentHandlers = false // keeps the expected stack trace out of the test output
        try {
            val delivered = LinkedBlockingQueue<InboxEvent>()
            var first = true
            fixture.connected(bob, { event ->
                if (first) {
                    first = false
                    throw IllegalStateException("listener bug")
                }
                delivered.put(event)
            })
            val aliceMessenger = fixture.connected(alice, CollectingListener())
            aliceMessenger.send(bob, hello)
            aliceMessenger.send(bob, hello.copy(id = ID_2))
            assertEquals(InboxEvent.MessageReceived(hello.copy(id = ID_2)), delivered.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
            val record = synchronized(logged) { logged.single() }
            assertEquals("inbox listener of $bob failed; message acknowledged anyway", record.message)
            assertEquals("listener bug", record.thrown.message)
        } finally {
            logger.removeHandler(capture)
            logger.useParentHandlers = true
        }
    }

    @Test
    fun publishCapabilities_isRetainedForUsersWhoConnectLater() = runBlocking {
        val bobCapabilities = Capabilities(bob, RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 34, resonantFrequencyHz = 170.0)
        val bobInbox = CollectingListener()
        val bobMessenger = fixture.connected(bob, bobInbox)
        bobMessenger.publishCapabilities(bobCapabilities)
        // Bob was subscribed when he published: his own copy is a live one (RETAIN 0).
        assertEquals(InboxEvent.CapabilitiesReceived(bobCapabilities, retained = false), bobInbox.awaitEvent())
        val aliceInbox = CollectingListener()
        fixture.connected(alice, aliceInbox)
        // Alice gets the stored copy because she just subscribed (RETAIN 1, MQTT 3.1.1 §3.3.1.3).
        assertEquals(InboxEvent.CapabilitiesReceived(bobCapabilities, retained = true), aliceInbox.awaitEvent())
        // An empty retained message deletes it, so later tests on the shared broker do not receive it. Only bob
        // may write bob's capabilities, and only one client can be bob at a time.
        bobMessenger.disconnect()
        fixture.rawClient(bob).publishQos1(Topics.capabilities(bob), ByteArray(0), retain = true)
    }

    /**
     * What the app's "has this user ever connected" rests on: a client that connects gets every stored capabilities
     * message (RETAIN 1), and the live copy of the capabilities it then publishes itself comes after all of them.
     */
    @Test
    fun connect_retainedDirectoryArrivesBeforeTheLiveCopyOfOwnCapabilities() = runBlocking {
        val bobCapabilities = Capabilities(bob, RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 34)
        val bobMessenger = fixture.connected(bob, CollectingListener())
        bobMessenger.publishCapabilities(bobCapabilities)
        bobMessenger.disconnect()
        val aliceInbox = CollectingListener()
        val aliceMessenger = fixture.connected(alice, aliceInbox)
        val aliceCapabilities = Capabilities(alice, RendererKind.ON_OFF, amplitudeControl = false, apiLevel = 35)
        aliceMessenger.publishCapabilities(aliceCapabilities)
        // Other tests' users may have left capabilities on the shared broker: read up to alice's own live copy.
        val own = InboxEvent.CapabilitiesReceived(aliceCapabilities, retained = false)
        val before = generateSequence { aliceInbox.awaitEvent() }.takeWhile { it != own }.toList()
        assertTrue(before.contains(InboxEvent.CapabilitiesReceived(bobCapabilities, retained = true)))
        assertTrue("$before", before.all { it is InboxEvent.CapabilitiesReceived && it.retained })
        aliceMessenger.disconnect()
        for (user in listOf(alice, bob)) fixture.rawClient(user).publishQos1(Topics.capabilities(user), ByteArray(0), retain = true)
    }

    @Test
    fun offlineRecipient_getsWhatWasSentMeanwhile_onItsNextConnection() = runBlocking {
        val bobMessenger = fixture.connected(bob, CollectingListener())
        bobMessenger.disconnect()
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        aliceMessenger.send(bob, hello)
        aliceMessenger.send(bob, hello.copy(id = ID_2, text = "second"))
        val bobAgain = CollectingListener()
        fixture.connected(bob, bobAgain)
        assertEquals(
            listOf(InboxEvent.MessageReceived(hello), InboxEvent.MessageReceived(hello.copy(id = ID_2, text = "second"))),
            bobAgain.awaitEvents(2),
        )
    }

    @Test
    fun connect_whileTheBrokerIsDown_waitsForItAndThenConnects() = runBlocking {
        // Nothing listens on the broker's port until it starts again. (Not a second broker on a port of its own:
        // two HiveMQ brokers in one JVM swap payloads, see OneBrokerAtATime.)
        fixture.broker.stop()
        val aliceMessenger = fixture.messenger(alice)
        val connecting = async { aliceMessenger.connect(CollectingListener()) }
        val retrying = withTimeout(20_000) { aliceMessenger.state.first { it is ConnectionState.Connecting && it.lastFailure != null } }
        assertEquals(true, (retrying as ConnectionState.Connecting).lastFailure!!.startsWith("connection refused: nothing accepts connections there"))
        fixture.broker.start()
        withTimeout(20_000) { connecting.await() }
        assertEquals(ConnectionState.Connected, aliceMessenger.state.value)
    }

    @Test
    fun connect_brokerRestarts_reconnectsByItself() = runBlocking {
        val bobInbox = CollectingListener()
        fixture.connected(bob, bobInbox)
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        fixture.broker.restart()
        // The state may still read Connected for a moment after the restart; send until alice is back.
        withTimeout(20_000) {
            while (true) {
                try {
                    aliceMessenger.send(bob, hello)
                    break
                } catch (e: MessagingException) {
                    aliceMessenger.state.first { it == ConnectionState.Connected }
                }
            }
        }
        assertEquals(InboxEvent.MessageReceived(hello), bobInbox.awaitEvent())
    }

    @Test
    fun reconnectNow_brokerBackDuringALongBackoff_connectsAtOnceNotAfterTheBackoff() = runBlocking {
        val twoMinutes = org.hapticon.messaging.RetryPolicy(initialDelayMillis = 120_000, maxDelayMillis = 120_000, jitter = 0.0)
        val slow = MqttMessenger(MqttSettings(fixture.address, alice, SharedBroker.register(alice), TestDevices.of(alice), reconnectPolicy = twoMinutes))
        try {
            slow.connect(CollectingListener())
            fixture.broker.stop()
            withTimeout(10_000) { slow.state.first { it is ConnectionState.Connecting } }
            fixture.broker.start()
            // Left alone, it waits out its two minutes although the broker is back.
            Thread.sleep(1_500)
            assertTrue(slow.state.value is ConnectionState.Connecting)

            val nudged = System.nanoTime()
            slow.reconnectNow()
            withTimeout(15_000) { slow.state.first { it == ConnectionState.Connected } }
            val seconds = (System.nanoTime() - nudged) / 1e9
            assertTrue("connected ${"%.1f".format(seconds)} s after the nudge", seconds < 15.0)
        } finally {
            slow.disconnect()
        }
    }

    @Test
    fun disconnect_whileWaitingToReconnect_staysDisconnectedEvenWhenNudged() = runBlocking {
        val twoMinutes = org.hapticon.messaging.RetryPolicy(initialDelayMillis = 120_000, maxDelayMillis = 120_000, jitter = 0.0)
        val slow = MqttMessenger(MqttSettings(fixture.address, bob, SharedBroker.register(bob), TestDevices.of(bob), reconnectPolicy = twoMinutes))
        slow.connect(CollectingListener())
        fixture.broker.stop()
        withTimeout(10_000) { slow.state.first { it is ConnectionState.Connecting } }
        slow.disconnect()
        fixture.broker.start()
        slow.reconnectNow()
        Thread.sleep(1_500)
        assertEquals(ConnectionState.Disconnected, slow.state.value)
    }

    @Test
    fun ping_connected_brokerAnswers_andTheInboxStaysSubscribed() = runBlocking {
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        val bobInbox = CollectingListener()
        val bobMessenger = fixture.connected(bob, bobInbox)
        assertTrue(bobMessenger.ping(5_000))
        assertTrue(bobMessenger.ping(5_000))
        // The round trip's UNSUBSCRIBE named a filter bob never subscribed: his inbox still receives.
        aliceMessenger.send(bob, hello)
        assertEquals(InboxEvent.MessageReceived(hello), bobInbox.awaitEvent())
    }

    @Test
    fun ping_notConnectedOrBrokerGone_false() = runBlocking {
        assertEquals(false, fixture.messenger(alice).ping(1_000))
        val bobMessenger = fixture.connected(bob, CollectingListener())
        fixture.broker.stop()
        try {
            withTimeout(10_000) { bobMessenger.state.first { it is ConnectionState.Connecting } }
            assertEquals(false, bobMessenger.ping(1_000))
        } finally {
            fixture.broker.start()
        }
    }

    @Test
    fun send_whenNotConnected_throwsMessagingException() {
        val aliceMessenger = fixture.messenger(alice)
        val e = assertThrows(MessagingException::class.java) { runBlocking { aliceMessenger.send(bob, hello) } }
        assertEquals("not connected (disconnected)", e.message)
    }

    @Test
    fun disconnect_afterConnect_endsDisconnected() = runBlocking {
        val aliceMessenger = fixture.connected(alice, CollectingListener())
        assertEquals(ConnectionState.Connected, aliceMessenger.state.value)
        aliceMessenger.disconnect()
        assertEquals(ConnectionState.Disconnected, aliceMessenger.state.value)
        assertThrows(IllegalStateException::class.java) { runBlocking { aliceMessenger.connect(CollectingListener()) } }
        Unit
    }
}
