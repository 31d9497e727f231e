package org.hapticon.app.sync

import android.util.Log
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.collectLatest
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.withContext
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.messageUsage
import org.hapticon.app.playback.playMessageOffMain
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.messaging.ArrivalAlert
import org.hapticon.messaging.ArrivalAlerts
import org.hapticon.messaging.ArrivalConditions
import kotlinx.coroutines.flow.Flow
import org.hapticon.app.sensors.HandshakeLink
import org.hapticon.app.sensors.NetworkPartnerHand
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.Outbox
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import kotlinx.coroutines.coroutineScope

/**
 * The background sync: while the user has an account, keeps a [Messenger] connected, drains the Room
 * outbox through an [OutboxSender] (retries with backoff; a message stays in the outbox until the
 * receiver's receipt arrives and is sent again meanwhile), stores what arrives exactly once, answers with
 * delivered receipts (and read receipts for the conversation on screen; a receipt that cannot go out now is
 * kept in Room and sent when the connection returns), records receipts for own messages,
 * remembers peers' capabilities and, when the user enabled it, plays arriving icons after their notification, as
 * [ArrivalAlerts] decides (ringer, Do Not Disturb, the conversation's channel, what Android's vibrator would do, and
 * [rateLimiter]'s limits). Runs in the application scope from app start ([start]).
 *
 * Every receipt is true: "read" only for a conversation on screen ([openConversation] while the screen is on), "felt"
 * only for an icon Android played ([Playback.Playing] from the player, which checks Android's vibrator rules).
 *
 * Hostile input never gets past the messaging codec: a rejected payload is logged and has no effect.
 */
class ChatSync(
    private val repository: ChatRepository,
    private val outbox: Outbox,
    private val settings: ChatSettingsRepository,
    /** Makes the messenger for an account; null when the settings cannot make one (a bad broker URL). */
    private val messengerFactory: (user: String, brokerUrl: String, password: String?) -> Messenger?,
    private val player: HapticPlayer,
    private val rateLimiter: VibrationRateLimiter,
    /** What this device can do, published as the user's retained capabilities. */
    private val localCapabilities: (user: String) -> Capabilities,
    private val scope: CoroutineScope,
    private val clock: Clock = Clock.SYSTEM,
    private val retryPolicy: RetryPolicy = RetryPolicy(),
    private val nanoClock: () -> Long = System::nanoTime,
    /** The phone's ringer, Do Not Disturb and the icon channel of a peer's conversation, read when its message arrives. */
    private val arrivalConditions: (peer: String) -> ArrivalConditions = { ArrivalConditions.UNRESTRICTED },
    /** `PowerManager.isInteractive()`: a conversation counts as read only while the screen is on. */
    private val screenOn: () -> Boolean = { true },
) : HandshakeLink {
    /**
     * Told once per newly stored message while its conversation is not on screen (the notifier), before its icon plays:
     * [alert] is how it alerts ([ArrivalAlerts]), so the notification is posted on the channel that fits and the icon
     * follows it. Set before [start].
     */
    @Volatile
    var onIncoming: (message: ChatMessage, alert: ArrivalAlert) -> Unit = { _, _ -> }

    private val connectionState = MutableStateFlow<ConnectionState>(ConnectionState.Disconnected)
    // The user, broker and password that connectionState belongs to; null before the first session.
    private val sessionTarget = MutableStateFlow<SessionTarget?>(null)
    // An account being tested (first launch, a new broker in Settings): the session runs as it, while the saved
    // settings stay as they were until it answers (see [trySession]).
    private val candidate = MutableStateFlow<SessionTarget?>(null)
    private val peers = MutableStateFlow<Map<String, Capabilities>>(emptyMap())
    private val openConversations = MutableStateFlow<Set<String>>(emptySet())
    private val hands = java.util.concurrent.ConcurrentHashMap<String, NetworkPartnerHand>()
    private var job: Job? = null
    // Bumped to end the session and start a fresh one for the same account (the network changed under it).
    private val restarts = MutableStateFlow(0)
    // The default network the phone last reported; null before the first report.
    @Volatile
    private var network: String? = null

    @Volatile
    private var session: Session? = null

    private class Session(val messenger: Messenger, val sender: OutboxSender)

    /** The connection of the current account, Disconnected without one. */
    val connection: StateFlow<ConnectionState> = connectionState.asStateFlow()

    private val warnings = MutableStateFlow<List<String>>(emptyList())

    /**
     * End-to-end warnings for the user, newest last (at most [MAX_SECURITY_WARNINGS]): a peer's changed key (with
     * both safety numbers), a forged or undecryptable payload, plaintext refused. Shown, never silently dropped;
     * the refused payload itself stays in the sender's outbox.
     */
    val securityWarnings: StateFlow<List<String>> = warnings.asStateFlow()

    private val changedPeers = MutableStateFlow<Set<String>>(emptySet())

    /** Peers whose key changed and is held back until the user trusts it ([keyTrusted] takes one off). */
    val changedKeys: StateFlow<Set<String>> = changedPeers.asStateFlow()

    /** [peer]'s new key was trusted: its warning is settled. */
    fun keyTrusted(peer: String) = changedPeers.update { it - peer }

    /** The latest capabilities each peer published (retained on the broker, so known soon after connecting). */
    val peerCapabilities: StateFlow<Map<String, Capabilities>> = peers.asStateFlow()

    /** The users whose capabilities this session's messenger received, and whether that is all the broker has. */
    private data class Directory(val users: Set<String> = emptySet(), val complete: Boolean = false)

    @Volatile
    private var directory = Directory()
    private val known = MutableStateFlow<Set<String>?>(null)

    /**
     * Everyone who ever connected to the current broker, or null until that is known. Every client publishes its
     * retained capabilities on every connection (here at each Connected), so the broker's retained capabilities are a
     * directory of its users; a new subscription receives them all (RETAIN 1), and the broker queues the live copy of
     * this phone's own publish behind them, so that copy's arrival completes the directory
     * ([InboxEvent.CapabilitiesReceived.retained]; MqttMessengerTest). Users who connect later join as they publish.
     * Null again while a new session subscribes afresh, and for good when the own publish never comes back.
     */
    val knownUsers: StateFlow<Set<String>?> = known.asStateFlow()

    private fun learnUser(messenger: Messenger, event: InboxEvent.CapabilitiesReceived) {
        val user = event.capabilities.user
        val now = Directory(directory.users + user, directory.complete || (user == messenger.user && !event.retained))
        directory = now
        known.value = now.users.takeIf { now.complete }
    }

    /** Whom a session connects as. */
    data class SessionTarget(val user: String, val brokerUrl: String, val password: String?) {
        override fun toString(): String = "SessionTarget($user at $brokerUrl)" // never the password
    }

    /** Suspends until the session for [target] is Connected or Failed, and returns that state. */
    suspend fun settledStateOf(target: SessionTarget): ConnectionState =
        kotlinx.coroutines.flow.combine(sessionTarget, connectionState) { current, state -> if (current == target) state else null }
            .first { it == ConnectionState.Connected || it is ConnectionState.Failed }!!

    /**
     * Runs the session as [target] without saving it, until [block] returns: the settings (and every screen
     * that shows them) keep the saved account meanwhile. [block] saves the account when it answered; the
     * session then goes on unchanged. Not saved, the session returns to the saved account.
     */
    suspend fun <T> trySession(target: SessionTarget, block: suspend () -> T): T {
        candidate.value = target
        try {
            return block()
        } finally {
            candidate.value = null
        }
    }

    /** Starts syncing; reconnects with a new messenger whenever the user name, broker or password changes. Idempotent. */
    fun start() {
        if (job != null) return
        job = scope.launch {
            // endToEnd too: switching it makes a new (sealing or plain) messenger. A candidate under test
            // replaces the saved account; saving it afterwards maps to the same account, so the session goes on.
            val accounts = kotlinx.coroutines.flow.combine(settings.preferences, candidate) { prefs, tried ->
                val account = tried?.let { Triple(it.user, it.brokerUrl, it.password) } ?: Triple(prefs.userName, prefs.brokerUrl, prefs.brokerPassword)
                account to prefs.endToEnd
            }.distinctUntilChanged()
            kotlinx.coroutines.flow.combine(accounts, restarts) { account, _ -> account }
                .collectLatest { (target, _) ->
                    val (user, broker, password) = target
                    if (user == null) {
                        // No account: the previous session was cancelled (and disconnected) by collectLatest.
                        connectionState.value = ConnectionState.Disconnected
                        return@collectLatest
                    }
                    // Set before the session starts, so a waiter never takes the previous session's state for this one's.
                    connectionState.value = ConnectionState.Connecting(null)
                    sessionTarget.value = SessionTarget(user, broker, password)
                    val messenger = try {
                        messengerFactory(user, broker, password)
                    } catch (e: Exception) {
                        if (e is kotlinx.coroutines.CancellationException) throw e
                        // E.g. no Keystore to unwrap the end-to-end keys: say so, and keep the sync alive for the next account.
                        Log.w(TAG, "no messenger for $user: ${e.message}")
                        null
                    }
                    if (messenger == null) {
                        connectionState.value = ConnectionState.Failed("this phone cannot open a session as $user (see the log)")
                        return@collectLatest
                    }
                    runSession(messenger)
                }
        }
    }

    override val handshakePeers: Flow<List<String>> = repository.conversations().map { list -> list.map { it.peer } }

    /** The hand of [peer]; poses from anyone nobody asked for are dropped on arrival. */
    override fun partner(peer: String): NetworkPartnerHand = hands.getOrPut(peer) { NetworkPartnerHand(peer) }

    override fun sendOwnHand(peer: String, thumbDegrees: Double, middleDegrees: Double) {
        val messenger = session?.messenger ?: return
        if (messenger.state.value != ConnectionState.Connected) return
        val pose = try {
            HandPose(messenger.user, thumbDegrees, middleDegrees, clock.nowMillis())
        } catch (e: org.hapticon.messaging.InvalidMessageException) {
            return // an angle outside what a hand can do (an uncalibrated sensor) is not worth sending
        }
        scope.launch {
            // QoS 0: a lost sample is replaced by the next one; failures are expected while reconnecting.
            runCatching { messenger.send(peer, pose) }
        }
    }

    /**
     * The phone's default network is now [network] (an id that differs between networks; Android's
     * connectivity callback, see [NetworkWatcher]). A session waiting out its reconnection backoff tries
     * at once: the user is reachable again within a round trip, not after up to 30 s. A session that
     * reads Connected but was made over another network is started afresh: its socket went with the old
     * network, and keep-alive would notice only after up to 1.5 × 60 s. The session is persistent
     * (cleanSession=false) and the outbox keeps what is unsent, so a restart loses nothing.
     */
    fun networkAvailable(network: String) {
        val previous = this.network
        this.network = network
        val messenger = session?.messenger ?: return
        when (messenger.state.value) {
            is ConnectionState.Connecting -> messenger.reconnectNow()
            ConnectionState.Connected -> if (previous != null && previous != network) {
                Log.i(TAG, "default network changed: starting a fresh session")
                restarts.update { it + 1 }
            }
            else -> Unit
        }
    }

    /**
     * The keep-alive alarm woke the phone ([KeepAlive]): the MQTT client's own timers count only awake time, so
     * after a sleep its keep-alive is late and a reconnection backoff may still be waiting. Connected, one round
     * trip tells the broker the client lives and shows whether the connection does; none within
     * [KeepAlive.ROUND_TRIP_TIMEOUT_MILLIS] starts a fresh session (persistent, and the outbox keeps what is
     * unsent, so nothing is lost). Waiting to reconnect, it reconnects now. True when the broker answered.
     */
    suspend fun keepAlive(): Boolean {
        val messenger = session?.messenger ?: return false
        return when (messenger.state.value) {
            ConnectionState.Connected -> messenger.ping(KeepAlive.ROUND_TRIP_TIMEOUT_MILLIS).also { alive ->
                if (!alive && session?.messenger === messenger) {
                    Log.i(TAG, "no answer to the keep-alive: starting a fresh session")
                    restarts.update { it + 1 }
                }
            }
            is ConnectionState.Connecting -> {
                messenger.reconnectNow()
                false
            }
            else -> false
        }
    }

    /** Starts a fresh session with the same account (the client certificate changed: a new TLS handshake). */
    fun restartSession() {
        restarts.update { it + 1 }
    }

    /** Makes the outbox sender look now, after something was composed. */
    fun wake() {
        session?.sender?.wake()
    }

    /**
     * The conversation with [peer] is on screen (its screen RESUMED): marks its messages read (with read receipts), and
     * those arriving while the screen is on, until [closeConversation] (the screen paused: another app, or the screen off).
     */
    fun openConversation(peer: String) {
        openConversations.update { it + peer }
        scope.launch { if (screenOn()) markReadAndReceipt(peer) }
    }

    /** Marks [peer]'s messages read with read receipts without opening the conversation (the notification's "Mark as read"). */
    fun markRead(peer: String) {
        scope.launch { markReadAndReceipt(peer) }
    }

    /**
     * Publishes this phone's capabilities again while connected: the renderer override or the pitch fit changed in
     * Settings, and senders should see the change now, not after the next reconnection.
     */
    fun republishCapabilities() {
        val current = session ?: return
        if (connectionState.value != ConnectionState.Connected) return
        scope.launch {
            runCatching { current.messenger.publishCapabilities(localCapabilities(current.messenger.user)) }
                .onFailure { if (it is kotlinx.coroutines.CancellationException) throw it else Log.w(TAG, "publishing capabilities failed: ${it.message}") }
        }
    }

    fun closeConversation(peer: String) {
        openConversations.update { it - peer }
    }

    private suspend fun runSession(messenger: Messenger) = coroutineScope {
        val sender = OutboxSender(outbox, messenger, retryPolicy, clock)
        session = Session(messenger, sender)
        // A new messenger subscribes afresh (possibly to another broker): its directory starts empty.
        directory = Directory()
        known.value = null
        try {
            launch {
                // One collector, so every (re)connection the screens see is one that flushes what is owed. The
                // flushing runs beside it, never in it: a QoS 1 publish in flight when the connection drops is
                // kept by the HiveMQ client for the next connection, so its await ends only after the
                // reconnection, and a collector waiting on it would show Connected through the whole backoff
                // (ChatSyncReconnectTest). A new state cancels the previous connection's flush; what it did not
                // finish is flushed again on the next Connected (owed receipts stay owed until sent).
                var flush: Job? = null
                messenger.state.collect { state ->
                    flush?.cancel()
                    connectionState.value = state
                    if (state == ConnectionState.Connected) {
                        // Undispatched: the flush starts before the next state, as when it ran in the collector.
                        flush = launch(start = kotlinx.coroutines.CoroutineStart.UNDISPATCHED) {
                            runCatching { messenger.publishCapabilities(localCapabilities(messenger.user)) }
                                .onFailure { if (it is kotlinx.coroutines.CancellationException) throw it else Log.w(TAG, "publishing capabilities failed: ${it.message}") }
                            sendOwedReceipts(messenger)
                            for (peer in onScreen()) markReadAndReceipt(peer)
                        }
                    }
                }
            }
            launch { sender.run() }
            try {
                // The listener runs on the messenger's delivery thread, which may block; the message is
                // acknowledged to the broker only after it is stored, so a crash means redelivery, not loss.
                messenger.connect(InboxListener { event -> runBlocking { handle(messenger, event) } })
                // connect returns once connected; the session (and wake, felt, read receipts through it) lives
                // on until the account changes or the network moves, which cancels it. Ending this block here
                // would clear `session` under a working connection: replies and composed messages would then
                // wait for the next reconnection (found by ChatOverBrokerTest's notification reply).
                kotlinx.coroutines.awaitCancellation()
            } catch (e: Exception) {
                if (e is kotlinx.coroutines.CancellationException) throw e
                Log.w(TAG, "connection refused for good: ${e.message}")
            }
        } finally {
            session = null
            // The session ends (account changed, fresh session, app stopping): its client must go too. Left
            // running, it would reconnect under the same client id as the next session's and the broker would
            // hand the session back and forth between them (MQTT 3.1.1 §3.1.4: a second CONNECT with a client id
            // disconnects the first).
            withContext(NonCancellable) { runCatching { messenger.disconnect() } }
        }
    }

    /** Handles one inbox [event]; never throws (a bad event must not stall the inbox). */
    internal suspend fun handle(messenger: Messenger, event: InboxEvent) {
        try {
            when (event) {
                is InboxEvent.MessageReceived -> onMessage(messenger, event.message)
                is InboxEvent.ReceiptReceived -> {
                    repository.applyReceipt(event.receipt)
                    // The receiver has it: the outbox stops sending it again (OutboxSender, end to end).
                    outbox.markDelivered(event.receipt.messageId, event.receipt.from)
                }
                is InboxEvent.CapabilitiesReceived -> {
                    peers.update { it + (event.capabilities.user to event.capabilities) }
                    learnUser(messenger, event)
                }
                is InboxEvent.HandPoseReceived -> hands[event.pose.from]?.offer(event.pose, nanoClock())
                is InboxEvent.Rejected -> {
                    Log.w(TAG, "rejected payload on ${event.topic}: ${event.rejection.reason} ${event.rejection.field ?: ""} ${event.rejection.detail}")
                    if (event.rejection.reason in SECURITY_REASONS) warnings.update { (it + event.rejection.detail).takeLast(MAX_SECURITY_WARNINGS) }
                    if (event.rejection.reason == RejectionReason.KEY_CHANGED) {
                        val user = messenger.user
                        val peer = org.hapticon.messaging.Topics.inboxSender(user, event.topic) ?: org.hapticon.messaging.Topics.keysOwner(event.topic)
                        if (peer != null) changedPeers.update { it + peer }
                    }
                }
            }
        } catch (e: Exception) {
            if (e is kotlinx.coroutines.CancellationException) throw e
            Log.e(TAG, "handling $event failed", e)
        }
    }

    private suspend fun onMessage(messenger: Messenger, message: ChatMessage): Unit = coroutineScope {
        val first = repository.receive(message)
        // Stored, so the receipt is true. It is sealed and sent on another thread, and the broker's acknowledgement
        // awaited there, beside the notification and the icon rather than before them (time the user would feel:
        // docs/performance.md, "Arrival to touch"); the scope still waits for it, so the message is acknowledged to the
        // broker only after it. A repeat gets its receipt again (the first may have been lost) but never vibrates again.
        // The felt receipt may overtake it: the sender's states only move forward, whatever order receipts come in.
        launch(Dispatchers.Default) {
            sendReceipt(messenger, message.sender, Receipt(message.id, messenger.user, ReceiptState.DELIVERED, clock.nowMillis()))
        }
        if (!first) return@coroutineScope
        // A new message brings an archived conversation back to the list, as in Signal.
        if (message.sender in settings.preferences.value.archived) settings.update { it.copy(archived = it.archived - message.sender) }
        val open = message.sender in onScreen()
        if (open) markReadAndReceipt(message.sender)
        val seconds = message.icon?.duration ?: message.pattern?.duration
        val plan = ArrivalAlerts.plan(
            carriesHaptic = seconds != null,
            autoPlay = settings.preferences.value.autoPlay,
            conditions = arrivalConditions(message.sender),
            vibration = player.verdict(RECEIVED),
        ) { rateLimiter.tryAcquire(message.sender, ((seconds ?: 0.0) * 1000).toLong()) }
        if (plan.alert != ArrivalAlert.ICON && seconds != null) Log.i(TAG, "${message.id} does not play on arrival: ${plan.reason}")
        // The notification first, on the channel that fits; the icon follows it, once.
        if (!open) onIncoming(message, plan.alert)
        if (plan.alert.playsIcon) autoPlay(messenger, message)
    }

    /** Plays an arriving icon or pattern; the sender is told it was felt only when Android played it. */
    private suspend fun autoPlay(messenger: Messenger, message: ChatMessage) {
        val playback = player.playMessageOffMain(message.icon, message.pattern, RECEIVED)
        if (playback is Playback.Playing) {
            sendFelt(messenger, message.sender, message.id)
        } else {
            Log.i(TAG, "${message.id} did not play: $playback")
        }
    }

    // The conversations on screen now: open in a resumed screen, and the screen on.
    private fun onScreen(): Set<String> = if (screenOn()) openConversations.value else emptySet()

    /**
     * Android played the icon of [messageId] from [peer] at the user's request (a press on the bubble or "Feel again";
     * callers tell only of a [Playback.Playing]): tells the sender with a felt receipt unless the user switched those off.
     */
    fun felt(peer: String, messageId: String) {
        scope.launch {
            val messenger = session?.messenger
            if (messenger != null) {
                sendFelt(messenger, peer, messageId)
            } else if (settings.preferences.value.sendFeltReceipts) {
                val user = settings.preferences.value.userName ?: return@launch
                repository.queueReceipt(peer, Receipt(messageId, user, ReceiptState.FELT, clock.nowMillis()))
            }
        }
    }

    private suspend fun sendFelt(messenger: Messenger, peer: String, messageId: String) {
        if (!settings.preferences.value.sendFeltReceipts) return
        sendReceipt(messenger, peer, Receipt(messageId, messenger.user, ReceiptState.FELT, clock.nowMillis()))
    }

    private suspend fun markReadAndReceipt(peer: String) {
        val messenger = session?.messenger
        val now = clock.nowMillis()
        val read = repository.markRead(peer, now)
        val user = messenger?.user ?: settings.preferences.value.userName ?: return
        for (message in read) {
            val receipt = Receipt(message.id, user, ReceiptState.READ, now)
            if (messenger != null) sendReceipt(messenger, peer, receipt) else repository.queueReceipt(peer, receipt)
        }
    }

    /** Sends [receipt] now, or keeps it in Room for [sendOwedReceipts] when that fails. */
    private suspend fun sendReceipt(messenger: Messenger, to: String, receipt: Receipt) {
        try {
            messenger.send(to, receipt)
        } catch (e: Exception) {
            if (e is kotlinx.coroutines.CancellationException) {
                // Cancelled mid-send (the connection dropped under an on-connect flush, or the session ended):
                // whether it went out is unknown, so it is owed; a receipt sent twice changes nothing.
                kotlinx.coroutines.withContext(kotlinx.coroutines.NonCancellable) { repository.queueReceipt(to, receipt) }
                throw e
            }
            Log.w(TAG, "receipt ${receipt.state} for ${receipt.messageId} not sent now, kept for later: ${e.message}")
            repository.queueReceipt(to, receipt)
        }
    }

    /** Sends the receipts owed from earlier, oldest first; stops at the first failure (the line is down again). */
    private suspend fun sendOwedReceipts(messenger: Messenger) {
        for (owed in repository.pendingReceipts()) {
            try {
                messenger.send(owed.peer, owed.receipt)
            } catch (e: Exception) {
                if (e is kotlinx.coroutines.CancellationException) throw e
                Log.w(TAG, "owed receipts still not sent: ${e.message}")
                return
            }
            repository.receiptSent(owed.receipt)
        }
    }

    private companion object {
        const val TAG = "ChatSync"

        /** A received icon or pattern, however it plays ([messageUsage]). */
        val RECEIVED: VibrationUsage = messageUsage(outgoing = false)
        const val MAX_SECURITY_WARNINGS = 20
        val SECURITY_REASONS = setOf(
            RejectionReason.KEY_CHANGED, RejectionReason.FORGED, RejectionReason.UNDECRYPTABLE,
            RejectionReason.NOT_ENCRYPTED, RejectionReason.ENCRYPTED,
        )
    }
}

/** The current preferences' account, for screens that need to know whether one is set up. */
val ChatPreferences.hasAccount: Boolean get() = userName != null
