package org.hapticon.study.log

import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue
import org.hapticon.study.JsonFields
import org.hapticon.study.ProtocolException

/**
 * Something that happened in a session. The time is not part of the event: the [LogEntry] that records it carries
 * the timestamp. [type] is the entry's `type`, the rest is its JSON payload ([payload]).
 */
public sealed interface StudyEvent {
    /** The entry type, for example `answer`. */
    public val type: String

    /** The session began: the plan is that of [protocolId] revision [revision] for [participantIndex] and [seed]. */
    public data class SessionStarted(val protocolId: String, val revision: Int, val participantIndex: Int, val seed: Long) : StudyEvent {
        override val type: String get() = SESSION_STARTED
    }

    /** The participant finished the last task. */
    public data object SessionEnded : StudyEvent {
        override val type: String get() = SESSION_ENDED
    }

    /** The participant read the intro of [taskId] and began it. */
    public data class TaskStarted(val taskId: String) : StudyEvent {
        override val type: String get() = TASK_STARTED
    }

    /** The participant left the screen showing every stimulus of [taskId] together, going on to its questions. */
    public data class ExplorationEnded(val taskId: String) : StudyEvent {
        override val type: String get() = EXPLORATION_ENDED
    }

    /** The participant left the end screen of [taskId]. */
    public data class TaskEnded(val taskId: String) : StudyEvent {
        override val type: String get() = TASK_ENDED
    }

    /** Stimulus [stimulusId] of [taskId] appeared on screen; response times count from here. */
    public data class StimulusShown(val taskId: String, val stimulusId: String) : StudyEvent {
        override val type: String get() = STIMULUS_SHOWN
    }

    /** The participant pressed the icon of the stimulus to feel it (again). */
    public data class IconPressed(val taskId: String, val stimulusId: String) : StudyEvent {
        override val type: String get() = ICON_PRESSED
    }

    /** The actuator began playing the stimulus's icon. */
    public data class PlaybackStarted(val taskId: String, val stimulusId: String) : StudyEvent {
        override val type: String get() = PLAYBACK_STARTED
    }

    /** The actuator finished playing the stimulus's icon. */
    public data class PlaybackFinished(val taskId: String, val stimulusId: String) : StudyEvent {
        override val type: String get() = PLAYBACK_FINISHED
    }

    /** The participant rated the statement of stimulus [stimulusId] of [taskId] with [value] (1..scale points). */
    public data class Answer(val taskId: String, val stimulusId: String, val value: Int) : StudyEvent {
        override val type: String get() = ANSWER
    }

    public companion object {
        /** `type` of [SessionStarted]. */
        public const val SESSION_STARTED: String = "session_started"
        /** `type` of [SessionEnded]. */
        public const val SESSION_ENDED: String = "session_ended"
        /** `type` of [TaskStarted]. */
        public const val TASK_STARTED: String = "task_started"
        /** `type` of [TaskEnded]. */
        public const val TASK_ENDED: String = "task_ended"

        /** Type of [ExplorationEnded]. */
        public const val EXPLORATION_ENDED: String = "exploration_ended"
        /** `type` of [StimulusShown]. */
        public const val STIMULUS_SHOWN: String = "stimulus_shown"
        /** `type` of [IconPressed]. */
        public const val ICON_PRESSED: String = "icon_pressed"
        /** `type` of [PlaybackStarted]. */
        public const val PLAYBACK_STARTED: String = "playback_started"
        /** `type` of [PlaybackFinished]. */
        public const val PLAYBACK_FINISHED: String = "playback_finished"
        /** `type` of [Answer]. */
        public const val ANSWER: String = "answer"

        /** [event]'s payload: its properties as a JSON object, in declaration order. Does not throw. */
        public fun payload(event: StudyEvent): JsonObject = JsonObject(
            when (event) {
                is SessionStarted -> linkedMapOf(
                    "protocol" to JsonString(event.protocolId), "revision" to JsonNumber(event.revision),
                    "participantIndex" to JsonNumber(event.participantIndex),
                    // A string: a 64-bit seed does not survive a JSON number, which is a double.
                    "seed" to JsonString(event.seed.toString()),
                )
                SessionEnded -> linkedMapOf()
                is TaskStarted -> linkedMapOf("task" to JsonString(event.taskId))
                is TaskEnded -> linkedMapOf("task" to JsonString(event.taskId))
                is ExplorationEnded -> linkedMapOf("task" to JsonString(event.taskId))
                is StimulusShown -> trial(event.taskId, event.stimulusId)
                is IconPressed -> trial(event.taskId, event.stimulusId)
                is PlaybackStarted -> trial(event.taskId, event.stimulusId)
                is PlaybackFinished -> trial(event.taskId, event.stimulusId)
                is Answer -> trial(event.taskId, event.stimulusId).apply { put("value", JsonNumber(event.value)) }
            },
        )

        /**
         * The event of [type] with [payload]. Throws [ProtocolException] (path `payload.MEMBER`)
         * when the payload lacks a member or has one of the wrong type, and [IllegalArgumentException] for an unknown [type].
         */
        public fun of(type: String, payload: JsonValue): StudyEvent {
            val p = JsonFields.of(payload, "payload", "payload")
            return when (type) {
                SESSION_STARTED -> SessionStarted(
                    p.string("protocol"), p.int("revision"), p.int("participantIndex"),
                    p.string("seed").toLongOrNull() ?: throw ProtocolException("payload.seed", "expected a decimal 64-bit integer"),
                )
                SESSION_ENDED -> SessionEnded
                TASK_STARTED -> TaskStarted(p.string("task"))
                TASK_ENDED -> TaskEnded(p.string("task"))
                EXPLORATION_ENDED -> ExplorationEnded(p.string("task"))
                STIMULUS_SHOWN -> StimulusShown(p.string("task"), p.string("stimulus"))
                ICON_PRESSED -> IconPressed(p.string("task"), p.string("stimulus"))
                PLAYBACK_STARTED -> PlaybackStarted(p.string("task"), p.string("stimulus"))
                PLAYBACK_FINISHED -> PlaybackFinished(p.string("task"), p.string("stimulus"))
                ANSWER -> Answer(p.string("task"), p.string("stimulus"), p.int("value"))
                else -> throw IllegalArgumentException("unknown event type \"${type.take(40)}\"")
            }
        }

        private fun trial(taskId: String, stimulusId: String) =
            linkedMapOf<String, JsonValue>("task" to JsonString(taskId), "stimulus" to JsonString(stimulusId))
    }
}
