package org.hapticon.study.export

import org.hapticon.study.ProtocolJson
import org.hapticon.study.StudyPlan
import org.hapticon.study.StudyProtocol
import org.hapticon.study.log.LogEntry
import org.hapticon.study.log.StudyEvent

/** Turns a session's event log into [ResponseRow]s. */
public object ResponseRows {
    /**
     * One row per Answer in [entries] (one participant's log, oldest first), in log order. The plan is rebuilt from the
     * log's SessionStarted event under [protocol] ([StudyPlan.ofSession]), which gives each answer its task position,
     * trial and question. The response time counts from the trial's last StimulusShown before the answer; presses are
     * the trial's IconPressed events before the answer. An empty log has no rows.
     *
     * Throws [IllegalArgumentException] when the log has no SessionStarted or names another protocol or revision, or
     * answers a trial the plan does not have or with a value off the scale.
     */
    public fun of(protocol: StudyProtocol, entries: List<LogEntry>): List<ResponseRow> {
        if (entries.isEmpty()) return emptyList()
        val events = entries.map { it.event }
        val plan = StudyPlan.ofSession(protocol, events)
        val trials = plan.trials.associateBy { it.task.id to it.stimulus.id }
        val shownAt = HashMap<Pair<String, String>, Long>()
        val presses = HashMap<Pair<String, String>, Int>()
        val rows = ArrayList<ResponseRow>()
        entries.forEachIndexed { i, entry ->
            when (val event = events[i]) {
                is StudyEvent.StimulusShown -> shownAt[event.taskId to event.stimulusId] = entry.timestampMillis
                is StudyEvent.IconPressed -> presses.merge(event.taskId to event.stimulusId, 1, Int::plus)
                is StudyEvent.Answer -> {
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
                        envelopeModel = ProtocolJson.modelName(protocol.envelopeModel),
                        participant = entry.participantId,
                        participantIndex = plan.schedule.participantIndex,
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
