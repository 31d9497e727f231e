package org.hapticon.study

import org.hapticon.study.design.Counterbalancing

/**
 * What one participant does, in order: [tasks] (fixed-first tasks, then the counterbalanced ones), and the order of
 * each task's stimuli in [stimuli], keyed by task id.
 */
public class ParticipantSchedule private constructor(
    /** The 0-based participant index the schedule is for. */
    public val participantIndex: Int,
    /** The seed of the random schemes. */
    public val seed: Long,
    /** The tasks in the order this participant does them. */
    public val tasks: List<StudyTask>,
    /** Each task's stimuli in the order this participant sees them, keyed by task id. */
    public val stimuli: Map<String, List<Stimulus>>,
) {
    public companion object {
        /**
         * The schedule of participant [participantIndex] (0-based) under [protocol], a pure function of its arguments.
         * The tasks are ordered by [StudyProtocol.taskOrder] after [StudyProtocol.fixedFirst]; the stimuli of the task at
         * protocol index t by its [StudyTask.stimulusOrder], using random stream t + 1 (stream 0 is the task order).
         *
         * Throws [IllegalArgumentException] when [participantIndex] is negative or a full design has too many items.
         */
        public fun of(protocol: StudyProtocol, participantIndex: Int, seed: Long = 0L): ParticipantSchedule {
            require(participantIndex >= 0) { "participantIndex must be >= 0, was $participantIndex" }
            val fixed = protocol.fixedFirst.map { protocol.task(it)!! }
            val free = protocol.counterbalancedTasks
            val tasks = fixed + Counterbalancing.order(protocol.taskOrder, free.size, participantIndex, seed).map { free[it] }
            val stimuli = LinkedHashMap<String, List<Stimulus>>()
            for (task in tasks) {
                val stream = protocol.tasks.indexOf(task) + 1
                stimuli[task.id] = Counterbalancing.order(task.stimulusOrder, task.stimuli.size, participantIndex, seed, stream)
                    .map { task.stimuli[it] }
            }
            return ParticipantSchedule(participantIndex, seed, tasks, stimuli)
        }
    }
}
