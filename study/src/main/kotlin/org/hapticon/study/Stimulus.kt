package org.hapticon.study

import org.hapticon.core.HapticIcon

/**
 * One thing a participant rates: a haptic [icon], shown alone or with a message [text] and/or a [sticker]
 * (a sticker id such as `sticker_stroke`). [label] is free text a question template can use as `{label}`.
 *
 * Checked by [StudyProtocol] (ids, blank strings), which knows the stimulus's place and so can name its path.
 */
public data class Stimulus(
    val id: String,
    val icon: HapticIcon,
    val text: String? = null,
    val sticker: String? = null,
    val label: String? = null,
)
