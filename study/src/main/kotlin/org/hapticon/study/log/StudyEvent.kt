package org.hapticon.study.log

import kotlinx.serialization.DeserializationStrategy
import kotlinx.serialization.Serializable
import kotlinx.serialization.SerializationStrategy
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import org.hapticon.core.io.SchemaJson
import org.hapticon.study.schema.ProtocolException
import org.hapticon.study.schema.StudyReport

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
        public fun payload(event: StudyEvent): JsonObject = when (event) {
            is SessionStarted -> encode(SessionPayload.serializer(), SessionPayload(event.protocolId, event.revision, event.participantIndex, event.seed.toString()))
            SessionEnded -> encode(EmptyPayload.serializer(), EmptyPayload())
            is TaskStarted -> encode(TaskPayload.serializer(), TaskPayload(event.taskId))
            is TaskEnded -> encode(TaskPayload.serializer(), TaskPayload(event.taskId))
            is ExplorationEnded -> encode(TaskPayload.serializer(), TaskPayload(event.taskId))
            is StimulusShown -> encode(TrialPayload.serializer(), TrialPayload(event.taskId, event.stimulusId))
            is IconPressed -> encode(TrialPayload.serializer(), TrialPayload(event.taskId, event.stimulusId))
            is PlaybackStarted -> encode(TrialPayload.serializer(), TrialPayload(event.taskId, event.stimulusId))
            is PlaybackFinished -> encode(TrialPayload.serializer(), TrialPayload(event.taskId, event.stimulusId))
            is Answer -> encode(AnswerPayload.serializer(), AnswerPayload(event.taskId, event.stimulusId, event.value))
        }

        /**
         * The event of [type] with [payload]. Throws [ProtocolException] (path `payload.MEMBER`)
         * when the payload lacks a member or has one of the wrong type, and [IllegalArgumentException] for an unknown [type].
         */
        public fun of(type: String, payload: JsonElement): StudyEvent {
            fun <T> read(deserializer: DeserializationStrategy<T>): T = SchemaJson.decode(deserializer, payload, PAYLOAD_REPORT, "payload")
            return when (type) {
                SESSION_STARTED -> read(SessionPayload.serializer()).let {
                    SessionStarted(
                        it.protocol, it.revision, it.participantIndex,
                        it.seed.toLongOrNull() ?: throw ProtocolException("payload.seed", "expected a decimal 64-bit integer"),
                    )
                }
                SESSION_ENDED -> SessionEnded.also { read(EmptyPayload.serializer()) }
                TASK_STARTED -> TaskStarted(read(TaskPayload.serializer()).task)
                TASK_ENDED -> TaskEnded(read(TaskPayload.serializer()).task)
                EXPLORATION_ENDED -> ExplorationEnded(read(TaskPayload.serializer()).task)
                STIMULUS_SHOWN -> read(TrialPayload.serializer()).let { StimulusShown(it.task, it.stimulus) }
                ICON_PRESSED -> read(TrialPayload.serializer()).let { IconPressed(it.task, it.stimulus) }
                PLAYBACK_STARTED -> read(TrialPayload.serializer()).let { PlaybackStarted(it.task, it.stimulus) }
                PLAYBACK_FINISHED -> read(TrialPayload.serializer()).let { PlaybackFinished(it.task, it.stimulus) }
                ANSWER -> read(AnswerPayload.serializer()).let { Answer(it.task, it.stimulus, it.value) }
                else -> throw IllegalArgumentException("unknown event type \"${type.take(40)}\"")
            }
        }

        private val PAYLOAD_REPORT = StudyReport("payload", emptyMap())

        // The payload holds strings and Ints only, so kotlinx spells its numbers as the old writer did; its text is
        // hashed, and LogEntry.canonicalJson restores the old writer's escapes (LogEntry).
        private fun <T> encode(serializer: SerializationStrategy<T>, value: T): JsonObject =
            SchemaJson.encodeToElement(serializer, value) as JsonObject
    }
}

// Payloads, members in the order they are written (and hashed). The seed is a string: a 64-bit seed does not
// survive a JSON number, which is a double.
@Serializable
internal class SessionPayload(val protocol: String, val revision: Int, val participantIndex: Int, val seed: String)

@Serializable
internal class EmptyPayload

@Serializable
internal class TaskPayload(val task: String)

@Serializable
internal class TrialPayload(val task: String, val stimulus: String)

@Serializable
internal class AnswerPayload(val task: String, val stimulus: String, val value: Int)
