package org.hapticon.study

import org.hapticon.study.design.OrderScheme

/**
 * One block of a study: an intro ([title], [instructions]), then one trial per stimulus in [stimuli], each asking
 * [question] with the placeholders of [QuestionTemplate] filled in. [stimulusOrder] counterbalances the order of the
 * stimuli across participants. [presentation] says whether each stimulus is shown and rated in turn
 * ([TaskPresentation.PER_TRIAL]) or all are shown together first and rated after ([TaskPresentation.TOGETHER]).
 *
 * Checked by [StudyProtocol], which knows the task's index and so can name the path of a problem.
 */
public data class StudyTask(
    val id: String,
    val title: String,
    val instructions: String,
    val stimuli: List<Stimulus>,
    val question: String,
    val stimulusOrder: OrderScheme = OrderScheme.FIXED,
    val presentation: TaskPresentation = TaskPresentation.PER_TRIAL,
)

/** How a task shows its stimuli. */
public enum class TaskPresentation(
    /** The name in protocol JSON. */
    public val jsonName: String,
) {
    /** One trial per stimulus: the stimulus and its question on one screen, in the participant's order. */
    PER_TRIAL("per-trial"),

    /**
     * The originating study's way: every stimulus of the task on one chat screen ([StudyStep.Explore]), pressed
     * freely in any order and as often as wanted, then the questionnaire items, one per stimulus, after it.
     */
    TOGETHER("together"),
    ;

    public companion object {
        /** The presentation called [name] in protocol JSON, or null. */
        public fun fromJsonName(name: String): TaskPresentation? = entries.firstOrNull { it.jsonName == name }
    }
}
