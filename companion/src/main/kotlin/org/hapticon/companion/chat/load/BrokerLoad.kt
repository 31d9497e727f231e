package org.hapticon.companion.chat.load

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.async
import kotlinx.coroutines.awaitAll
import kotlinx.coroutines.cancel
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.drop
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.sync.Semaphore
import kotlinx.coroutines.sync.withPermit
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.broker.PasswordFile
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import java.io.File
import java.io.IOException
import java.security.SecureRandom
import java.util.Base64
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger
import kotlin.random.Random

/**
 * `hapticon bench --broker-load`: [users] simulated people on one broker, each with its own user name, password and
 * device (client id USER:DEVICE), connected as the app connects ([MqttMessenger]: QoS 1 inbox, persistent session,
 * the shipped ACL), each sending a text with the knock icon to a random other user every [minIntervalMillis] to
 * [maxIntervalMillis] (uniformly), and answering every message with a delivered receipt as the app does. With
 * [burst] > 0 every user also sends [burst] messages at once, twice in the run (at a third and at two thirds of it),
 * as a room of participants answering the same cue would.
 *
 * All clients share this JVM's HiveMQ client event loops (its NettyEventLoopProvider gives every client built without
 * an executor of its own the same group, 2 × cores threads), so N users cost N sockets and N idle inbox threads, not N
 * event loops. The broker runs in a process of its own; the CPU time of both processes is reported so that a
 * saturated client is not taken for a slow broker.
 */
class BrokerLoad(
    val users: Int,
    val durationMillis: Long,
    val minIntervalMillis: Long = 10_000,
    val maxIntervalMillis: Long = 30_000,
    val burst: Int = 0,
    /** Messages sent one at a time between two users before the load starts: the baseline. */
    val baselineSamples: Int = 200,
    /** How long to wait, after sending stops, for acknowledged messages still on their way. */
    val drainMillis: Long = 20_000,
    /** Logins at a time while connecting (the embedded broker hashes passwords on one thread and turns away more than 16 waiting). */
    val connectConcurrency: Int = 8,
    /** PBKDF2 rounds of the throw-away passwords (the deployment's 210,000 cost a core ~0.25 s per login: a login benchmark, not this one). */
    val passwordIterations: Int = 1_000,
    val seed: Long = 1,
) {
    init {
        require(users >= 2) { "at least 2 users, got $users" }
        require(durationMillis > 0) { "duration must be positive" }
        require(minIntervalMillis in 1..maxIntervalMillis) { "intervals must satisfy 1 <= min <= max" }
        require(burst >= 0) { "burst must be >= 0" }
        require(baselineSamples >= 1) { "at least one baseline sample" }
    }

    /** Runs the load against the broker [startBroker] starts in a directory of its own given its password file; blocks until done. */
    fun run(directory: File, startBroker: (File, File) -> LoadBroker, progress: (String) -> Unit): LoadResult {
        val people = List(users) { "u$it" }
        val baselinePair = listOf("baseline-a", "baseline-b")
        val passwords = (people + baselinePair).associateWith { randomPassword() }
        val passwordFile = File(directory, "passwd")
        progress("writing ${passwords.size} users' password hashes ($passwordIterations PBKDF2 rounds each)")
        passwordFile.writeText(passwords.entries.joinToString("\n", postfix = "\n") { (user, password) -> "$user:${PasswordFile.hash(password.toCharArray(), passwordIterations)}" })
        val loadAtStart = ProcessStats.loadAverage()
        startBroker(directory, passwordFile).use { broker ->
            progress("${broker.name}: broker pid ${broker.pid} on ${broker.address}")
            fun settings(user: String) = MqttSettings(broker.address, user, passwords.getValue(user), DeviceId.generate())
            val baseline = baseline(settings(baselinePair[0]), settings(baselinePair[1]))
            progress("${broker.name}: baseline (one message at a time between two users) p50 %.2f ms, p99 %.2f ms".format(baseline.p50, baseline.p99))
            val idle = broker.memory()
            return runBlocking(Dispatchers.Default) {
                val ledger = DeliveryLedger()
                val receipts = ReceiptCount()
                val messengers = people.map { MqttMessenger(settings(it)) }
                val drops = AtomicInteger()
                val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
                try {
                    val connectStart = System.nanoTime()
                    val gate = Semaphore(connectConcurrency)
                    val connected = AtomicInteger()
                    val refusals = ArrayList<String>()
                    val live = messengers.map { messenger ->
                        async {
                            val ok = gate.withPermit {
                                try {
                                    withTimeoutOrNull(CONNECT_TIMEOUT_MILLIS) { messenger.connect { event -> onInbox(messenger, event, ledger, receipts, scope) } } != null
                                } catch (e: MessagingException) {
                                    synchronized(refusals) { refusals += e.message.orEmpty() }
                                    false
                                }
                            }
                            val n = connected.incrementAndGet()
                            if (n % 500 == 0) progress("${broker.name}: $n of $users connect attempts done")
                            ok
                        }
                    }.awaitAll()
                    val connectSeconds = (System.nanoTime() - connectStart) / 1e9
                    // Only connected users send and are sent to: a message to a user who never connected has no
                    // session to wait in, and would be counted lost against the broker.
                    val senders = messengers.indices.filter { live[it] }
                    if (senders.size < 2) throw IOException("only ${senders.size} of $users users connected" + (refusals.firstOrNull()?.let { ": $it" } ?: ""))
                    progress("${broker.name}: ${senders.size} of $users users connected in %.1f s; sending for %d s".format(connectSeconds, durationMillis / 1000))
                    if (senders.size < users) progress("${broker.name}: ${users - senders.size} did not connect within ${CONNECT_TIMEOUT_MILLIS / 1000} s" + (refusals.firstOrNull()?.let { " (first refusal: $it)" } ?: ""))
                    // Every later change of a connected messenger's state is a dropped connection.
                    for (i in senders) scope.launch { messengers[i].state.drop(1).collect { if (it != ConnectionState.Connected) drops.incrementAndGet() } }
                    val brokerCpu0 = ProcessStats.cpuSeconds(broker.pid)
                    val clientCpu0 = ProcessStats.cpuSeconds(ProcessHandle.current().pid())
                    val machine0 = ProcessStats.machineTicks()
                    val start = System.nanoTime()
                    val end = start + durationMillis * 1_000_000
                    val random = Random(seed)
                    val sending = senders.map { i ->
                        val messenger = messengers[i]
                        val own = Random(random.nextLong())
                        scope.launch {
                            // Staggered first messages: people do not all start typing at once.
                            var next = start + own.nextLong(0, maxIntervalMillis) * 1_000_000
                            while (isActive && next < end) {
                                val wait = (next - System.nanoTime()) / 1_000_000
                                if (wait > 0) delay(wait)
                                send(messenger, people[peerOf(i, senders, own)], ledger, burst = false)
                                next += own.nextLong(minIntervalMillis, maxIntervalMillis + 1) * 1_000_000
                            }
                        }
                    }
                    val bursts = if (burst == 0) emptyList() else listOf(1, 2).map { k ->
                        scope.launch {
                            delay(durationMillis * k / 3)
                            progress("${broker.name}: burst $k: every user sends $burst messages at once")
                            for (i in senders) {
                                val own = Random(seed * 31 + i * 7 + k)
                                repeat(burst) { launch { send(messengers[i], people[peerOf(i, senders, own)], ledger, burst = true) } }
                            }
                        }
                    }
                    (sending + bursts).forEach { it.join() }
                    val sendingSeconds = (System.nanoTime() - start) / 1e9
                    val loaded = broker.memory()
                    val brokerCpu = ProcessStats.cpuSeconds(broker.pid) - brokerCpu0
                    val clientCpu = ProcessStats.cpuSeconds(ProcessHandle.current().pid()) - clientCpu0
                    val machine = ProcessStats.machineTicks().let { (busy, all) -> if (all > machine0.second) (busy - machine0.first).toDouble() / (all - machine0.second) else Double.NaN }
                    val loadAtEnd = ProcessStats.loadAverage()
                    progress("${broker.name}: sending stopped; waiting up to ${drainMillis / 1000} s for messages on their way")
                    val drainEnd = System.nanoTime() + drainMillis * 1_000_000
                    while (System.nanoTime() < drainEnd && (ledger.outstanding() > 0 || ledger.tally().pending > 0 || receipts.outstanding() > 0)) delay(50)
                    val held = messengers.count { it.state.value == ConnectionState.Connected }
                    val tally = ledger.tally()
                    LoadResult(
                        broker = broker.name, users = users, connectSeconds = connectSeconds, connectionsHeld = held, drops = drops.get(),
                        sendingSeconds = sendingSeconds, tally = tally, receiptsSent = receipts.sent.get(), receiptsReceived = receipts.received.get(),
                        baselineMillis = baseline, memoryIdle = idle, memoryLoaded = loaded,
                        brokerCpuSeconds = brokerCpu, clientCpuSeconds = clientCpu, machineBusy = machine, cores = Runtime.getRuntime().availableProcessors(), loadAtStart = loadAtStart, loadAtEnd = loadAtEnd,
                    )
                } finally {
                    scope.cancel()
                    messengers.map { async { runCatching { it.disconnect() } } }.awaitAll()
                }
            }
        }
    }

    /** A random one of [live] (ascending user indices) other than [self]. */
    private fun peerOf(self: Int, live: List<Int>, random: Random): Int {
        val r = random.nextInt(live.size - 1)
        return if (live[r] >= self) live[r + 1] else live[r]
    }

    private suspend fun send(messenger: MqttMessenger, recipient: String, ledger: DeliveryLedger, burst: Boolean) {
        val message = ChatMessage.compose(messenger.user, "Are you there? Feel this.", icon = HapticIcon.KNOCK)
        ledger.sent(message.id, recipient, System.nanoTime(), burst)
        try {
            messenger.send(recipient, message)
            ledger.acknowledged(message.id)
        } catch (e: Exception) {
            ledger.failed(message.id)
        }
    }

    private fun onInbox(receiver: MqttMessenger, event: InboxEvent, ledger: DeliveryLedger, receipts: ReceiptCount, scope: CoroutineScope) {
        when (event) {
            is InboxEvent.MessageReceived -> {
                ledger.received(event.message.id, receiver.user, System.nanoTime())
                // As the app does once the message is stored: a delivered receipt into the sender's inbox.
                val receipt = Receipt(event.message.id, receiver.user, ReceiptState.DELIVERED, System.currentTimeMillis())
                receipts.sending.incrementAndGet()
                scope.launch {
                    try {
                        receiver.send(event.message.sender, receipt)
                        receipts.sent.incrementAndGet()
                    } catch (e: Exception) {
                        receipts.failed.incrementAndGet()
                    }
                }
            }
            is InboxEvent.ReceiptReceived -> receipts.received.incrementAndGet()
            else -> Unit
        }
    }

    private class ReceiptCount {
        val sending = AtomicInteger()
        val sent = AtomicInteger()
        val failed = AtomicInteger()
        val received = AtomicInteger()

        fun outstanding(): Int = sending.get() - failed.get() - received.get()
    }

    /** [baselineSamples] messages from [a] to [b], one at a time, after 300 unmeasured ones (a fresh broker JVM compiles its hot paths meanwhile): the idle broker's latency, ms. */
    private fun baseline(a: MqttSettings, b: MqttSettings): LatencySummary = runBlocking {
        val arrivals = LinkedBlockingQueue<Long>()
        val sender = MqttMessenger(a)
        val receiver = MqttMessenger(b)
        try {
            sender.connect { }
            receiver.connect { if (it is InboxEvent.MessageReceived) arrivals.put(System.nanoTime()) }
            val latencies = List(WARMUP + baselineSamples) { i ->
                val message = ChatMessage.compose(a.user, "Are you there? Feel this.", icon = HapticIcon.KNOCK)
                val start = System.nanoTime()
                sender.send(b.user, message)
                val arrived = arrivals.poll(10, TimeUnit.SECONDS) ?: error("baseline message $i did not arrive within 10 s")
                (arrived - start) / 1e6
            }
            LatencySummary.of(latencies.drop(WARMUP))
        } finally {
            sender.disconnect()
            receiver.disconnect()
        }
    }

    private companion object {
        const val WARMUP = 300
        const val CONNECT_TIMEOUT_MILLIS = 120_000L
        val random = SecureRandom()

        fun randomPassword(): String = Base64.getUrlEncoder().withoutPadding().encodeToString(ByteArray(16).also(random::nextBytes))
    }
}
