package org.hapticon.companion.chat

import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Deferred
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.async
import kotlinx.coroutines.cancel
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.job
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.selects.select
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.companion.cli.AudioSettings
import org.hapticon.companion.cli.IconSource
import org.hapticon.companion.cli.PatternSource
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli.WavExport
import org.hapticon.companion.cli.writeWav
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Admission
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxGate
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.InvalidMessageException
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.Outbox
import org.hapticon.messaging.OutboxEntry
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import org.hapticon.messaging.VibrationDecision
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.SafetyNumber
import java.io.BufferedReader
import java.io.File
import java.io.PrintStream
import java.util.concurrent.ConcurrentHashMap
import kotlin.concurrent.thread

/**
 * A terminal chat for [messenger]'s user: lines read from the input are sent to the current peer, what
 * arrives is printed to [out], connection news and rejected payloads go to [err].
 *
 * Typed messages go through [outbox], so they wait while the broker is unreachable, and stay there until the
 * receiver's delivered receipt: with a [ChatStore] across restarts too (a new session sends what an earlier one left
 * unconfirmed, and `/pending` lists what is still unconfirmed). Received messages pass an [InboxGate] (repeats
 * dropped, icons rate-limited; with a [ChatStore] as its deduplicator, across restarts), are shown, then acknowledged
 * with a delivered receipt, and get a read receipt when the user next enters a line (the terminal showed them by
 * then). Whatever a peer wrote is shown neutralised ([ChatFormat]): control characters escaped, further lines of a
 * text indented under their sender. A laptop cannot vibrate: with [wavDir], icons the gate lets through are rendered
 * to WAV files there instead.
 */
class ChatSession(
    private val messenger: Messenger,
    initialPeer: String?,
    private val out: PrintStream,
    private val err: PrintStream,
    private val wavDir: File? = null,
    private val gate: InboxGate,
    private val clock: Clock = Clock.SYSTEM,
    private val drainTimeoutMillis: Long = 5_000,
    /** The end-to-end protection [messenger] uses, for `/safety` and `/trust`; null when it is off. */
    private val e2e: EndToEnd? = null,
    /** Where typed messages wait for their receipts. */
    private val outbox: Outbox,
    /** Where [outbox] keeps them across restarts, for the user's information; null when it dies with the process. */
    private val keptIn: File? = null,
) : InboxListener {
    private val user = messenger.user
    private val sender = OutboxSender(outbox, messenger, clock = clock)
    @Volatile private var peer: String? = initialPeer
    private val unread = ArrayList<ChatMessage>() // shown, read receipt not yet sent
    private val sentTexts = ConcurrentHashMap<String, String>() // message id → how to mention it in a receipt
    private val receipts = Channel<Pair<String, Receipt>>(Channel.UNLIMITED)

    // Everyone's capabilities arrive (retained); the peer's are shown, the rest kept for a later /to. Bounded,
    // least recently updated first out, so a flood of retained messages cannot exhaust memory.
    private val capabilities = object : LinkedHashMap<String, Capabilities>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, Capabilities>): Boolean = size > MAX_KNOWN_CAPABILITIES
    }

    /**
     * Runs the chat until `/quit` or the end of [input]; then waits up to the drain timeout for typed
     * messages to reach the broker, and disconnects. Suspends meanwhile. Throws [UsageException] when the
     * broker refuses the user for good (bad password, ACL), or (after disconnecting) when typed messages
     * never reached the broker.
     */
    suspend fun run(input: BufferedReader) {
        // The input is read on a thread of its own: a blocked readLine cannot be cancelled, and the chat must
        // be able to end (broker refusal) while it waits.
        val lines = Channel<String?>(Channel.UNLIMITED)
        thread(isDaemon = true, name = "hapticon-chat-input") {
            while (true) {
                val line = try {
                    input.readLine()
                } catch (e: java.io.IOException) {
                    null
                }
                lines.trySend(line)
                if (line == null) break
            }
        }
        resumeEarlierSession()
        coroutineScope {
            val background = CoroutineScope(coroutineContext + SupervisorJob(coroutineContext.job))
            background.launch { reportConnection() }
            background.launch { sendReceipts() }
            background.launch { sender.run() }
            val connection = background.async {
                messenger.connect(this@ChatSession)
                messenger.publishCapabilities(Capabilities(user, if (wavDir != null) RendererKind.AUDIO else RendererKind.NONE, amplitudeControl = false))
            }
            try {
                readLines(lines, connection)
                // A refusal must end the chat with its reason (exit 2) even when the input ends first, as a script
                // piping nothing or one line in does: while the first attempt has not settled, wait for it as long
                // as typed lines would be waited for. The state turns Failed before connect() throws (it disconnects
                // first), so a Failed state waits for that throw.
                val unsettled = messenger.state.value.let { it == ConnectionState.Disconnected || it == ConnectionState.Connecting(lastFailure = null) }
                if (!connection.isCompleted && unsettled) {
                    withTimeoutOrNull(drainTimeoutMillis) {
                        messenger.state.first { it == ConnectionState.Connected || it is ConnectionState.Failed }
                    }
                }
                if (connection.isCompleted || messenger.state.value is ConnectionState.Failed) connection.await()
                val left = drainOutbox()
                val unconfirmed = outbox.pending().filter { it.awaitingReceipt }
                if (unconfirmed.isNotEmpty()) {
                    val fate = keptIn?.let { "kept in $it and sent again at the next start" } ?: "nothing will send them again after this process ends"
                    err.println("chat: ${unconfirmed.size} message(s) reached the broker but were not yet confirmed by the receiver; $fate:")
                    listPending(unconfirmed, err)
                }
                if (left > 0) {
                    val why = (messenger.state.value as? ConnectionState.Connecting)?.lastFailure ?: lastFailure ?: "the broker did not acknowledge them"
                    val fate = keptIn?.let { "kept in $it and sent at the next start" } ?: "they are lost with this process"
                    // One line and a non-zero exit: a script piping lines in must learn that they did not go out.
                    throw UsageException("$left message(s) not delivered ($why); $fate")
                }
            } finally {
                background.cancel()
                withContext(NonCancellable) { messenger.disconnect() }
            }
        }
    }

    /**
     * Says what an earlier session left unconfirmed and makes all of it due at once: that session may have ended long
     * ago, and a broker may have lost what it acknowledged (the receiver drops a repeat by id).
     */
    private suspend fun resumeEarlierSession() {
        val earlier = outbox.pending()
        if (earlier.isEmpty()) return
        val now = clock.nowMillis()
        for (entry in earlier) {
            sentTexts[entry.message.id] = mention(entry.message)
            if (entry.awaitingReceipt) outbox.markSent(entry.message.id, now)
        }
        err.println("chat: ${earlier.size} message(s) of an earlier session not yet confirmed by their receivers; sending them again:")
        listPending(earlier, err)
    }

    /** One line per entry, oldest first, at most [MAX_LISTED] (then how many more). */
    private fun listPending(entries: List<OutboxEntry>, to: PrintStream) {
        for (entry in entries.take(MAX_LISTED)) {
            val state = if (entry.awaitingReceipt) "reached the broker, no receipt yet" else "not yet at the broker" + (entry.lastError?.let { ": " + ChatFormat.oneLine(it) } ?: "")
            to.println("  … to ${entry.recipient}: ${mention(entry.message)} ($state)")
        }
        if (entries.size > MAX_LISTED) to.println("  … and ${entries.size - MAX_LISTED} more")
    }

    private suspend fun readLines(lines: Channel<String?>, connection: Deferred<Unit>) {
        var connected = false
        while (true) {
            // Also wakes when the connection settles: a refusal (which onAwait rethrows) ends the chat at once.
            val next = select<Any?> {
                lines.onReceive { it }
                if (!connected) connection.onAwait { ConnectionSettled }
            }
            if (next === ConnectionSettled) {
                connected = true
                continue
            }
            val line = next as String? ?: return
            if (!handle(line)) return
        }
    }

    /** Handles one input line; returns false for `/quit`. */
    private suspend fun handle(line: String): Boolean {
        markShownAsRead()
        val trimmed = line.trim()
        if (trimmed.isEmpty()) return true
        if (!trimmed.startsWith("/")) {
            send(trimmed, sticker = null, icon = null)
            return true
        }
        val command = trimmed.substringBefore(' ')
        val rest = trimmed.substringAfter(' ', "").trim()
        when (command) {
            "/quit" -> return false
            "/help" -> say(HELP)
            "/to" -> if (Topics.isValidUserName(rest)) {
                peer = rest
                say("talking to $rest")
                synchronized(capabilities) { capabilities[rest] }?.let { say(ChatFormat.capabilities(it)) }
            } else {
                say("not a user name: '$rest'")
            }
            "/icon" -> {
                val name = rest.substringBefore(' ')
                val text = rest.substringAfter(' ', "")
                try {
                    // A pattern file (.ahap, .haptic, pattern JSON) travels as a pattern message (version 2).
                    val imported = PatternSource.loadIfPattern(name)
                    if (imported != null) {
                        imported.notes.forEach { say("note: $it") }
                        send(text, sticker = null, icon = null, pattern = imported.pattern)
                    } else {
                        send(text, sticker = null, icon = IconSource.load(name))
                    }
                } catch (e: UsageException) {
                    say("no icon sent: ${e.message}")
                }
            }
            "/pending" -> {
                val pending = outbox.pending()
                if (pending.isEmpty()) {
                    say("every message you sent is confirmed by its receiver")
                } else {
                    say("${pending.size} message(s) not yet confirmed by their receivers:")
                    synchronized(out) { listPending(pending, out) }
                }
            }
            "/safety" -> say(safety(rest.ifEmpty { peer }))
            "/trust" -> say(trust(rest))
            "/sticker" -> send(rest.substringAfter(' ', ""), sticker = rest.substringBefore(' '), icon = null)
            else -> say("unknown command $command; /help lists them")
        }
        return true
    }

    private fun safety(of: String?): String {
        val e2e = e2e ?: return "end-to-end encryption is off (this chat was started with --plaintext)"
        if (of == null || !Topics.isValidUserName(of)) return "usage: /safety PEER"
        return e2e.safetyNumber(of)?.let { "safety number with $of: $it (compare it with $of's)" } ?: "no key of $of yet"
    }

    private fun trust(user: String): String {
        val e2e = e2e ?: return "end-to-end encryption is off (this chat was started with --plaintext)"
        if (!Topics.isValidUserName(user)) return "usage: /trust PEER"
        val trusted = e2e.trust(user) ?: return "no changed key of $user is waiting"
        return "now trusting $user's new key; safety number ${SafetyNumber.of(e2e.identity.bundle, trusted)}"
    }

    private suspend fun send(text: String, sticker: String?, icon: HapticIcon?, pattern: HapticPattern? = null) {
        val to = peer ?: return say("no recipient: start with --to PEER or type /to PEER")
        val message = try {
            ChatMessage.compose(user, text, sticker, icon, clock, pattern)
        } catch (e: InvalidMessageException) {
            return say("not sent: ${e.message}")
        }
        sentTexts[message.id] = mention(message)
        sender.enqueue(to, message)
        if (messenger.state.value != ConnectionState.Connected) say("(queued until the broker is reachable)")
    }

    override fun onInboxEvent(event: InboxEvent) {
        when (event) {
            is InboxEvent.MessageReceived -> received(event.message)
            is InboxEvent.ReceiptReceived -> {
                val r = event.receipt
                val confirmed = runBlocking { sender.confirm(r) } // the message is done: it leaves the outbox
                // Each copy of a resent message is acknowledged: only the receipt that confirmed it is news.
                if (r.state == ReceiptState.DELIVERED && !confirmed) return
                val what = sentTexts[r.messageId] ?: "message ${r.messageId.take(8)}"
                say(
                    when (r.state) {
                        ReceiptState.FELT -> "〰 ${r.from} felt $what"
                        ReceiptState.READ -> "✓✓ ${r.from} read $what"
                        ReceiptState.DELIVERED -> "✓ ${r.from} received $what"
                    },
                )
            }
            is InboxEvent.CapabilitiesReceived -> {
                val owner = event.capabilities.user
                synchronized(capabilities) { capabilities[owner] = event.capabilities }
                if (owner == peer) say(ChatFormat.capabilities(event.capabilities))
            }
            // The terminal has no glove: a partner's handshake stream (30 samples/s) is not for printing.
            is InboxEvent.HandPoseReceived -> Unit
            is InboxEvent.Rejected -> {
                val r = event.rejection
                err.println("chat: rejected a payload on ${ChatFormat.oneLine(event.topic)}: ${r.reason}${r.field?.let { " (${ChatFormat.oneLine(it)})" } ?: ""}: ${ChatFormat.oneLine(r.detail)}")
                if (r.reason == RejectionReason.KEY_CHANGED) {
                    val who = Topics.inboxSender(user, event.topic) ?: Topics.keysOwner(event.topic)
                    // Signal's rule: a changed key is shown, never silently accepted; the user decides after comparing.
                    err.println("chat: WARNING: compare safety numbers with $who (in person or by phone), then /trust $who; until then their messages wait in their outbox")
                }
            }
        }
    }

    private fun received(message: ChatMessage) {
        // Recorded as seen, then shown, then acknowledged: the delivered receipt says the user has it.
        val admission = gate.admit(message) as? Admission.New
        if (admission != null) show(message, admission)
        // Every copy is acknowledged, repeats too: the sender resends until a delivered receipt arrives, and
        // the first receipt may have been lost.
        receipts.trySend(message.sender to Receipt(message.id, user, ReceiptState.DELIVERED, clock.nowMillis()))
    }

    private fun show(message: ChatMessage, admission: Admission.New) {
        say(ChatFormat.message(message))
        synchronized(unread) { unread += message }
        if (message.icon == null && message.pattern == null) return
        when (admission.vibration) {
            VibrationDecision.VIBRATE -> if (wavDir != null) renderHaptic(message, wavDir)
            VibrationDecision.SENDER_LIMIT -> say("  (icon not played: ${message.sender} is sending icons too fast)")
            VibrationDecision.DUTY_CYCLE_LIMIT -> say("  (icon not played: enough vibration for this minute)")
            null -> Unit
        }
    }

    private fun renderHaptic(message: ChatMessage, dir: File) {
        val name = message.icon?.name ?: message.pattern?.name ?: return
        val file = File(dir, "${message.sender}-${message.id.take(8)}-${ChatFormat.fileSafe(name)}.wav")
        try {
            val icon = message.icon
            val pattern = message.pattern
            // The line names the icon, which the peer chose: one line, control characters escaped.
            val wrote = if (icon != null) WavExport.write(icon, AudioSettings(), file) else writeWav(pattern!!, file, AudioSettings().sampleRate, AudioSettings().encoding)
            say("  " + ChatFormat.oneLine(wrote))
        } catch (e: UsageException) {
            say("  (icon not rendered: ${ChatFormat.oneLine(e.message.orEmpty())})")
        }
    }

    private fun markShownAsRead() {
        val shown = synchronized(unread) { unread.toList().also { unread.clear() } }
        for (message in shown) receipts.trySend(message.sender to Receipt(message.id, user, ReceiptState.READ, clock.nowMillis()))
    }

    // Receipts are best effort: one that fails is reported, not retried (the message itself was delivered).
    private suspend fun sendReceipts() {
        for ((to, receipt) in receipts) {
            messenger.state.first { it == ConnectionState.Connected }
            try {
                messenger.send(to, receipt)
            } catch (e: Exception) {
                err.println("chat: ${receipt.state.wireName} receipt to $to not sent: ${e.message}")
            }
        }
    }

    @Volatile private var lastFailure: String? = null

    private suspend fun reportConnection() {
        var wasConnected = false
        var everConnected = false
        messenger.state.collect { state ->
            when (state) {
                ConnectionState.Connected -> {
                    everConnected = true
                    err.println("chat: connected as $user" + (peer?.let { ", talking to $it" } ?: "") + "; /help lists commands")
                }
                is ConnectionState.Connecting -> when {
                    wasConnected -> err.println("chat: connection lost (${state.lastFailure}); reconnecting")
                    // Why the first connection fails, once per distinct reason: refused, TLS trust, unknown host.
                    !everConnected && state.lastFailure != null && state.lastFailure != lastFailure ->
                        err.println("chat: cannot connect: ${state.lastFailure}; still trying (typed lines wait)")
                }
                is ConnectionState.Failed -> err.println("chat: the broker refused $user: ${state.reason}")
                ConnectionState.Disconnected -> Unit
            }
            if (state is ConnectionState.Connecting && state.lastFailure != null) lastFailure = state.lastFailure
            wasConnected = state == ConnectionState.Connected
        }
    }

    /**
     * Waits up to the drain timeout for every message to reach the broker (and, briefly, for receipts);
     * returns how many never reached it.
     */
    private suspend fun drainOutbox(): Int {
        withTimeoutOrNull(drainTimeoutMillis) {
            while (outbox.pending().any { !it.awaitingReceipt }) delay(DRAIN_POLL_MILLIS)
        }
        // A peer that is online confirms within moments; one that is offline should not hold the terminal.
        withTimeoutOrNull(minOf(drainTimeoutMillis, RECEIPT_GRACE_MILLIS)) {
            while (outbox.pending().isNotEmpty()) delay(DRAIN_POLL_MILLIS)
        }
        return outbox.pending().count { !it.awaitingReceipt }
    }

    private fun say(line: String) {
        synchronized(out) { out.println(line) }
    }

    private fun mention(message: ChatMessage): String = when {
        message.text.isNotEmpty() -> "\"" + ChatFormat.oneLine(message.text.take(40)) + (if (message.text.length > 40) "…\"" else "\"")
        message.icon != null -> "icon ${ChatFormat.oneLine(message.icon!!.name)}"
        message.pattern != null -> "pattern ${ChatFormat.oneLine(message.pattern!!.name)}"
        else -> "sticker ${message.sticker}"
    }

    companion object {
        /** The in-chat commands, as `/help` prints them. */
        val HELP: String = """
            |  TEXT                  send TEXT to the current peer
            |  /icon ICON [TEXT]     send a preset icon (stroke, hit, knock, hug), an icon JSON file or a pattern file
            |                        (.ahap, .haptic, pattern JSON), with optional text
            |  /sticker NAME [TEXT]  send a sticker (a-z, 0-9, '_', '-'), with optional text
            |  /to PEER              talk to PEER from now on
            |  /safety [PEER]        show the safety number with PEER (end-to-end encryption)
            |  /trust PEER           accept PEER's changed key after comparing safety numbers
            |  /pending              list the messages their receivers have not confirmed yet
            |  /quit                 leave (so does end of input)
        """.trimMargin()

        private const val DRAIN_POLL_MILLIS = 20L
        private const val RECEIPT_GRACE_MILLIS = 1_000L
        private const val MAX_KNOWN_CAPABILITIES = 1_000
        private const val MAX_LISTED = 10
    }

    private object ConnectionSettled
}
