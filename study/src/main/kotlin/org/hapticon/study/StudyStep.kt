package org.hapticon.study

/** One screen of a session, in the order of a [StudyPlan]. */
public sealed interface StudyStep {
    /** The intro of [task], the [taskPosition]-th (1-based) task of the participant; left by a TaskStarted event. */
    public data class TaskIntro(val task: StudyTask, val taskPosition: Int) : StudyStep

    /**
     * Every stimulus of [task] (a [TaskPresentation.TOGETHER] task, the [taskPosition]-th) on one chat screen, in
     * [stimuli] order (by number when they have one), pressed freely; left by an ExplorationEnded event, after
     * which the task's trials ask its questions.
     */
    public data class Explore(val task: StudyTask, val taskPosition: Int, val stimuli: List<Stimulus>) : StudyStep

    /**
     * One rating: [stimulus] at 1-based [trial] within [task] (the [taskPosition]-th task), asking [question] (the
     * task's template filled in); left by an Answer event.
     */
    public data class Trial(val task: StudyTask, val taskPosition: Int, val trial: Int, val stimulus: Stimulus, val question: String) : StudyStep

    /** The end of [task]; left by a TaskEnded event. */
    public data class TaskEnd(val task: StudyTask, val taskPosition: Int) : StudyStep

    /** Every task is done; the session is over once SessionEnded is recorded. */
    public data object Done : StudyStep
}
