package org.hapticon.app.sync

import android.Manifest
import android.content.Context
import android.os.PowerManager
import android.os.VibrationAttributes
import android.os.VibrationEffect
import androidx.room.Room
import java.io.File
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicLong
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.AppKeys
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AndroidVibrationGate
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.IconAudioCache
import org.hapticon.app.playback.Media3AudioCoupledOutput
import org.hapticon.app.playback.UsageVibrator
import org.hapticon.app.playback.defaultVibrator
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Implementation
import org.robolectric.annotation.Implements
import org.robolectric.shadows.ShadowSystemVibrator

/**
 * The platform's vibrator as Robolectric keeps it, noting the moment each vibration reaches it ([onHandoff]): where
 * the app's part of "arrival to touch" ends (the effect handed to `SystemVibrator`, which on a phone passes it to the
 * vibrator service).
 */
@Implements(className = "android.os.SystemVibrator", isInAndroidSdk = false)
class HandoffVibrator : ShadowSystemVibrator() {
    // SystemVibrator.vibrate(uid, opPkg, VibrationEffect, reason, VibrationAttributes), API 31+: what Vibrator.vibrate calls.
    @Implementation(minSdk = 31)
    fun vibrate(uid: Int, opPkg: String?, effect: VibrationEffect, reason: String?, attributes: VibrationAttributes) {
        onHandoff?.invoke(System.nanoTime())
        super.vibrate(uid, opPkg, effect as Any, reason, attributes as Any)
    }

    companion object {
        /** Told the `System.nanoTime` of every vibration handed to the platform. */
        @Volatile
        var onHandoff: ((Long) -> Unit)? = null
    }
}

/** The points of a received message's way through the phone, in order; each a `System.nanoTime`. */
enum class ArrivalStage(val label: String) {
    SENT("bob's send() called"),
    DECODED("delivered and decoded: the inbox listener has it"),
    STORED("stored in Room"),
    NOTIFYING("receipt handed over, arrival planned: the notifier called"),
    NOTIFIED("notification built and posted"),
    VIBRATED("first vibration handed to the platform"),
}

/**
 * One message's stamps ([ArrivalStage], 0 = not reached) and what happened to it, in order; [receiptAcked] when the
 * broker acknowledged its delivered receipt, which the phone awaits beside the notification and the icon.
 */
class Arrival(val id: String) {
    val at = LongArray(ArrivalStage.entries.size)

    @Volatile
    var receiptAcked: Long = 0L
    val events: MutableList<String> = java.util.Collections.synchronizedList(mutableListOf())

    fun stamp(stage: ArrivalStage, nanos: Long = System.nanoTime()) {
        if (at[stage.ordinal] == 0L) at[stage.ordinal] = nanos
        events += stage.name
    }

    /** Milliseconds from [from] to [to]. */
    fun millis(from: ArrivalStage, to: ArrivalStage): Double = (at[to.ordinal] - at[from.ordinal]) / 1e6
}

/**
 * The app's receive path on this Robolectric phone, wired as [ChatComponent.create] wires it (its own helpers:
 * [ChatComponent.mqttMessenger] sealing end to end with [AppKeys] under a Keystore key, [ChatComponent.chatPlayer] on
 * the platform vibrator through [UsageVibrator] and [AndroidVibrationGate], [MessageNotifier] as `onIncoming`, Room on
 * a SQLite file), against the embedded broker in a child JVM ([BrokerProcess]); bob sends from his own sealing client in
 * this JVM, so one `System.nanoTime` times the whole way. What differs from the app, and why:
 * - thin wrappers stamp the stages ([Arrival]): the messenger's listener, the repository's `receive`, the receipt send,
 *   the notifier call, and the vibrator shadow [HandoffVibrator];
 * - the vibration limiter's clock moves a minute per reading, so every icon may play as it would for messages a
 *   minute apart (the real clock would refuse all but a burst of three: the flood limit, tested in ChatSyncTest);
 * - the settings are in memory (the application's own container shares the preference file), auto-play on.
 */
class ArrivalRig(private val context: Context, dir: File) : AutoCloseable {
    private val broker = BrokerProcess(File(dir, "broker"), BrokerProcess.freePort()).also { it.start() }
    private val address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val db = Room.databaseBuilder(context, HapticonDatabase::class.java, "arrival-${broker.port}.db").build()
    private val arrivals = ConcurrentHashMap<String, Arrival>()
    private val felt = LinkedBlockingQueue<String>()
    private val spacedClock = AtomicLong()

    @Volatile
    private var current: Arrival? = null

    /** The notifications and vibrations that happened outside any message's way (none expected). */
    val strays: MutableList<String> = java.util.Collections.synchronizedList(mutableListOf())

    private val settings = InMemoryChatSettings(
        ChatPreferences(userName = "alice", brokerUrl = address.toString(), brokerPassword = "alice-secret", autoPlay = true),
    )
    val sync: ChatSync
    private val bob: MqttMessenger

    private val repository = OfflineFirstChatRepository(db)

    init {
        shadowOf(context.applicationContext as android.app.Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        val keys = AppKeys(File(dir, "e2e"))
        val devices = File(dir, "mqtt-devices")
        val vibrator = defaultVibrator(context)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        val audio = DeviceCapabilities.detect(context, vibrator)
        val device = { DeviceCapabilities.detect(context, vibrator, audio.hapticPlaybackSupported, audio.hapticGeneratorAvailable) }
        val player = ChatComponent.chatPlayer(
            UsageVibrator(vibrator, AndroidVibrationGate(context, vibrator)), device, settings,
            audio = Media3AudioCoupledOutput(context), audioCache = IconAudioCache(File(dir, "icon-audio")),
        )
        val notifier = MessageNotifier(context) { settings.preferences.value.userName }
        val power = context.getSystemService(PowerManager::class.java)
        sync = ChatSync(
            repository = StampingRepository(repository),
            outbox = repository,
            settings = settings,
            messengerFactory = { user, url, password -> ChatComponent.mqttMessenger(user, url, password, keys, devices)?.let(::StampingMessenger) },
            player = player,
            rateLimiter = VibrationRateLimiter({ spacedClock.addAndGet(60_000) }),
            localCapabilities = ChatComponent.localCapabilities(device, settings),
            scope = scope,
            arrivalConditions = notifier::arrivalConditions,
            screenOn = { power?.isInteractive ?: true },
        )
        sync.onIncoming = { message, alert ->
            val arrival = arrivals[message.id]
            arrival?.stamp(ArrivalStage.NOTIFYING) ?: strays.add("notification of ${message.id}")
            notifier.show(message, alert)
            arrival?.stamp(ArrivalStage.NOTIFIED)
        }
        HandoffVibrator.onHandoff = { nanos -> current?.stamp(ArrivalStage.VIBRATED, nanos) ?: strays.add("vibration") }
        sync.start()
        bob = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate()), EndToEnd(Identity.generate("bob"), TestKeyPins()))
        runBlocking {
            withTimeout(60_000) { sync.connection.first { it == ConnectionState.Connected } }
            bob.connect(InboxListener { event ->
                if (event is InboxEvent.ReceiptReceived && event.receipt.state == ReceiptState.FELT) felt.put(event.receipt.messageId)
            })
        }
    }

    /**
     * Sends [message] as bob and waits until alice's phone told him it was felt (after its vibration), so that the next
     * message finds the phone idle. Returns its stamps.
     */
    fun deliver(message: ChatMessage): Arrival = runBlocking {
        val arrival = Arrival(message.id)
        arrivals[message.id] = arrival
        current = arrival
        arrival.stamp(ArrivalStage.SENT)
        sendWhenKeyKnown(message)
        val answered = felt.poll(60, TimeUnit.SECONDS) ?: throw AssertionError("no felt receipt for ${message.id}; stages ${arrival.events}")
        check(answered == message.id) { "felt receipt for $answered while waiting for ${message.id}" }
        current = null
        arrival
    }

    // alice's retained key reaches bob just after he connects; until then a sealed send has no recipient key.
    private suspend fun sendWhenKeyKnown(message: ChatMessage) {
        val deadline = System.nanoTime() + 30_000_000_000L
        while (true) {
            try {
                return bob.send("alice", message)
            } catch (e: MessagingException) {
                if (System.nanoTime() > deadline) throw e
                delay(20)
            }
        }
    }

    /** The texts of bob's messages as Room holds them, oldest first. */
    suspend fun storedTexts(): List<String> = repository.messages("bob").first().map { it.text }

    /** The message bench and test send: a text with the knock icon, as the broker-load bench sends. */
    fun knock(text: String): ChatMessage = ChatMessage.compose("bob", text, null, HapticIcon.KNOCK, Clock.SYSTEM)

    override fun close() {
        HandoffVibrator.onHandoff = null
        runBlocking { runCatching { bob.disconnect() } }
        runBlocking {
            // No account: the sync ends its session (and its client) before the broker goes.
            settings.update { it.copy(userName = null) }
            runCatching { withTimeout(10_000) { sync.connection.first { it !is ConnectionState.Connected } } }
        }
        scope.cancel()
        db.close()
        broker.stop()
    }

    private inner class StampingRepository(private val real: ChatRepository) : ChatRepository by real {
        override suspend fun receive(message: ChatMessage): Boolean = real.receive(message).also { arrivals[message.id]?.stamp(ArrivalStage.STORED) }
    }

    private inner class StampingMessenger(private val real: Messenger) : Messenger by real {
        override suspend fun connect(listener: InboxListener) = real.connect(InboxListener { event ->
            if (event is InboxEvent.MessageReceived) arrivals[event.message.id]?.stamp(ArrivalStage.DECODED)
            listener.onInboxEvent(event)
        })

        override suspend fun send(recipient: String, receipt: Receipt) {
            real.send(recipient, receipt)
            if (receipt.state == ReceiptState.DELIVERED) arrivals[receipt.messageId]?.let { it.receiptAcked = System.nanoTime() }
        }
    }
}
