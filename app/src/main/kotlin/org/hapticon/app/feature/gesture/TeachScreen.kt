package org.hapticon.app.feature.gesture

import org.hapticon.sensor.live.PlotSource
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.FilterChip
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.gesture.TouchGestureSource
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.LabeledValue
import org.hapticon.gesture.recognition.GestureLabel
import java.util.Locale
import org.hapticon.app.ui.ButtonRow

/** The Teach tab wired to [viewModel]; [touch] is the touchscreen source the pad feeds, [onImportModel] opens the file picker. */
@Composable
fun TeachRoute(viewModel: TeachViewModel, touch: TouchGestureSource?, onImportModel: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onImportModel) {
        TeachActions(
            onSelectSource = viewModel::selectSource,
            onToggleLabel = viewModel::toggleLabel,
            onSetTakesPerLabel = viewModel::setTakesPerLabel,
            onStartTake = viewModel::startTake,
            onStopTake = viewModel::stopTake,
            onTrain = viewModel::train,
            onClearExamples = viewModel::clearExamples,
            onImportModel = onImportModel,
            onDismissMessage = viewModel::dismissMessage,
        )
    }
    TeachScreen(uiState, viewModel.plot, touch, actions)
}

/** What the Teach tab can ask for. */
@Immutable
class TeachActions(
    val onSelectSource: (GestureSourceKind) -> Unit = {},
    val onToggleLabel: (GestureLabel) -> Unit = {},
    val onSetTakesPerLabel: (Int) -> Unit = {},
    val onStartTake: () -> Unit = {},
    val onStopTake: () -> Unit = {},
    val onTrain: () -> Unit = {},
    val onClearExamples: () -> Unit = {},
    val onImportModel: () -> Unit = {},
    val onDismissMessage: () -> Unit = {},
)

/** Choose labels and takes, record the takes one by one, train, see the accuracy; or import a model. */
@Composable
fun TeachScreen(uiState: TeachUiState, plot: PlotSource, touch: TouchGestureSource?, actions: TeachActions) {
    when (uiState) {
        TeachUiState.Loading -> GestureLoading()
        is TeachUiState.Ready -> TeachContent(uiState, plot, touch, actions)
    }
}

@OptIn(androidx.compose.foundation.layout.ExperimentalLayoutApi::class)
@Composable
private fun TeachContent(state: TeachUiState.Ready, plot: PlotSource, touch: TouchGestureSource?, actions: TeachActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions.onDismissMessage() }
        Text(state.model?.let { "Model: ${it.labels.joinToString { l -> l.id }} from ${it.channels.joinToString()} at ${it.sampleRate} Hz" } ?: "No model yet")
        SourcePicker(state.sourceKind, !state.recording) { actions.onSelectSource(it) }
        Text("Gestures to teach", style = MaterialTheme.typography.titleMedium)
        FlowRow(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
            for (label in GestureLabel.ALL) {
                FilterChip(selected = label in state.labels, onClick = { actions.onToggleLabel(label) }, label = { Text(label.id) }, enabled = !label.isNone)
            }
        }
        DropdownField("Takes per gesture", SingleChoice((1..TeachViewModel.MAX_TAKES).toList(), state.takesPerLabel) { it.toString() }, { actions.onSetTakesPerLabel(it) })
        if (state.sourceKind == GestureSourceKind.TOUCH && touch != null) TouchPad(touch)
        val (done, wanted) = state.progress
        val next = state.next
        if (next != null) {
            Text("Take ${(state.recorded[next] ?: 0) + 1} of ${state.takesPerLabel}: ${next.id}. " + if (next.isNone) "Press Record and rest your hand." else "Press Record, rest, do it once, rest, press Stop.")
            if (state.recording) {
                Button(onClick = { actions.onStopTake() }) { Text("Stop") }
                Text(String.format(Locale.ROOT, "%.1f s", state.seconds))
                LivePlots(plot, state.channels, state.plotRevision)
            } else {
                Button(onClick = { actions.onStartTake() }) { Text("Record ${next.id}") }
            }
        } else {
            Text("All $wanted takes recorded")
        }
        Text("$done of $wanted takes", style = MaterialTheme.typography.bodySmall)
        ButtonRow {
            Button(onClick = { actions.onTrain() }, enabled = done > 0 && !state.training && !state.recording) { Text(if (state.training) "Training…" else "Train") }
            OutlinedButton(onClick = { actions.onClearExamples() }, enabled = done > 0 && !state.recording) { Text("Clear takes") }
        }
        state.result?.let { r ->
            LabeledValue("Training accuracy", String.format(Locale.ROOT, "%.1f %%", 100 * r.trainingAccuracy))
            LabeledValue("Validation accuracy", r.validationAccuracy?.let { String.format(Locale.ROOT, "%.1f %% (last take of each held out)", 100 * it) } ?: "needs 2 takes per gesture")
            LabeledValue("Windows", r.windows.toString())
            LabeledValue("Training time", "${r.trainingMillis} ms")
        }
        OutlinedButton(onClick = actions.onImportModel) { Text("Import model file") }
    }
}
