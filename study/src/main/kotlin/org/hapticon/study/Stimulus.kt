package org.hapticon.study

import org.hapticon.core.HapticIcon

/**
 * One thing a participant rates: a haptic [icon], shown alone or with a message [text] and/or a [sticker]
 * (a sticker id such as `sticker_stroke`). [label] is free text a question template can use as `{label}`.
 * [number] is a fixed number the participant knows the stimulus by (the originating study's icon 1 = stroke,
 * 2 = hit, 3 = knock, 4 = hug); `{n}` uses it instead of the position when set.
 *
 * Checked by [StudyProtocol] (ids, blank strings), which knows the stimulus's place and so can name its path.
 */
public data class Stimulus(
    val id: String,
    val icon: HapticIcon,
    val text: String? = null,
    val sticker: String? = null,
    val label: String? = null,
    val number: Int? = null,
)
