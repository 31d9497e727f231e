package org.hapticon.study

import org.hapticon.study.schema.ProtocolException
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.study.design.OrderScheme

/** Noise played on the participant's headphones during a session, masking the actuator's sound. */
public enum class Masking(
    /** The name in protocol JSON. */
    public val jsonName: String,
) {
    /** No masking. */
    NONE("none"),

    /** White noise, as in the originating study. */
    WHITE("white"),

    /** Pink noise. */
    PINK("pink"),
    ;

    public companion object {
        /** The masking called [name] in protocol JSON, or null. */
        public fun fromJsonName(name: String): Masking? = entries.firstOrNull { it.jsonName == name }
    }
}

/**
 * A counterbalanced user study: [tasks] rated on [scale]. The tasks named in [fixedFirst] come first, in that order,
 * for every participant; the others follow in an order [taskOrder] counterbalances across participants.
 * [revision] is the protocol's own version (exported as `protocol_version`), distinct from the JSON schema version.
 * [envelopeModel] is how every stimulus's envelope is rendered for the participants (exported as `envelope_model`):
 * [EnvelopeModel.PROCESSING], what the originating study's participants felt, unless the researcher picks `paper`.
 * [participants] is the planned sample size when the protocol fixes one (null: open), and [masking] the noise played
 * on the participant's headphones to mask the actuator's sound.
 *
 * A value is always valid: the constructor throws [ProtocolException] naming the path of the first problem: a
 * blank or malformed id (ids are 1..64 of `A-Z a-z 0-9 _ . -`), a duplicate task or stimulus id, a task without
 * stimuli, a blank title or question, an unknown question placeholder, or a fixed-first id that is no task.
 */
public data class StudyProtocol(
    val id: String,
    val title: String,
    val scale: LikertScale,
    val tasks: List<StudyTask>,
    val taskOrder: OrderScheme = OrderScheme.FIXED,
    val fixedFirst: List<String> = emptyList(),
    val revision: Int = 1,
    val envelopeModel: EnvelopeModel = EnvelopeModel.DEFAULT,
    val participants: Int? = null,
    val masking: Masking = Masking.NONE,
) {
    init {
        requireId(id, "id")
        requireText(title, "title")
        if (revision < 1) throw ProtocolException("revision", "must be >= 1, was $revision")
        if (participants != null && participants < 1) throw ProtocolException("participants", "must be >= 1, was $participants")
        if (tasks.isEmpty()) throw ProtocolException("tasks", "a study needs at least one task")
        val taskIds = HashSet<String>()
        tasks.forEachIndexed { t, task -> checkTask(task, "tasks[$t]", taskIds) }
        val fixed = HashSet<String>()
        fixedFirst.forEachIndexed { i, taskId ->
            if (taskId !in taskIds) throw ProtocolException("fixedFirst[$i]", "no task has id \"$taskId\"")
            if (!fixed.add(taskId)) throw ProtocolException("fixedFirst[$i]", "task \"$taskId\" is listed twice")
        }
    }

    /** The task called [taskId], or null. */
    public fun task(taskId: String): StudyTask? = tasks.firstOrNull { it.id == taskId }

    /** The tasks whose order is counterbalanced: all but [fixedFirst], in protocol order. */
    public val counterbalancedTasks: List<StudyTask> get() = tasks.filter { it.id !in fixedFirst }

    public companion object {
        /** Longest id of a protocol, task or stimulus. */
        public const val MAX_ID_LENGTH: Int = 64

        private val ID = Regex("[A-Za-z0-9_.-]{1,$MAX_ID_LENGTH}")

        private fun checkTask(task: StudyTask, path: String, taskIds: MutableSet<String>) {
            requireId(task.id, "$path.id")
            if (!taskIds.add(task.id)) throw ProtocolException("$path.id", "duplicate task id \"${task.id}\"")
            requireText(task.title, "$path.title")
            requireText(task.question, "$path.question")
            QuestionTemplate.unknownPlaceholders(task.question).firstOrNull()?.let {
                throw ProtocolException(
                    "$path.question", "unknown placeholder {$it}; use ${QuestionTemplate.PLACEHOLDERS.joinToString(", ") { p -> "{$p}" }}",
                )
            }
            if (task.stimuli.isEmpty()) throw ProtocolException("$path.stimuli", "task \"${task.id}\" has no stimuli")
            val stimulusIds = HashSet<String>()
            task.stimuli.forEachIndexed { s, stimulus ->
                val at = "$path.stimuli[$s]"
                requireId(stimulus.id, "$at.id")
                if (!stimulusIds.add(stimulus.id)) throw ProtocolException("$at.id", "duplicate stimulus id \"${stimulus.id}\" in task \"${task.id}\"")
                stimulus.text?.let { requireText(it, "$at.text") }
                stimulus.sticker?.let { requireId(it, "$at.sticker") }
                stimulus.label?.let { requireText(it, "$at.label") }
            }
        }

        private fun requireId(value: String, path: String) {
            if (!ID.matches(value)) {
                throw ProtocolException(path, "expected 1..$MAX_ID_LENGTH of A-Z a-z 0-9 _ . -, got \"${value.take(80)}\"")
            }
        }

        private fun requireText(value: String, path: String) {
            if (value.isBlank()) throw ProtocolException(path, "must not be blank")
        }
    }
}
