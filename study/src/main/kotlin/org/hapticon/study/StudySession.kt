package org.hapticon.study

import org.hapticon.study.log.StudyEvent

/**
 * Where a participant is in their [plan], derived only from the events recorded so far, so that a session killed
 * mid-task resumes at the exact next unanswered step. Holds no state of its own: a ViewModel keeps the event log and
 * asks again after every append.
 */
public class StudySession(
    /** The participant's plan. */
    public val plan: StudyPlan,
) {
    /**
     * The first step of the plan that [events] have not completed: a task intro until its TaskStarted, an
     * exploration until its ExplorationEnded, a trial until
     * its Answer, a task end until its TaskEnded; [StudyStep.Done] when all are. Events that match no step (for example
     * presses and playback) do not move the session. Does not throw.
     */
    public fun nextStep(events: List<StudyEvent>): StudyStep {
        val completed = completedKeys(events)
        return plan.steps.firstOrNull { step -> key(step)?.let { it !in completed } ?: true } ?: StudyStep.Done
    }

    /** How many of the plan's trials [events] have answered. Does not throw. */
    public fun answeredTrials(events: List<StudyEvent>): Int {
        val completed = completedKeys(events)
        return plan.trials.count { key(it) in completed }
    }

    /** True when every step is complete and SessionEnded is recorded. */
    public fun isFinished(events: List<StudyEvent>): Boolean =
        nextStep(events) == StudyStep.Done && events.any { it == StudyEvent.SessionEnded }

    // Steps and events meet on string keys, so that one set lookup answers "is this step done?".
    private fun completedKeys(events: List<StudyEvent>): Set<String> = events.mapNotNullTo(HashSet()) { event ->
        when (event) {
            is StudyEvent.TaskStarted -> "intro/${event.taskId}"
            is StudyEvent.ExplorationEnded -> "explore/${event.taskId}"
            is StudyEvent.Answer -> "trial/${event.taskId}/${event.stimulusId}"
            is StudyEvent.TaskEnded -> "end/${event.taskId}"
            else -> null
        }
    }

    private fun key(step: StudyStep): String? = when (step) {
        is StudyStep.TaskIntro -> "intro/${step.task.id}"
        is StudyStep.Explore -> "explore/${step.task.id}"
        is StudyStep.Trial -> "trial/${step.task.id}/${step.stimulus.id}"
        is StudyStep.TaskEnd -> "end/${step.task.id}"
        StudyStep.Done -> null
    }
}
