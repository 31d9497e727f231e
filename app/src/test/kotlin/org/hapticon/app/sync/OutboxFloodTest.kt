package org.hapticon.app.sync

import android.content.Context
import android.os.Vibrator
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import java.util.Collections
import java.util.concurrent.CompletableFuture
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.usageVibrator
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.Topics
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.broker.BrokerLimits
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import kotlin.coroutines.EmptyCoroutineContext

/**
 * The flood against the app's own outbox: a participant (carol) publishes 10,100 messages into bob's inbox as fast as
 * the embedded broker (a child JVM) takes them, while alice types [ALICES] messages in the app. They go the app's way:
 * Room's outbox, ChatSync's sender, the real MQTT messenger. When bob comes online he gets carol's share of his queue
 * and every one of alice's; his delivered receipts bring each of alice's rows to DELIVERED and empty her outbox.
 * The figures are printed (docs/security.md's flood row).
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class OutboxFloodTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val fast = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500, jitter = 0.0)
    private val bobDevice = DeviceId.generate()
    private val messengers = mutableListOf<MqttMessenger>()
    private lateinit var broker: BrokerProcess
    private lateinit var address: BrokerAddress
    private lateinit var db: HapticonDatabase

    @After
    fun tearDown() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin()
        messengers.forEach { runCatching { it.disconnect() } }
        if (::db.isInitialized) db.close()
        if (::broker.isInitialized) broker.stop()
    }

    private fun bob(listener: InboxListener = InboxListener { }): MqttMessenger =
        MqttMessenger(MqttSettings(address, "bob", "bob-secret", bobDevice, reconnectPolicy = fast)).also {
            messengers += it
            runBlocking { it.connect(listener) }
        }

    @Test
    fun flood_tenThousandMessagesIntoBobsInbox_alicesAppMessagesAllDelivered() = runBlocking {
        broker = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).also { it.start() }
        address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
        // bob's phone has a session on the broker and is away: the broker queues for him.
        bob().disconnect()

        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
        val repository = OfflineFirstChatRepository(db)
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = address.toString(), brokerPassword = "alice-secret"))
        val sends = AtomicInteger()
        val alicePhone = DeviceId.generate()
        val sync = ChatSync(
            repository, repository, settings,
            { user, url, password ->
                val real = MqttMessenger(MqttSettings(BrokerAddress.parse(url), user, password, alicePhone, reconnectPolicy = fast)).also { messengers += it }
                object : Messenger by real {
                    override suspend fun send(recipient: String, message: ChatMessage) {
                        sends.incrementAndGet()
                        real.send(recipient, message)
                    }
                }
            },
            AdaptiveHapticPlayer(usageVibrator(context.getSystemService(Vibrator::class.java)), { device }, { null }, renderContext = EmptyCoroutineContext),
            VibrationRateLimiter(Clock.MONOTONIC), { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        )
        sync.start()
        withTimeout(30_000) { sync.connection.first { it == ConnectionState.Connected } }

        // carol's flood: every publish handed to her client at once; alice types while the broker works through them.
        val carol = MqttClient.builder().useMqttVersion3().identifier("carol:" + DeviceId.generate().value)
            .serverHost(address.host).serverPort(address.port)
            .simpleAuth().username("carol").password("carol-secret".toByteArray()).applySimpleAuth()
            .buildAsync()
        carol.connect().get(30, TimeUnit.SECONDS)
        val floodStart = System.nanoTime()
        val acks = List(FLOOD) {
            carol.publishWith().topic(Topics.inbox("bob", "carol")).qos(MqttQos.AT_LEAST_ONCE)
                .payload(MessageCodec.encode(ChatMessage.compose("carol", "spam $it"))).send()
        }
        val typed = List(ALICES) { n ->
            repository.send("alice", "bob", "alice $n, under the flood").also { sync.wake() }.id.also { delay(20) }
        }
        val acknowledgedDuringFlood = acks.count { it.isDone }
        CompletableFuture.allOf(*acks.toTypedArray()).get(180, TimeUnit.SECONDS)
        val floodSeconds = (System.nanoTime() - floodStart) / 1e9
        carol.disconnect().get(30, TimeUnit.SECONDS)
        // The broker acknowledged all of alice's: her rows read SENT (one tick), still in the outbox until bob's receipt.
        awaitRows("alice's $ALICES acknowledged by the broker", repository) { states -> states.all { it == MessageState.SENT } }
        assertEquals(typed.toSet(), repository.pending().map { it.message.id }.toSet())

        // bob comes online and answers every message of alice's with a delivered receipt, as his app does.
        val spam = AtomicInteger()
        val fromAlice = Collections.synchronizedList(mutableListOf<String>())
        val bobStart = System.nanoTime()
        lateinit var online: MqttMessenger
        online = bob { event ->
            val message = (event as? InboxEvent.MessageReceived)?.message ?: return@bob
            if (message.sender == "carol") {
                spam.incrementAndGet()
            } else {
                fromAlice += message.id
                runBlocking { online.send("alice", Receipt(message.id, "bob", ReceiptState.DELIVERED, System.currentTimeMillis())) }
            }
        }
        awaitRows("bob's receipts for all of alice's", repository) { states -> states.all { it == MessageState.DELIVERED } }
        val aliceSeconds = (System.nanoTime() - bobStart) / 1e9
        // Nothing of alice's waits any more, and bob saw each of hers (a resend may bring a copy twice).
        assertEquals(emptyList<Any>(), repository.pending())
        assertEquals(typed.toSet(), fromAlice.toSet())
        // The flood was real and held to carol's share of bob's queue.
        withTimeout(30_000) { while (spam.get() < BrokerLimits().inboxShare) delay(20) }
        delay(500)
        assertEquals(BrokerLimits().inboxShare, spam.get())
        println(
            "app outbox flood (embedded broker): carol published $FLOOD in %.1f s (%d acknowledged when alice's %d were typed); bob received %d of them; alice's %d all DELIVERED %.1f s after bob connected, sent %d times in all"
                .format(floodSeconds, acknowledgedDuringFlood, ALICES, spam.get(), ALICES, aliceSeconds, sends.get()),
        )
    }

    private suspend fun awaitRows(what: String, repository: OfflineFirstChatRepository, done: (List<MessageState>) -> Boolean) {
        suspend fun states() = repository.messages("bob").first().filter { it.outgoing }.map { it.state }
        withTimeoutOrNull(180_000) { while (states().size != ALICES || !done(states())) delay(50) }
            ?: throw AssertionError("timed out waiting for $what; alice's rows: ${states()}")
    }

    private companion object {
        // As BrokerSecurityContract's flood: 10,000 fill bob's queue, and then some.
        const val FLOOD = 10_100
        const val ALICES = 20
    }
}
