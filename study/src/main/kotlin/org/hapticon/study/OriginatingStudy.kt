package org.hapticon.study

import org.hapticon.core.HapticIcon
import org.hapticon.study.design.OrderScheme

/**
 * The default protocol: the study the haptic icons come from. A virtual partner "has already sent" the messages;
 * the participant plays each icon and rates a statement on a 5-point agreement scale.
 *
 * 1. `icons`: the four preset icons alone, "Haptic icon N feels like stroking / hitting / knocking / hugging", one
 *    statement per icon, N its position in the participant's order. Always first.
 * 2. `text`: a short message with each icon, "This haptic icon enhances the effect of the text".
 * 3. `stickers`: a sticker with each icon, "This haptic icon enhances the touch effect of the sticker".
 *
 * Tasks 2 and 3 alternate across participants (2-3, 3-2, ...); the icons within each task follow a Williams square.
 */
public object OriginatingStudy {
    /** The protocol id. */
    public const val ID: String = "hapticon-icons"

    /** Id of task 1: the icons alone. */
    public const val ICONS_TASK: String = "icons"

    /** Id of task 2: text with icons. */
    public const val TEXT_TASK: String = "text"

    /** Id of task 3: stickers with icons. */
    public const val STICKERS_TASK: String = "stickers"

    private val GESTURES = listOf(
        Gesture(HapticIcon.STROKE, "stroking", "There, there. It'll be fine."),
        Gesture(HapticIcon.HIT, "hitting", "Take that!"),
        Gesture(HapticIcon.KNOCK, "knocking", "Hey, are you there?"),
        Gesture(HapticIcon.HUG, "hugging", "I missed you so much!"),
    )

    /** The protocol; see the type's description. */
    public val PROTOCOL: StudyProtocol = StudyProtocol(
        id = ID,
        title = "Haptic icons in instant messages",
        scale = LikertScale.AGREEMENT_5,
        taskOrder = OrderScheme.PAPER,
        fixedFirst = listOf(ICONS_TASK),
        tasks = listOf(
            StudyTask(
                id = ICONS_TASK,
                title = "Haptic icons",
                instructions = "Your partner has sent you four haptic icons. Press each icon to feel it, then rate the statement.",
                question = "Haptic icon {n} feels like {label}",
                stimulusOrder = OrderScheme.WILLIAMS,
                stimuli = GESTURES.map { Stimulus(id = it.icon.name, icon = it.icon, label = it.verb) },
            ),
            StudyTask(
                id = TEXT_TASK,
                title = "Text with haptic icons",
                instructions = "Your partner has sent you messages with haptic icons. Read each message, feel its icon, then rate the statement.",
                question = "This haptic icon enhances the effect of the text",
                stimulusOrder = OrderScheme.WILLIAMS,
                stimuli = GESTURES.map { Stimulus(id = "text_${it.icon.name}", icon = it.icon, text = it.text) },
            ),
            StudyTask(
                id = STICKERS_TASK,
                title = "Stickers with haptic icons",
                instructions = "Your partner has sent you stickers with haptic icons. Look at each sticker, feel its icon, then rate the statement.",
                question = "This haptic icon enhances the touch effect of the sticker",
                stimulusOrder = OrderScheme.WILLIAMS,
                stimuli = GESTURES.map { Stimulus(id = "sticker_${it.icon.name}", icon = it.icon, sticker = "sticker_${it.icon.name}") },
            ),
        ),
    )

    private class Gesture(val icon: HapticIcon, val verb: String, val text: String)
}
