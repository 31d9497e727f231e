package org.hapticon.sensor.live

import java.io.IOException
import java.util.ArrayDeque
import java.util.concurrent.Executor
import java.util.concurrent.Executors
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.framed.AckStatus

/**
 * Writes commands to a board off both the UI thread and the reading thread, so a stalled USB write can neither
 * freeze the UI nor stop the stream, and follows each command until the board answers.
 *
 * One queue, written in order. Settings ([OutgoingCommand.settingKey]) coalesce per key: a setting still waiting is
 * removed when a newer one of its key arrives, and the newer one joins the end of the queue, so a slow board gets
 * the newest value rather than a backlog, and a setting sent after an event is never written before it. Events
 * (a calibration STIMULATE) are never replaced; at most [eventCapacity] may wait, and one more is refused with
 * [CommandState.Overflowed], counted and reported in [commandError] rather than dropped silently.
 *
 * A command with an [OutgoingCommand.ackSequence] (framed protocol) waits, once written, for the board's ack with
 * that sequence number ([onAck], from the reading thread): OK is [CommandState.Acknowledged], a NACK
 * [CommandState.Rejected] with the board's reason, and no answer within [ackTimeoutMillis] is
 * [CommandState.TimedOut] (checked by [expireOverdue], which the session calls on every read).
 *
 * Thread-safe.
 *
 * @param clock nanoseconds, monotonic; for the ack deadlines.
 * @param eventCapacity events that may wait at once (settings take one slot per key and need no bound).
 * @param ackTimeoutMillis how long a written command waits for its ack.
 * @param executor runs the writes; one daemon thread by default (a test may run them inline or hold them).
 */
public class CommandWriter(
    private val clock: () -> Long = System::nanoTime,
    public val eventCapacity: Int = DEFAULT_EVENT_CAPACITY,
    public val ackTimeoutMillis: Long = ACK_TIMEOUT_MILLIS,
    private val executor: Executor = defaultExecutor(),
) {
    init {
        require(eventCapacity >= 1) { "eventCapacity must be at least 1, was $eventCapacity" }
        require(ackTimeoutMillis >= 1) { "ackTimeoutMillis must be positive, was $ackTimeoutMillis" }
    }

    private class Record(
        val command: OutgoingCommand,
        val port: SerialPort,
        val timeoutMillis: Int,
    ) : CommandHandle {
        val mutableState = MutableStateFlow<CommandState>(CommandState.Queued)
        var deadlineNanos = 0L
        override val description: String get() = command.description
        override val state: StateFlow<CommandState> = mutableState.asStateFlow()
    }

    private val lock = Any()

    // Guarded by lock.
    private val queue = ArrayDeque<Record>()
    private var queuedEvents = 0
    private var draining = false
    private val awaiting = LinkedHashMap<Int, Record>()
    private var counts = CommandCounts()

    private val failure = MutableStateFlow<String?>(null)
    private val problem = MutableStateFlow<String?>(null)

    /** Why the last command could not be written (a timeout, an unplug), or null. */
    public val writeError: StateFlow<String?> = failure.asStateFlow()

    /**
     * The last command that went wrong, in one line: refused by the board (with its reason), unanswered, not
     * queued because the queue was full, or not written. Null until one does, and after [clearError].
     */
    public val commandError: StateFlow<String?> = problem.asStateFlow()

    /** Commands written since the last [reset]. */
    public val commandsSent: Long get() = counts().sent

    /** Commands that could not be written (timeout, unplug, I/O error) since the last [reset]. */
    public val commandsLost: Long get() = counts().lost

    /** What happened to the commands since the last [reset]. */
    public fun counts(): CommandCounts = synchronized(lock) { counts }

    /** Forgets the last errors (a new connection). */
    public fun clearError() {
        failure.value = null
        problem.value = null
    }

    /**
     * A new connection: commands still awaiting an ack from the old one end [CommandState.TimedOut] (that board
     * will not answer them), the counters restart, and the errors are forgotten.
     */
    public fun reset() {
        val orphans = synchronized(lock) {
            counts = CommandCounts()
            awaiting.values.toList().also { awaiting.clear() }
        }
        for (r in orphans) r.mutableState.value = CommandState.TimedOut("the connection ended before the board answered")
        clearError()
    }

    /**
     * Queues [command] for [port] as a setting that replaces one still waiting; for boards without acks (the
     * LucidGloves force feedback). Kept for callers that hold raw bytes; see [submit].
     */
    public fun send(port: SerialPort, command: ByteArray, timeoutMillis: Int = WRITE_TIMEOUT_MILLIS) {
        submit(port, OutgoingCommand(command, "a command", settingKey = RAW_SETTING_KEY, ackSequence = null), timeoutMillis)
    }

    /**
     * Queues [command] for [port] and returns at once with its handle; it is written in queue order within
     * [timeoutMillis] per write, or ends [CommandState.WriteFailed]. An event that finds [eventCapacity] events
     * waiting is refused at once ([CommandState.Overflowed]) and nothing is written.
     */
    public fun submit(port: SerialPort, command: OutgoingCommand, timeoutMillis: Int = WRITE_TIMEOUT_MILLIS): CommandHandle {
        val record = Record(command, port, timeoutMillis)
        var superseded: List<Record> = emptyList()
        val startDrain: Boolean
        synchronized(lock) {
            if (command.isEvent) {
                if (queuedEvents >= eventCapacity) {
                    counts = counts.copy(overflowed = counts.overflowed + 1)
                    val message = "$eventCapacity commands are already waiting for the board: it is not keeping up"
                    record.mutableState.value = CommandState.Overflowed(message)
                    problem.value = describeProblem(command.description, record.mutableState.value)
                    return record
                }
                queuedEvents++
            } else {
                superseded = queue.filter { it.command.settingKey == command.settingKey }
                if (superseded.isNotEmpty()) {
                    queue.removeAll(superseded.toSet())
                    counts = counts.copy(superseded = counts.superseded + superseded.size)
                }
            }
            queue.addLast(record)
            startDrain = !draining
            if (startDrain) draining = true
        }
        for (r in superseded) r.mutableState.value = CommandState.Superseded
        if (startDrain) executor.execute(::drain)
        return record
    }

    /**
     * The board's answer to the command with [sequence]: settles the command awaiting it, or counts an ack
     * nobody awaits ([CommandCounts.unmatchedAcks]). Called on the reading thread; does not block.
     */
    public fun onAck(sequence: Int, status: AckStatus, detail: Int) {
        val record = synchronized(lock) {
            val r = awaiting.remove(sequence)
            counts = when {
                r == null -> counts.copy(unmatchedAcks = counts.unmatchedAcks + 1)
                status == AckStatus.OK -> counts.copy(acknowledged = counts.acknowledged + 1)
                else -> counts.copy(rejected = counts.rejected + 1)
            }
            r
        } ?: return
        val state = if (status == AckStatus.OK) CommandState.Acknowledged else CommandState.Rejected(status, detail, record.command.explainNack(status, detail))
        record.mutableState.value = state
        describeProblem(record.description, state)?.let { problem.value = it }
    }

    /** Ends every command whose ack is overdue at [nowNanos] as [CommandState.TimedOut]; returns how many. */
    public fun expireOverdue(nowNanos: Long = clock()): Int {
        val overdue = synchronized(lock) {
            // Written in order, so the oldest deadline comes first: nothing is allocated while none is due.
            val oldest = awaiting.values.firstOrNull() ?: return 0
            if (nowNanos - oldest.deadlineNanos < 0) return 0
            val late = awaiting.values.filter { nowNanos - it.deadlineNanos >= 0 }
            for (r in late) awaiting.remove(r.command.ackSequence)
            if (late.isNotEmpty()) counts = counts.copy(timedOut = counts.timedOut + late.size)
            late
        }
        for (r in overdue) {
            val state = CommandState.TimedOut("no acknowledgement within $ackTimeoutMillis ms")
            r.mutableState.value = state
            problem.value = describeProblem(r.description, state)
        }
        return overdue.size
    }

    /**
     * Ends every command still awaiting an ack as [CommandState.TimedOut] with [reason] and counts it (the stream
     * stopped: no answer can come any more); returns how many.
     */
    public fun abandonAwaiting(reason: String): Int {
        val orphans = synchronized(lock) {
            val all = awaiting.values.toList()
            awaiting.clear()
            if (all.isNotEmpty()) counts = counts.copy(timedOut = counts.timedOut + all.size)
            all
        }
        for (r in orphans) {
            val state = CommandState.TimedOut(reason)
            r.mutableState.value = state
            problem.value = describeProblem(r.description, state)
        }
        return orphans.size
    }

    /** Commands written and still awaiting their ack. */
    public fun awaitingAcks(): Int = synchronized(lock) { awaiting.size }

    private fun drain() {
        while (true) {
            val record = synchronized(lock) {
                val next = queue.pollFirst()
                if (next == null) {
                    draining = false
                } else if (next.command.isEvent) {
                    queuedEvents--
                }
                next
            } ?: return
            write(record)
        }
    }

    private fun write(record: Record) {
        val command = record.command
        val sequence = command.ackSequence
        // Registered before the write: the board may answer before write() returns, on the reading thread.
        if (sequence != null) {
            val displaced = synchronized(lock) {
                record.deadlineNanos = clock() + ackTimeoutMillis * 1_000_000
                // Two encoders on one board can reuse a number; the older command's ack can no longer be told apart.
                awaiting.put(sequence, record)?.also { counts = counts.copy(timedOut = counts.timedOut + 1) }
            }
            if (displaced != null) {
                val state = CommandState.TimedOut("a later command reused sequence number $sequence before the board answered")
                displaced.mutableState.value = state
                problem.value = describeProblem(displaced.description, state)
            }
        }
        record.mutableState.value = CommandState.Sent(isFinal = sequence == null)
        try {
            command.bytes.let { record.port.write(it, 0, it.size, record.timeoutMillis) }
            synchronized(lock) { counts = counts.copy(sent = counts.sent + 1) }
        } catch (e: IOException) {
            // The board may be gone or stalled; the stream's own reader reports an unplug.
            val message = e.message ?: e.javaClass.simpleName
            synchronized(lock) {
                if (sequence != null && awaiting[sequence] === record) awaiting.remove(sequence)
                counts = counts.copy(lost = counts.lost + 1)
            }
            val state = CommandState.WriteFailed(message)
            record.mutableState.value = state
            failure.value = message
            problem.value = describeProblem(command.description, state)
        }
    }

    public companion object {
        /** Long enough for a 26-byte command at 9600 baud plus a busy board; short enough not to pile up. */
        public const val WRITE_TIMEOUT_MILLIS: Int = 100

        /**
         * How long a written command waits for its ack: the reference firmware answers in the `loop()` pass that
         * decodes the command (about 1 ms), so 500 ms leaves room for a 9600-baud line and a full USB buffer
         * of samples ahead of the ack, while a person still learns within half a second that nothing came.
         */
        public const val ACK_TIMEOUT_MILLIS: Long = 500

        /** Events that may wait at once: far more than a person can trigger before a working board catches up. */
        public const val DEFAULT_EVENT_CAPACITY: Int = 16

        /** The key of raw commands given to [send]: they replace each other, as before settings had keys. */
        public const val RAW_SETTING_KEY: String = "raw"

        private fun defaultExecutor(): Executor = Executors.newSingleThreadExecutor { task ->
            Thread(task, "hapticon-sensor-writer").apply { isDaemon = true }
        }

        /**
         * A NACK in words, for any framed command (docs/protocols.md "Ack statuses", hfp_device.cpp). Commands whose
         * detail means more (the grain checks) bring their own [OutgoingCommand.explainNack].
         */
        public fun ackReason(status: AckStatus, detail: Int): String = when (status) {
            AckStatus.OK -> "accepted"
            AckStatus.OUT_OF_RANGE -> "a value out of range (detail $detail)"
            AckStatus.BAD_OUTPUT -> "no output $detail on this board"
            AckStatus.MALFORMED -> "malformed command (wrong payload length)"
            AckStatus.UNKNOWN_COMMAND -> "the board does not know command type 0x${detail.toString(16).padStart(2, '0')}"
            AckStatus.UNSUPPORTED_VERSION -> "the board does not speak protocol version $detail"
            AckStatus.UNKNOWN -> "a status this version does not know (detail $detail)"
        }
    }
}
