package org.hapticon.app.feature.gesture

import org.hapticon.sensor.live.PlotSource
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.ExperimentalComposeUiApi
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.clearAndSetSemantics
import androidx.compose.ui.input.pointer.pointerInteropFilter
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import org.hapticon.app.ui.LivePlot
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.TouchGestureSource
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice

/** A pad to touch while the touchscreen records: every event goes to [source]. */
@OptIn(ExperimentalComposeUiApi::class)
@Composable
fun TouchPad(source: TouchGestureSource, modifier: Modifier = Modifier) {
    Box(
        modifier
            .fillMaxWidth()
            .height(160.dp)
            .background(MaterialTheme.colorScheme.secondaryContainer, MaterialTheme.shapes.medium)
            .semantics { contentDescription = "Touch pad: press, stroke or tap here while recording" }
            .pointerInteropFilter { event ->
                source.onMotionEvent(event)
                true
            },
    ) {
        Text("Touch here", Modifier.padding(12.dp), style = MaterialTheme.typography.labelLarge)
    }
}

@Composable
internal fun SourcePicker(selected: GestureSourceKind, enabled: Boolean, onSelect: (GestureSourceKind) -> Unit) {
    DropdownField("Source", SingleChoice(GestureSourceKind.entries, selected) { it.label }, onSelect, enabled = enabled)
}

@Composable
internal fun LivePlots(plot: PlotSource, channels: List<String>, revision: Long) {
    channels.take(MAX_PLOTTED).forEachIndexed { i, name -> NamedPlot(name) { LivePlot(plot, i, revision, name) } }
}

/** A plot under its channel's name: without it several stacked plots cannot be told apart. */
@Composable
internal fun NamedPlot(name: String, plot: @Composable () -> Unit) {
    // The plot's own description names the channel for TalkBack; the visible name would only repeat it.
    Text(name, style = MaterialTheme.typography.labelMedium, modifier = Modifier.clearAndSetSemantics {})
    plot()
}

@Composable
internal fun Message(message: String?, onDismiss: () -> Unit) {
    if (message == null) return
    Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
        Text(message, Modifier.weight(1f), style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.error)
        TextButton(onClick = onDismiss) { Text("Dismiss") }
    }
}

/** A tab still reading what it shows from storage. */
@Composable
internal fun GestureLoading() {
    Box(Modifier.fillMaxSize(), Alignment.Center) { CircularProgressIndicator() }
}

/** Channels plotted live at most (the rest are recorded but not drawn). */
internal const val MAX_PLOTTED = 6
