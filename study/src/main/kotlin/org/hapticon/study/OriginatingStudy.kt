package org.hapticon.study

import org.hapticon.core.HapticIcon
import org.hapticon.study.design.OrderScheme

/**
 * The built-in protocols of the study the haptic icons come from (Wei et al.; its text is 000_f26496a15a0d284b.txt):
 * [PROTOCOL], the default, rates each icon in its own trial; [PAPER_PROTOCOL] runs the paper's own procedure. Both
 * play the `processing` envelopes, what the study's participants felt (the Sound library of Processing 3, :66, :95).
 *
 * [PROTOCOL]: the study the haptic icons come from. A virtual partner "has already sent" the messages (:95); the
 * participant plays each icon and rates a statement on the paper's 5-point Likert scale, 1 strongly disagree .. 5
 * strongly agree (:121).
 *
 * 1. `icons`: the four preset icons alone, "Haptic icon N feels like stroking / hitting / knocking / hugging" (:121),
 *    one statement per icon, N its position in the participant's order. Always first (:127).
 * 2. `text`: a short message with each icon, "This haptic icon enhances the effect of the text" (the paper's "This
 *    haptic icon enhance the effect of text.", :121, grammar mended). The texts are ours: the paper shows its own
 *    only in images (Fig. 4, Tables 4-5, :74, :95, :97).
 * 3. `stickers`: a sticker with each icon, "This haptic icon enhances the touch effect of the sticker" (:121). The
 *    stickers are ours: the paper's were WeChat dialog boxes, not published (:95).
 *
 * Tasks 2 and 3 alternate across participants (2-3, 3-2, ...: "counterbalanced between participants", :127); the
 * icons within each task follow a Williams square (the paper shows them on one screen; the order is ours).
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

    /** Id of [PAPER_PROTOCOL]. */
    public const val PAPER_ID: String = "hapticon-icons-paper"

    /** Participants in the originating study: 16, 4 male and 12 female, aged 25-30 (000_f26496a15a0d284b.txt:117). */
    public const val PAPER_PARTICIPANTS: Int = 16

    /** The per-trial protocol; see the type's description. */
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

    /**
     * The originating study's procedure, read-only in the app: [PAPER_PARTICIPANTS] participants; task 1 (the icons)
     * first, tasks 2 (text) and 3 (stickers) counterbalanced as in the paper (2-3 for one participant, 3-2 for the
     * next; 000_f26496a15a0d284b.txt:127); the icons numbered as in the paper's items (icon 1 = stroke, 2 = hit,
     * 3 = knock, 4 = hug, :121) rather than by their position; in every task the four icons shown together on one
     * chat screen (Fig. 4, :95) and pressed (:127; how often: paper silent, ours freely,
     * [TaskPresentation.TOGETHER]), then the questionnaire items answered after the task (on a computer in the
     * paper, :127; in the app here); white noise on the participant's headphones (:125).
     */
    public val PAPER_PROTOCOL: StudyProtocol = PROTOCOL.copy(
        id = PAPER_ID,
        title = "Haptic icons in instant messages (the paper's procedure)",
        participants = PAPER_PARTICIPANTS,
        masking = Masking.WHITE,
        tasks = PROTOCOL.tasks.map { task ->
            task.copy(
                instructions = task.instructions.replace("Press each icon to feel it, then rate the statement.", "Press the icons freely, as often as you like; then rate the statements.")
                    .replace("Read each message, feel its icon, then rate the statement.", "Read the messages and press their icons freely; then rate the statements.")
                    .replace("Look at each sticker, feel its icon, then rate the statement.", "Look at the stickers and press their icons freely; then rate the statements."),
                // Rated after the task, so each item names its icon by number.
                question = task.question.replace("This haptic icon", "Haptic icon {n}").replace("of the text", "of its text")
                    .replace("of the sticker", "of its sticker"),
                stimulusOrder = OrderScheme.FIXED,
                presentation = TaskPresentation.TOGETHER,
                stimuli = task.stimuli.mapIndexed { i, stimulus -> stimulus.copy(number = i + 1) },
            )
        },
    )

    /** The built-in protocols, the default first. */
    public val BUILT_IN: List<StudyProtocol> = listOf(PROTOCOL, PAPER_PROTOCOL)

    private class Gesture(val icon: HapticIcon, val verb: String, val text: String)
}
