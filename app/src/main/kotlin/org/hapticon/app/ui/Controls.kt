package org.hapticon.app.ui

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.shape.CornerSize
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.ui.geometry.Size
import androidx.compose.ui.graphics.Shape
import androidx.compose.ui.layout.Layout
import androidx.compose.ui.text.TextStyle
import androidx.compose.ui.unit.Constraints
import androidx.compose.ui.unit.Density
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.BoxWithConstraints
import androidx.compose.foundation.layout.heightIn
import androidx.compose.foundation.selection.selectable
import androidx.compose.foundation.selection.selectableGroup
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.Spacer
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.layout.width
import androidx.compose.foundation.selection.toggleable
import androidx.compose.material3.DropdownMenu
import androidx.compose.material3.DropdownMenuItem
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.RadioButton
import androidx.compose.material3.SegmentedButton
import androidx.compose.material3.SegmentedButtonDefaults
import androidx.compose.material3.SingleChoiceSegmentedButtonRow
import androidx.compose.material3.Switch
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.text.rememberTextMeasurer
import androidx.compose.ui.unit.Dp
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import org.hapticon.app.designsystem.HapticonIcons

/**
 * What a single-choice control shows: the [options] in order, the [selected] one, and the text [optionLabel]
 * gives each. [DropdownField] and [SegmentedChoice] both take one.
 *
 * [selected] need not be one of [options]: a value kept from before (a stored channel the board no longer
 * reports, a participant number past the list) is still shown as the current choice, and the user can pick
 * one of [options] instead. So nothing here requires it, and a screen never crashes on such a value.
 */
@Immutable
class SingleChoice<T>(val options: List<T>, val selected: T, val optionLabel: (T) -> String)

/**
 * A labelled drop-down: a button showing [label] and [choice]'s selected option; choosing an option calls
 * [onSelect]. Read by screen readers as "[label], [selected option]".
 */
@Composable
fun <T> DropdownField(
    label: String,
    choice: SingleChoice<T>,
    onSelect: (T) -> Unit,
    modifier: Modifier = Modifier,
    enabled: Boolean = true,
) {
    var expanded by remember { mutableStateOf(false) }
    Column(modifier) {
        Text(label, style = MaterialTheme.typography.labelMedium)
        Box {
            OutlinedButton(
                onClick = { expanded = true },
                enabled = enabled,
                shape = WrappingButtonShape,
                modifier = Modifier.semantics {
                    contentDescription = label
                    stateDescription = choice.optionLabel(choice.selected)
                },
            ) {
                // Weighted so a label too long for one line wraps and still leaves room for the arrow.
                Text(choice.optionLabel(choice.selected), Modifier.weight(1f, fill = false))
                Spacer(Modifier.width(4.dp))
                Icon(HapticonIcons.ArrowDropDown, contentDescription = null, modifier = Modifier.size(18.dp))
            }
            DropdownMenu(expanded = expanded, onDismissRequest = { expanded = false }) {
                for (option in choice.options) {
                    DropdownMenuItem(
                        text = { Text(choice.optionLabel(option)) },
                        onClick = {
                            expanded = false
                            onSelect(option)
                        },
                    )
                }
            }
        }
    }
}

/**
 * One choice among a few options ([choice]): Material's segmented buttons while every label fits its segment on one
 * line, otherwise (the largest font sizes, a narrow screen) the same choice as a column of radio rows, so a
 * label never breaks inside a word or spills over its neighbour. Material 3 gives segmented buttons short
 * labels of equal width; radio buttons are its single-choice control for labels that need the room.
 */
@Composable
fun <T> SegmentedChoice(choice: SingleChoice<T>, onSelect: (T) -> Unit, modifier: Modifier = Modifier, enabled: Boolean = true) {
    val measurer = rememberTextMeasurer()
    val style = MaterialTheme.typography.labelLarge
    val density = LocalDensity.current
    BoxWithConstraints(modifier.fillMaxWidth()) {
        val segment = maxWidth / choice.options.size
        val fits = choice.options.all { option ->
            val text = with(density) { measurer.measure(choice.optionLabel(option), style, maxLines = 1, softWrap = false).size.width.toDp() }
            text + segmentChrome(option == choice.selected) <= segment
        }
        if (fits) {
            SingleChoiceSegmentedButtonRow(Modifier.fillMaxWidth()) {
                choice.options.forEachIndexed { i, option ->
                    SegmentedButton(
                        selected = option == choice.selected,
                        onClick = { onSelect(option) },
                        enabled = enabled,
                        shape = SegmentedButtonDefaults.itemShape(i, choice.options.size),
                        label = { Text(choice.optionLabel(option), maxLines = 1) },
                    )
                }
            }
        } else {
            Column(Modifier.fillMaxWidth().selectableGroup()) {
                for (option in choice.options) {
                    Row(
                        Modifier.fillMaxWidth().heightIn(min = 48.dp)
                            .selectable(option == choice.selected, enabled = enabled, role = Role.RadioButton, onClick = { onSelect(option) }),
                        verticalAlignment = Alignment.CenterVertically,
                    ) {
                        RadioButton(selected = option == choice.selected, onClick = null, enabled = enabled)
                        // Disabled (the protocol while a board streams): Material's 38 % of onSurface, as on the radio.
                        Text(
                            choice.optionLabel(option), style = MaterialTheme.typography.bodyLarge, modifier = Modifier.padding(start = 12.dp),
                            color = if (enabled) Color.Unspecified else MaterialTheme.colorScheme.onSurface.copy(alpha = 0.38f),
                        )
                    }
                }
            }
        }
    }
}

/**
 * What a segment needs beside its label (Material 3's SegmentedButton): 12 dp padding on each side and its
 * 1 dp outline, and on the selected segment the 18 dp check mark with its 8 dp gap.
 */
private fun segmentChrome(selected: Boolean): Dp = 26.dp + if (selected) 26.dp else 0.dp

/** A whole-row switch: the row is the touch target and reads as one switch named [label]. */
@Composable
fun SwitchRow(label: String, checked: Boolean, onCheckedChange: (Boolean) -> Unit, modifier: Modifier = Modifier, enabled: Boolean = true) {
    Row(
        modifier
            .fillMaxWidth()
            .toggleable(value = checked, enabled = enabled, role = Role.Switch, onValueChange = onCheckedChange)
            .padding(vertical = 8.dp),
        verticalAlignment = Alignment.CenterVertically,
        horizontalArrangement = Arrangement.SpaceBetween,
    ) {
        // Material 3 list items keep 16 dp between a wrapped label and the trailing switch.
        Text(label, style = MaterialTheme.typography.titleMedium, modifier = Modifier.weight(1f).padding(end = 16.dp))
        Switch(checked = checked, onCheckedChange = null, enabled = enabled)
    }
}

/**
 * A label on the left, its value on the right; when both do not fit one line (the largest font sizes) the
 * value moves under its label whole instead of being squeezed into a column of broken words beside it.
 */
@OptIn(ExperimentalLayoutApi::class)
@Composable
fun LabeledValue(label: String, value: String, modifier: Modifier = Modifier, style: TextStyle = MaterialTheme.typography.bodyMedium, labelStyle: TextStyle = style) {
    FlowRow(modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
        Text(label, style = labelStyle, modifier = Modifier.padding(end = 8.dp))
        Text(value, style = style)
    }
}

/**
 * A group of buttons: side by side while every label fits on one line (as a `Row` with [spacing]), otherwise
 * stacked, each button the full width, [spacing] apart. Material 3 stacks buttons that do not fit side by side
 * (its dialogs' "stacked" button layout) rather than letting a label break inside a pill next to its
 * neighbour; at font scale 2.0 "Next | Send condition again" became a two-line oval beside a short button.
 * The decision uses each button's max intrinsic width, the width at which its label needs no line break.
 */
@Composable
fun ButtonRow(modifier: Modifier = Modifier, spacing: Dp = 12.dp, content: @Composable () -> Unit) {
    Layout(content, modifier) { measurables, constraints ->
        val gap = spacing.roundToPx()
        val natural = measurables.map { it.maxIntrinsicWidth(Constraints.Infinity) }
        val sideBySide = !constraints.hasBoundedWidth ||
            natural.sum() + gap * (measurables.size - 1).coerceAtLeast(0) <= constraints.maxWidth
        if (sideBySide) {
            val placeables = measurables.mapIndexed { i, m ->
                m.measure(constraints.copy(minWidth = 0, minHeight = 0, maxWidth = minOf(natural[i], constraints.maxWidth)))
            }
            val width = (placeables.sumOf { it.width } + gap * (placeables.size - 1).coerceAtLeast(0)).coerceIn(constraints.minWidth, constraints.maxWidth)
            val height = (placeables.maxOfOrNull { it.height } ?: 0).coerceIn(constraints.minHeight, constraints.maxHeight)
            layout(width, height) {
                var x = 0
                for (p in placeables) {
                    p.placeRelative(x, 0)
                    x += p.width + gap
                }
            }
        } else {
            val placeables = measurables.map { it.measure(Constraints.fixedWidth(constraints.maxWidth).copy(maxHeight = constraints.maxHeight)) }
            val height = (placeables.sumOf { it.height } + gap * (placeables.size - 1)).coerceIn(constraints.minHeight, constraints.maxHeight)
            layout(constraints.maxWidth, height) {
                var y = 0
                for (p in placeables) {
                    p.placeRelative(0, y)
                    y += p.height + gap
                }
            }
        }
    }
}

/**
 * Material 3's fully rounded button shape, with the corner radius capped at 32 dp so a label that needs two
 * lines (a long protocol name at font scale 2.0) sits in a rounded rectangle instead of an oval whose curve
 * cuts into the first and last words. A one-line button at any font scale (at most 64 dp tall) is exactly
 * the pill of `ButtonDefaults.shape`.
 */
val WrappingButtonShape: Shape = RoundedCornerShape(CappedHalfCorner(32.dp))

/** Half the shorter side (a pill) up to [cap]. */
private class CappedHalfCorner(private val cap: Dp) : CornerSize {
    override fun toPx(shapeSize: Size, density: Density): Float = minOf(shapeSize.minDimension / 2, with(density) { cap.toPx() })
}
