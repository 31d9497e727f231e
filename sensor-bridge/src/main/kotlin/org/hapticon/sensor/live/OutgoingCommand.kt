package org.hapticon.sensor.live

import kotlinx.coroutines.flow.StateFlow
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.protocol.framed.AckStatus

/**
 * One command for the board, as the [CommandWriter] queues it.
 *
 * A *setting* ([settingKey] not null: grain parameters, servo positions) is state: while it waits, a newer setting
 * of the same key replaces it, because only the newest value matters. An *event* ([settingKey] null: a calibration
 * STIMULATE) happens once: it is queued in order and never replaced.
 *
 * Anything that drives current carries its amplitude steps in [stimulationSteps], and they are checked here
 * against the hardware's 200 steps over 0–2.7 mA ([AmplitudeSteps.requireStep]), so no over-cap stimulation can
 * be queued even if its bytes were built by hand.
 *
 * @throws org.hapticon.sensor.safety.SafetyLimitException from the constructor for a step outside 0..200.
 * @throws IllegalArgumentException for empty [bytes], a blank [description] or [ackSequence] outside 0..65535.
 */
public class OutgoingCommand(
    /** The bytes to write, exactly as they go on the wire. */
    public val bytes: ByteArray,
    /** What it is, in words, for messages: "STIMULATE electrode 5 at step 60 for 200 ms". */
    public val description: String,
    /** Null for an event; otherwise the key under which a newer setting replaces this one while it waits. */
    public val settingKey: String?,
    /** The sequence number the board will acknowledge (framed protocol), or null when no answer comes (LucidGloves). */
    public val ackSequence: Int?,
    /** The amplitude step of every electrode this command drives; empty when it drives none. */
    public val stimulationSteps: List<Int> = emptyList(),
    /** The board's NACK in words; the detail byte means different things per command. */
    public val explainNack: (AckStatus, Int) -> String = CommandWriter::ackReason,
) {
    init {
        require(bytes.isNotEmpty()) { "a command needs bytes" }
        require(description.isNotBlank()) { "a command needs a description" }
        require(ackSequence == null || ackSequence in 0..0xFFFF) { "ackSequence must be in 0..65535, was $ackSequence" }
        // The cap again, at the queue: whatever built the bytes, nothing above step 200 (2.7 mA) is queued.
        stimulationSteps.forEach { AmplitudeSteps.requireStep(it) }
    }

    /** Whether this command is an event (kept in order, never replaced). */
    public val isEvent: Boolean get() = settingKey == null
}

/** What has happened to one [OutgoingCommand]. */
public sealed interface CommandState {
    /** Whether nothing more will happen to the command. */
    public val isFinal: Boolean

    /** Waiting in the writer's queue. */
    public data object Queued : CommandState {
        override val isFinal: Boolean get() = false
    }

    /**
     * Written to the port. Final for a command without [OutgoingCommand.ackSequence] (no answer comes); otherwise
     * the board's ack is awaited.
     */
    public data class Sent(override val isFinal: Boolean) : CommandState

    /** The board acknowledged it: applied (ack status OK). */
    public data object Acknowledged : CommandState {
        override val isFinal: Boolean get() = true
    }

    /** The board refused it and changed nothing: NACK [status] with [detail]; [reason] says why in words. */
    public data class Rejected(val status: AckStatus, val detail: Int, val reason: String) : CommandState {
        override val isFinal: Boolean get() = true
    }

    /** No answer came: [message] says how long was waited (a CRC error on the way gets no answer at all). */
    public data class TimedOut(val message: String) : CommandState {
        override val isFinal: Boolean get() = true
    }

    /** A newer setting of the same key replaced it before it was written; the newer value went instead. */
    public data object Superseded : CommandState {
        override val isFinal: Boolean get() = true
    }

    /** Refused before writing because the event queue was full; [message] says so. Nothing was written. */
    public data class Overflowed(val message: String) : CommandState {
        override val isFinal: Boolean get() = true
    }

    /** The write failed (a write timeout, an unplug); [message] says why. */
    public data class WriteFailed(val message: String) : CommandState {
        override val isFinal: Boolean get() = true
    }
}

/** A queued command and what has happened to it since ([state]); returned by [CommandWriter.submit]. */
public interface CommandHandle {
    /** What the command is, in words. */
    public val description: String

    /** Where the command is; ends in a [CommandState.isFinal] state. */
    public val state: StateFlow<CommandState>
}

/** One line for a person when [state] went wrong (refused, unanswered, lost), or null when it did not. */
public fun describeProblem(description: String, state: CommandState): String? = when (state) {
    is CommandState.Rejected -> "The board refused $description: ${state.reason}"
    is CommandState.TimedOut -> "No answer from the board to $description: ${state.message}"
    is CommandState.Overflowed -> "Not sent: $description: ${state.message}"
    is CommandState.WriteFailed -> "Could not write $description: ${state.message}"
    CommandState.Queued, is CommandState.Sent, CommandState.Acknowledged, CommandState.Superseded -> null
}

/** Counts of what happened to the commands of one connection. */
public data class CommandCounts(
    /** Commands written. */
    val sent: Long = 0,
    /** Commands whose write failed. */
    val lost: Long = 0,
    /** Commands the board acknowledged (status OK). */
    val acknowledged: Long = 0,
    /** Commands the board refused (a NACK). */
    val rejected: Long = 0,
    /** Commands that got no answer within the ack timeout. */
    val timedOut: Long = 0,
    /** Settings replaced by a newer one of the same key before they were written. */
    val superseded: Long = 0,
    /** Events refused because the queue was full. */
    val overflowed: Long = 0,
    /** Well-formed acks for no command awaiting one (late, duplicated, or from before this connection). */
    val unmatchedAcks: Long = 0,
)
