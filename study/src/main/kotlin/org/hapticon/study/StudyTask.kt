package org.hapticon.study

import org.hapticon.study.design.OrderScheme

/**
 * One block of a study: an intro ([title], [instructions]), then one trial per stimulus in [stimuli], each asking
 * [question] with the placeholders of [QuestionTemplate] filled in. [stimulusOrder] counterbalances the order of the
 * stimuli across participants.
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
)
