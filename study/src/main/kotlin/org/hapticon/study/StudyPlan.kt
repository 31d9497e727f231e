package org.hapticon.study

import org.hapticon.study.ParticipantSchedule
import org.hapticon.study.log.StudyEvent

/**
 * A participant's session as an ordered list of [steps]: for each task of their [schedule], its intro, for a
 * [TaskPresentation.TOGETHER] task the screen of all its stimuli ([StudyStep.Explore]), one trial per stimulus in
 * their order, its end; then [StudyStep.Done].
 */
public class StudyPlan private constructor(
    /** The protocol the plan expands. */
    public val protocol: StudyProtocol,
    /** The task and stimulus orders of this participant. */
    public val schedule: ParticipantSchedule,
    /** The pseudonymous id of the participant. */
    public val participantId: String,
    /** Every step in order; the last is [StudyStep.Done]. */
    public val steps: List<StudyStep>,
) {
    /** The trial steps only, in order. */
    public val trials: List<StudyStep.Trial> get() = steps.filterIsInstance<StudyStep.Trial>()

    public companion object {
        /**
         * The plan of participant [participantIndex] (0-based) under [protocol] with random-scheme [seed]. A pure
         * function of its arguments. Throws [IllegalArgumentException] as [ParticipantSchedule.of] does.
         */
        public fun of(protocol: StudyProtocol, participantIndex: Int, seed: Long = 0L): StudyPlan {
            val schedule = ParticipantSchedule.of(protocol, participantIndex, seed)
            val steps = ArrayList<StudyStep>()
            schedule.tasks.forEachIndexed { t, task ->
                val position = t + 1
                steps += StudyStep.TaskIntro(task, position)
                if (task.presentation == TaskPresentation.TOGETHER) {
                    val shown = task.stimuli.withIndex().sortedBy { (i, s) -> s.number ?: (i + 1) }.map { it.value }
                    steps += StudyStep.Explore(task, position, shown)
                }
                schedule.stimuli.getValue(task.id).forEachIndexed { s, stimulus ->
                    steps += StudyStep.Trial(task, position, s + 1, stimulus, QuestionTemplate.fill(task.question, stimulus, s + 1))
                }
                steps += StudyStep.TaskEnd(task, position)
            }
            steps += StudyStep.Done
            return StudyPlan(protocol, schedule, ParticipantId.of(participantIndex), steps)
        }

        /**
         * The plan of a recorded session: the participant index and seed of the first SessionStarted in [events],
         * under [protocol]. This is how a restarted app, or an analysis, recovers the orders a participant saw.
         * Throws [IllegalArgumentException] when [events] hold no SessionStarted or it names another protocol or revision.
         */
        public fun ofSession(protocol: StudyProtocol, events: List<StudyEvent>): StudyPlan {
            val started = events.firstNotNullOfOrNull { it as? StudyEvent.SessionStarted }
                ?: throw IllegalArgumentException("the log has no ${StudyEvent.SESSION_STARTED} event")
            require(started.protocolId == protocol.id && started.revision == protocol.revision) {
                "the session ran protocol ${started.protocolId} revision ${started.revision}, not ${protocol.id} revision ${protocol.revision}"
            }
            return of(protocol, started.participantIndex, started.seed)
        }
    }
}
