package org.hapticon.app.sync

import kotlin.coroutines.EmptyCoroutineContext
import android.content.Context
import android.os.Vibrator
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.OutboxEntity
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class ChatSyncTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator = context.getSystemService(Vibrator::class.java)
    private lateinit var db: HapticonDatabase
    private lateinit var repository: OfflineFirstChatRepository
    private lateinit var settings: InMemoryChatSettings
    private lateinit var messenger: TestMessenger
    private lateinit var sync: ChatSync
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    @Volatile private var now = 1_700_000_000_000L
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

    @Before
    fun setUp() {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
        repository = OfflineFirstChatRepository(db, clock = { now })
        settings = InMemoryChatSettings(ChatPreferences(userName = "alice"))
        messenger = TestMessenger("alice")
        start(VibrationRateLimiter(Clock { now }))
    }

    private fun start(limiter: VibrationRateLimiter) {
        sync = newSync(limiter)
        sync.start()
    }

    /** A sync over this test's repository, settings and vibrator; [factory] and [quietNow] as a test needs them. */
    private fun newSync(
        limiter: VibrationRateLimiter = VibrationRateLimiter(Clock { now }),
        factory: (String, String, String?) -> org.hapticon.messaging.Messenger? = { _, _, _ -> messenger },
        quietNow: () -> Boolean = { false },
    ) = ChatSync(
        repository, repository, settings, factory,
        // Rendered on the test's own thread: this test is about the sync (threading: MainThreadWorkTest).
        AdaptiveHapticPlayer(vibrator, { device }, { null }, renderContext = EmptyCoroutineContext), limiter,
        { user -> RendererChoice.capabilitiesOf(user, device, null, settings.preferences.value.pitchFit) }, scope, clock = { now },
        retryPolicy = RetryPolicy(initialDelayMillis = 10, maxDelayMillis = 10, jitter = 0.0), quietNow = quietNow,
    )

    @After
    fun tearDown() {
        // Stop the sync before closing the database it writes to.
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    private fun <T> await(flow: Flow<T>, predicate: (T) -> Boolean): T = runBlocking { withTimeout(5_000) { flow.first(predicate) } }

    @Test
    fun messengerCannotBeMade_connectionFailedWithWhy_nextAccountStillConnects() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.children.forEach { it.cancelAndJoin() }
        val bob = TestMessenger("bob")
        sync = newSync(factory = { user, _, _ -> if (user == "alice") throw IllegalStateException("no Keystore") else bob })
        sync.start()
        assertEquals(org.hapticon.messaging.ConnectionState.Failed("this phone cannot open a session as alice (see the log)"), await(sync.connection) { it is org.hapticon.messaging.ConnectionState.Failed })
        settings.update { it.copy(userName = "bob") }
        await(sync.connection) { it == org.hapticon.messaging.ConnectionState.Connected }
        assertEquals(org.hapticon.messaging.ConnectionState.Connected, bob.state.value)
    }

    @Test
    fun republishCapabilities_pitchFitChanged_peersGetTheNewFit() = runBlocking {
        await(messenger.published) { it.isNotEmpty() }
        assertEquals(org.hapticon.core.pattern.PitchFit.OCTAVES, messenger.published.value.last().pitchFit)
        settings.update { it.copy(pitchFit = org.hapticon.core.pattern.PitchFit.CLAMP) }
        sync.republishCapabilities()
        val published = await(messenger.published) { it.size >= 2 }
        assertEquals(org.hapticon.core.pattern.PitchFit.CLAMP, published.last().pitchFit)
    }

    @Test
    fun send_textWithIcon_outboxDrainedAndJsonHandedToMessenger() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val message = repository.send("alice", "bob", "feel this", icon = HapticIcon.KNOCK)
        sync.wake()

        val sent = await(messenger.sentMessages) { it.isNotEmpty() }.single()
        assertEquals("bob", sent.first)
        assertEquals(
            """{"schema":"hapticon.message","version":1,"id":"${message.id}","sender":"alice","sentAt":$now,"text":"feel this","sticker":null,"icon":${IconJson.encode(HapticIcon.KNOCK)}}""",
            sent.second,
        )
        await(repository.messages("bob")) { it.single().state == MessageState.SENT }
        // Kept until bob's delivered receipt arrives, then gone.
        assertEquals(listOf(message.id), db.outboxDao().pending().map { it.messageId })
        messenger.deliver(InboxEvent.ReceiptReceived(Receipt(message.id, "bob", ReceiptState.DELIVERED, now + 1)))
        assertEquals(emptyList<OutboxEntity>(), db.outboxDao().pending())
        assertEquals(MessageState.DELIVERED, repository.messages("bob").first().single().state)
    }

    @Test
    fun send_stickerWithIcon_encodesStickerAndIcon() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val message = repository.send("alice", "bob", "", sticker = "hug", icon = HapticIcon.HUG)
        sync.wake()

        val sent = await(messenger.sentMessages) { it.isNotEmpty() }.single()
        assertEquals(
            """{"schema":"hapticon.message","version":1,"id":"${message.id}","sender":"alice","sentAt":$now,"text":"","sticker":"hug","icon":${IconJson.encode(HapticIcon.HUG)}}""",
            sent.second,
        )
    }

    @Test
    fun send_brokerUnreachable_staysInOutboxWithAttempts() = runBlocking {
        messenger.failing = true
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val message = repository.send("alice", "bob", "later")
        sync.wake()

        val entry = await(db.outboxDao().pendingStream()) { it.singleOrNull()?.attempts ?: 0 >= 1 }.single()
        assertEquals(message.id, entry.messageId)
        assertEquals("broker unreachable", entry.lastError)
    }

    @Test
    fun receive_sameMessageTwice_appearsOnceAndDeliveredReceiptSent() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi", icon = HapticIcon.HIT)

        messenger.deliver(InboxEvent.MessageReceived(message))
        messenger.deliver(InboxEvent.MessageReceived(message))

        val stored = repository.messages("bob").first()
        assertEquals(listOf(message.id), stored.map { it.id })
        assertEquals(HapticIcon.HIT, stored.single().icon)
        assertEquals(Receipt(message.id, "alice", ReceiptState.DELIVERED, now), messenger.sentReceipts.value.first().second)
        // Auto-play is off by default: nothing vibrated.
        assertNull(lastVibration(vibrator))
    }

    @Test
    fun receive_conversationOpen_markedReadWithReadReceipt() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        sync.openConversation("bob")
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi")

        messenger.deliver(InboxEvent.MessageReceived(message))

        await(messenger.sentReceipts) { receipts -> receipts.any { it.second.state == ReceiptState.READ } }
        assertEquals(MessageState.READ, repository.messages("bob").first().single().state)
    }

    @Test
    fun receipts_brokerDown_keptInRoomAndSentOnceWhenTheConnectionReturns() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        sync.openConversation("bob")
        messenger.failing = true
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi")

        messenger.deliver(InboxEvent.MessageReceived(message))

        // Both receipts are owed (both at the same millisecond, so in no particular order), and nothing was sent.
        val owed = db.pendingReceiptDao().pending().sortedBy { it.state }
        assertEquals(listOf("delivered", "read"), owed.map { it.state })
        assertEquals(listOf("bob", "bob"), owed.map { it.peer })
        assertEquals(emptyList<Pair<String, Receipt>>(), messenger.sentReceipts.value)

        messenger.failing = false
        messenger.setConnection(org.hapticon.messaging.ConnectionState.Disconnected)
        await(sync.connection) { it == org.hapticon.messaging.ConnectionState.Disconnected }
        messenger.setConnection(org.hapticon.messaging.ConnectionState.Connected)

        val sent = await(messenger.sentReceipts) { it.size == 2 }
        assertEquals(
            setOf("bob" to Receipt(message.id, "alice", ReceiptState.DELIVERED, now), "bob" to Receipt(message.id, "alice", ReceiptState.READ, now)),
            sent.toSet(),
        )
        // Each row is deleted right after its send returns: wait for the last one.
        withTimeout(5_000) { while (db.pendingReceiptDao().pending().isNotEmpty()) kotlinx.coroutines.delay(10) }
    }

    @Test
    fun handshake_posesFromThePartnerReachTheirHandAndOursGoOutThroughTheMessenger() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val bob = sync.partner("bob")

        messenger.deliver(InboxEvent.HandPoseReceived(org.hapticon.messaging.HandPose("bob", 20.0, 45.0, now)))
        // Nobody asked for carol's hand: her poses are dropped.
        messenger.deliver(InboxEvent.HandPoseReceived(org.hapticon.messaging.HandPose("carol", 90.0, 90.0, now)))
        sync.sendOwnHand("bob", 50.0, 105.0)

        val angles = DoubleArray(2)
        bob.readAngles(System.nanoTime(), angles)
        assertEquals(listOf(20.0, 45.0), angles.toList())
        val sent = await(messenger.sentPoses) { it.isNotEmpty() }.single()
        assertEquals("bob" to org.hapticon.messaging.HandPose("alice", 50.0, 105.0, now), sent)
    }

    @Test
    fun receipt_readForOwnMessage_updatesState() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val own = repository.send("alice", "bob", "hi")
        messenger.deliver(InboxEvent.ReceiptReceived(Receipt(own.id, "bob", ReceiptState.READ, now + 3)))
        assertEquals(MessageState.READ, repository.messages("bob").first().single().state)
    }

    @Test
    fun receive_hostilePayload_loggedNotStoredNoVibration() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true) }

        messenger.deliverRaw("hapticon/v1/inbox/alice", """{"schema":"hapticon.message","version":1,"id":"x"}""".toByteArray())
        messenger.deliverRaw("hapticon/v1/inbox/alice", byteArrayOf(0xff.toByte(), 0x00))

        assertEquals(emptyList<Any>(), repository.conversations().first())
        assertNull(lastVibration(vibrator))
    }

    @Test
    fun autoPlay_enabled_vibratesExactWaveform() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true) }

        messenger.deliver(InboxEvent.MessageReceived(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "", icon = HapticIcon.KNOCK)))

        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
    }

    @Test
    fun autoPlay_floodFromOneSender_vibratesOnlyBurst() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true) }
        var vibrations = 0

        repeat(20) { i ->
            val id = "0b7e7c1e-3f7b-4a57-9d3e-%012d".format(i)
            vibrator.cancel()
            messenger.deliver(InboxEvent.MessageReceived(ChatMessage(id, "mallory", now, "", icon = HapticIcon.KNOCK)))
            if (shadowOf(vibrator).isVibrating) vibrations++
        }

        // The default limiter allows a burst of 3 per sender; the clock does not move, so no refill.
        assertEquals(3, vibrations)
        assertEquals(20, repository.messages("mallory").first().size)
    }

    private fun felt() = messenger.sentReceipts.value.filter { it.second.state == ReceiptState.FELT }

    @Test
    fun autoPlay_played_sendsAFeltReceiptAndTellsTheNotifierItWasFelt() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true) }
        val incoming = mutableListOf<Pair<String, Boolean>>()
        sync.onIncoming = { m, played -> incoming += m.id to played }
        val id = "0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d"

        messenger.deliver(InboxEvent.MessageReceived(ChatMessage(id, "bob", now, "", icon = HapticIcon.KNOCK)))
        messenger.deliver(InboxEvent.MessageReceived(ChatMessage(id, "bob", now, "", icon = HapticIcon.KNOCK)))

        assertEquals(listOf("bob" to Receipt(id, "alice", ReceiptState.FELT, now)), felt())
        assertEquals(listOf(id to true), incoming)
    }

    @Test
    fun autoPlay_feltReceiptsSwitchedOff_feltButNotTold() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true, sendFeltReceipts = false) }
        messenger.deliver(InboxEvent.MessageReceived(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "", icon = HapticIcon.KNOCK)))
        sync.felt("bob", "0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d")
        kotlinx.coroutines.delay(200)

        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
        assertEquals(emptyList<Pair<String, Receipt>>(), felt())
    }

    @Test
    fun autoPlay_doNotDisturb_nothingVibratesAndNoFeltReceipt() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.children.forEach { it.cancelAndJoin() }
        val quiet = newSync(quietNow = { true })
        quiet.start()
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(autoPlay = true) }
        val incoming = mutableListOf<Boolean>()
        quiet.onIncoming = { _, played -> incoming += played }
        messenger.deliver(InboxEvent.MessageReceived(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "", icon = HapticIcon.KNOCK)))

        assertNull(lastVibration(vibrator))
        assertEquals(emptyList<Pair<String, Receipt>>(), felt())
        assertEquals(listOf(false), incoming)
    }

    @Test
    fun feltReceipt_forOwnMessage_movesItToFeltAndALateReadDoesNotUndoIt() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val own = repository.send("alice", "bob", "for you", icon = HapticIcon.HUG)
        messenger.deliver(InboxEvent.ReceiptReceived(Receipt(own.id, "bob", ReceiptState.FELT, now + 5)))
        messenger.deliver(InboxEvent.ReceiptReceived(Receipt(own.id, "bob", ReceiptState.READ, now + 9)))
        messenger.deliver(InboxEvent.ReceiptReceived(Receipt(own.id, "bob", ReceiptState.DELIVERED, now + 9)))

        val row = repository.messages("bob").first().single()
        assertEquals(MessageState.FELT, row.state)
        assertEquals(now + 5, row.readAtMillis)
    }

    @Test
    fun newMessage_archivedConversation_comesBackToTheList() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        settings.update { it.copy(archived = setOf("bob", "carol")) }
        messenger.deliver(InboxEvent.MessageReceived(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi")))
        assertEquals(setOf("carol"), settings.preferences.value.archived)
    }

    @Test
    fun probe_answeringBroker_connectsTheRealSessionAndKeepsTheSettings() = runBlocking {
        val broker = org.hapticon.messaging.BrokerAddress.parse("tcp://192.168.1.20:1883")
        val problem = ChatComponent.probeBroker(settings, sync, "alice", broker, "alice-secret")
        assertNull(problem)
        val saved = settings.preferences.value
        assertEquals(listOf("alice", "tcp://192.168.1.20:1883", "alice-secret"), listOf(saved.userName, saved.brokerUrl, saved.brokerPassword))
    }

    @Test
    fun probe_brokerThatNeverAnswers_restoresThePreviousSettingsAndSaysWhy() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.children.forEach { it.cancelAndJoin() }
        // A factory that cannot make a messenger: no session ever settles, as with an unreachable broker.
        val silent = newSync(factory = { _, _, _ -> null })
        silent.start()
        val before = settings.preferences.value
        val broker = org.hapticon.messaging.BrokerAddress.parse("tcp://10.1.1.1:1883")
        val problem = ChatComponent.probeBroker(settings, silent, "carol", broker, null)
        assertEquals(true, problem!!.startsWith("No answer from tcp://10.1.1.1:1883 within 5 s."))
        assertEquals(before, settings.preferences.value)
    }

    /** The settings, recording every write (the probe's are what a screen would show). */
    private class RecordingSettings(private val inner: InMemoryChatSettings) : org.hapticon.app.data.ChatSettingsRepository {
        val writes = java.util.concurrent.CopyOnWriteArrayList<ChatPreferences>()
        override val preferences = inner.preferences
        override fun update(transform: (ChatPreferences) -> ChatPreferences) {
            inner.update(transform)
            writes += inner.preferences.value
        }
    }

    @Test
    fun probe_firstLaunch_runsTheCandidateSessionWithoutWritingUntilItAnswers() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.children.forEach { it.cancelAndJoin() }
        settings.update { ChatPreferences() }
        val made = java.util.concurrent.CopyOnWriteArrayList<String>()
        val candidate = newSync(factory = { user, broker, _ -> made += "$user at $broker"; null })
        candidate.start()
        val recording = RecordingSettings(settings)

        val problem = ChatComponent.probeBroker(recording, candidate, "carol", org.hapticon.messaging.BrokerAddress.parse("tcp://10.1.1.1:1883"), null, timeoutMillis = 300)

        assertEquals(true, problem!!.startsWith("No answer from tcp://10.1.1.1:1883 within 0 s."))
        // The session was tried as carol, while the settings (and every screen) never held her.
        assertEquals(listOf("carol at tcp://10.1.1.1:1883"), made)
        assertEquals(emptyList<ChatPreferences>(), recording.writes.toList())
        assertNull(settings.preferences.value.userName)
    }

    @Test
    fun probe_firstLaunch_answered_savesOnceWithTheOfferPending_andKeepsTheSession() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.children.forEach { it.cancelAndJoin() }
        settings.update { ChatPreferences() }
        val made = java.util.concurrent.CopyOnWriteArrayList<TestMessenger>()
        val candidate = newSync(factory = { user, _, _ -> TestMessenger(user).also { made += it } })
        candidate.start()
        val recording = RecordingSettings(settings)

        assertNull(ChatComponent.probeBroker(recording, candidate, "carol", org.hapticon.messaging.BrokerAddress.parse("tcp://10.1.1.1:1883"), "pw"))

        val saved = recording.writes.single()
        assertEquals(listOf("carol", "tcp://10.1.1.1:1883", "pw"), listOf(saved.userName, saved.brokerUrl, saved.brokerPassword))
        assertEquals(true, saved.reachableOfferPending)
        // Saving the candidate it already ran as does not start another session.
        kotlinx.coroutines.delay(200)
        assertEquals(1, made.size)
        assertEquals(org.hapticon.messaging.ConnectionState.Connected, candidate.connection.value)
    }

    @Test
    fun securityRejections_becomeWarnings_otherRejectionsOnlyLogged() = runBlocking {
        await(messenger.state) { it == org.hapticon.messaging.ConnectionState.Connected }
        val keyChanged = "bob's key changed (safety number now 1, was 2); message held back until you trust the new key"
        messenger.deliver(InboxEvent.Rejected("hapticon/v1/inbox/alice/bob", org.hapticon.messaging.Decoded.Rejected(org.hapticon.messaging.RejectionReason.MALFORMED_JSON, null, "not JSON")))
        messenger.deliver(InboxEvent.Rejected("hapticon/v1/inbox/alice/bob", org.hapticon.messaging.Decoded.Rejected(org.hapticon.messaging.RejectionReason.KEY_CHANGED, null, keyChanged)))
        assertEquals(listOf(keyChanged), await(sync.securityWarnings) { it.isNotEmpty() })
        assertEquals(setOf("bob"), sync.changedKeys.value)
        sync.keyTrusted("bob")
        assertEquals(emptySet<String>(), sync.changedKeys.value)
    }
}
