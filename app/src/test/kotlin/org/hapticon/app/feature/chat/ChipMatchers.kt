package org.hapticon.app.feature.chat

import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasText

/*
 * The conversation's chips as TalkBack names them, in Compose's merged tree: by their visible words alone (WCAG 2.5.3
 * Label in Name; TalkBackNodeTreeTest checks the spoken names on the real node tree).
 */

/** The composer's chip of icon [name] ("knock"): the one with that text that also previews on a long press. */
fun composerIconChip(name: String): SemanticsMatcher = hasText(name) and SemanticsMatcher.keyIsDefined(SemanticsActions.OnLongClick)

/** The composer's chip of pattern [name] ("ramp, pattern"). */
fun composerPatternChip(name: String): SemanticsMatcher = composerIconChip(name) and hasText("pattern")

/** A message's chip that plays its icon or pattern [name] ("Feel hug"). */
fun feelChip(name: String): SemanticsMatcher = hasText("Feel $name") and hasClickAction()
