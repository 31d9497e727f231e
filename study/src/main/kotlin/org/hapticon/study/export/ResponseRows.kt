package org.hapticon.study.export

import org.hapticon.study.StudyPlan
import org.hapticon.study.StudyProtocol
import org.hapticon.study.StudyStep
import org.hapticon.study.log.LogEntry
import org.hapticon.study.log.StudyEvent

/** Turns a session's event log into [ResponseRow]s. */
public object ResponseRows {
    /**
     * One row per Answer in [entries] (one participant's log, oldest first), in log order. The plan is rebuilt from the
     * log's SessionStarted event under [protocol], which gives each answer its task position, trial and question.
     * The response time counts from the trial's last StimulusShown before the answer; presses are the trial's
     * IconPressed events before the answer.
     *
     * Throws [IllegalArgumentException] when the log has no SessionStarted before its first answer, names another
     * protocol or revision, or answers a trial the plan does not have or with a value off the scale.
     */
    public fun of(protocol: StudyProtocol, entries: List<LogEntry>): List<ResponseRow> {
        var plan: StudyPlan? = null
        val trials = HashMap<Pair<String, String>, StudyStep.Trial>()
        val shownAt = HashMap<Pair<String, String>, Long>()
        val presses = HashMap<Pair<String, String>, Int>()
        val rows = ArrayList<ResponseRow>()
        for (entry in entries) {
            when (val event = entry.event) {
                is StudyEvent.SessionStarted -> {
                    require(event.protocolId == protocol.id && event.revision == protocol.revision) {
                        "entry ${entry.sequence}: the session ran protocol ${event.protocolId} revision ${event.revision}, " +
                            "not ${protocol.id} revision ${protocol.revision}"
                    }
                    plan = StudyPlan.of(protocol, event.participantIndex, event.seed).also { p ->
                        trials.clear()
                        p.trials.associateByTo(trials) { it.task.id to it.stimulus.id }
                    }
                }
                is StudyEvent.StimulusShown -> shownAt[event.taskId to event.stimulusId] = entry.timestampMillis
                is StudyEvent.IconPressed -> presses.merge(event.taskId to event.stimulusId, 1, Int::plus)
                is StudyEvent.Answer -> {
                    val started = requireNotNull(plan) { "entry ${entry.sequence}: an answer before SessionStarted" }
                    val key = event.taskId to event.stimulusId
                    val trial = requireNotNull(trials[key]) {
                        "entry ${entry.sequence}: task ${event.taskId} has no stimulus ${event.stimulusId} in this protocol"
                    }
                    require(protocol.scale.accepts(event.value)) {
                        "entry ${entry.sequence}: answer ${event.value} is outside 1..${protocol.scale.points}"
                    }
                    rows += ResponseRow(
                        studyId = protocol.id,
                        protocolVersion = protocol.revision,
                        participant = entry.participantId,
                        participantIndex = started.schedule.participantIndex,
                        task = trial.task.id,
                        taskPosition = trial.taskPosition,
                        trial = trial.trial,
                        stimulus = trial.stimulus.id,
                        icon = trial.stimulus.icon.name,
                        text = trial.stimulus.text,
                        sticker = trial.stimulus.sticker,
                        question = trial.question,
                        response = event.value,
                        responseTimeMillis = shownAt[key]?.let { entry.timestampMillis - it },
                        iconPresses = presses[key] ?: 0,
                        answeredAtMillis = entry.timestampMillis,
                    )
                }
                else -> Unit
            }
        }
        return rows
    }
}
