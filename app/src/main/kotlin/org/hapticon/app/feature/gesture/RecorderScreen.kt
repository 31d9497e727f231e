package org.hapticon.app.feature.gesture

import org.hapticon.sensor.live.PlotSource
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Slider
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableIntStateOf
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.ui.LivePlot
import org.hapticon.app.gesture.TouchGestureSource
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.app.ui.LabeledValue
import org.hapticon.gesture.Recording
import org.hapticon.gesture.extraction.FitReport
import org.hapticon.gesture.recognition.GestureLabel
import java.util.Locale
import org.hapticon.app.ui.ButtonRow

/** The Record tab wired to [viewModel]; [touch] is the touchscreen source the pad feeds, [onImport] opens the file picker. */
@Composable
fun RecorderRoute(viewModel: RecorderViewModel, touch: TouchGestureSource?, onImport: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onImport) {
        RecorderActions(
            onSelectSource = viewModel::selectSource,
            onStartRecording = viewModel::startRecording,
            onStopRecording = viewModel::stopRecording,
            onImport = onImport,
            onSetTrim = viewModel::setTrim,
            onSaveRecording = viewModel::saveRecording,
            onSelectFitChannel = viewModel::selectFitChannel,
            onSetIconName = viewModel::setIconName,
            onMakeIcon = viewModel::makeIcon,
            onPlay = viewModel::play,
            onSaveIcon = viewModel::saveIcon,
            onOpenRecording = viewModel::openRecording,
            onDeleteRecording = viewModel::deleteRecording,
            onFitSavedStrongest = { viewModel.fitSavedStrongest() },
            onSaveBatchIcons = viewModel::saveBatchIcons,
            onDismissMessage = viewModel::dismissMessage,
        )
    }
    RecorderScreen(uiState, viewModel.plot, touch, actions)
}

/** What the Record tab can ask for. */
@Immutable
class RecorderActions(
    val onSelectSource: (GestureSourceKind) -> Unit = {},
    val onStartRecording: () -> Unit = {},
    val onStopRecording: () -> Unit = {},
    val onImport: () -> Unit = {},
    val onSetTrim: (Int, Int) -> Unit = { _, _ -> },
    val onSaveRecording: (String, GestureLabel?) -> Unit = { _, _ -> },
    val onSelectFitChannel: (String) -> Unit = {},
    val onSetIconName: (String) -> Unit = {},
    val onMakeIcon: () -> Unit = {},
    val onPlay: () -> Unit = {},
    val onSaveIcon: () -> Unit = {},
    val onOpenRecording: (String) -> Unit = {},
    val onDeleteRecording: (String) -> Unit = {},
    val onFitSavedStrongest: () -> Unit = {},
    val onSaveBatchIcons: () -> Unit = {},
    val onDismissMessage: () -> Unit = {},
)

/**
 * Record or import a take, trim it, make an icon, play and save it; the saved recordings below. [plot] draws the
 * take being recorded; [touch] (null without a touchscreen source) is fed by the touch pad.
 */
@Composable
fun RecorderScreen(uiState: RecorderUiState, plot: PlotSource, touch: TouchGestureSource?, actions: RecorderActions) {
    when (uiState) {
        RecorderUiState.Loading -> GestureLoading()
        is RecorderUiState.Ready -> RecorderContent(uiState, plot, touch, actions)
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun RecorderContent(state: RecorderUiState.Ready, plot: PlotSource, touch: TouchGestureSource?, actions: RecorderActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions.onDismissMessage() }
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            SourcePicker(state.sourceKind, !state.recording) { actions.onSelectSource(it) }
        }
        if (state.sourceKind == GestureSourceKind.TOUCH && touch != null) TouchPad(touch)
        // A flow row: at the largest font sizes the second button goes under the first instead of wrapping its words.
        FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            if (state.recording) {
                Button(onClick = { actions.onStopRecording() }) { Text("Stop") }
            } else {
                Button(onClick = { actions.onStartRecording() }, enabled = state.sourceAvailable) { Text("Record") }
            }
            OutlinedButton(onClick = actions.onImport, enabled = !state.recording) { Text("Import WAV or CSV") }
        }
        if (state.recording) {
            Text(String.format(Locale.ROOT, "Recording %.1f s of at most %.0f s", state.seconds, state.maxSeconds))
            LivePlots(plot, state.channels, state.plotRevision)
        }
        state.take?.let { take -> TrimAndFit(state, take, actions) }
        Text("Saved recordings", style = MaterialTheme.typography.titleMedium)
        if (state.savedRecordings.isEmpty()) Text("None yet", style = MaterialTheme.typography.bodySmall)
        for (saved in state.savedRecordings) {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
                Text(
                    "${saved.name}${saved.label?.let { " · ${it.id}" } ?: ""} · ${String.format(Locale.ROOT, "%.1f s", saved.seconds)}",
                    Modifier.weight(1f),
                )
                TextButton(onClick = { actions.onOpenRecording(saved.id) }, modifier = Modifier.semantics { contentDescription = "Open ${saved.name}" }) { Text("Open") }
                TextButton(onClick = { actions.onDeleteRecording(saved.id) }, modifier = Modifier.semantics { contentDescription = "Delete ${saved.name}" }) { Text("Delete") }
            }
        }
        StrongestBatchSection(state, onFit = actions.onFitSavedStrongest, onSave = actions.onSaveBatchIcons)
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun TrimAndFit(state: RecorderUiState.Ready, take: Recording, actions: RecorderActions) {
    val source = remember(take) { RecordingPlotSource(take) }
    val last = take.frameCount.toFloat()
    Text("Trim", style = MaterialTheme.typography.titleMedium)
    take.channels.take(MAX_PLOTTED).forEachIndexed { i, channel ->
        NamedPlot(channel.name) { LivePlot(source, i, 0, channel.name, description = "Plot of the recorded ${channel.name}") }
    }
    Text(String.format(Locale.ROOT, "Keep %.2f s to %.2f s of %.2f s", state.trimFrom / take.sampleRate, state.trimTo / take.sampleRate, take.durationSeconds))
    Slider(
        value = state.trimFrom.toFloat(), onValueChange = { actions.onSetTrim(it.toInt(), state.trimTo) }, valueRange = 0f..last,
        modifier = Modifier.semantics { contentDescription = "Trim start" },
    )
    Slider(
        value = state.trimTo.toFloat(), onValueChange = { actions.onSetTrim(state.trimFrom, it.toInt()) }, valueRange = 0f..last,
        modifier = Modifier.semantics { contentDescription = "Trim end" },
    )
    var recordingName by rememberSaveable { mutableStateOf("") }
    var labelIndex by rememberSaveable { mutableIntStateOf(-1) }
    val labelOptions = listOf(-1) + GestureLabel.ALL.indices
    OutlinedTextField(recordingName, { recordingName = it }, label = { Text("Recording name") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        DropdownField("Label", SingleChoice(labelOptions, labelIndex) { if (it < 0) "no label" else GestureLabel.ALL[it].id }, { labelIndex = it })
        OutlinedButton(
            onClick = { actions.onSaveRecording(recordingName, GestureLabel.ALL.getOrNull(labelIndex)) },
            enabled = recordingName.isNotBlank(),
        ) { Text("Save recording") }
    }
    Text("Make an icon", style = MaterialTheme.typography.titleMedium)
    DropdownField("Fit channel", SingleChoice(take.channels.map { it.name }, state.fitChannel ?: take.channels.first().name) { it }, { actions.onSelectFitChannel(it) })
    OutlinedTextField(state.iconName, { actions.onSetIconName(it) }, label = { Text("Icon name") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    Button(onClick = { actions.onMakeIcon() }, enabled = !state.fitting) { Text(if (state.fitting) "Fitting…" else "Make icon") }
    state.fit?.let { fit ->
        EnvelopeThumbnail(fit.icon, Modifier.fillMaxWidth().height(96.dp))
        val icon = fit.icon
        Text(
            String.format(Locale.ROOT, "attack %.3f s · sustain %.3f s · level %.2f · release %.3f s · note %.1f · period %.3f s · count %d",
                icon.attack, icon.sustain, icon.level, icon.release, icon.note, icon.period, icon.count),
            style = MaterialTheme.typography.bodySmall,
        )
        FitReportView(fit.report)
        ButtonRow {
            OutlinedButton(onClick = { actions.onPlay() }) { Text("Play") }
            Button(onClick = { actions.onSaveIcon() }, enabled = state.iconName.isNotBlank()) { Text("Save icon") }
        }
        state.savedIcon?.let { Text("\"$it\" is in your icons: pick it in a chat or the Icons tab", style = MaterialTheme.typography.bodySmall) }
    }
}

/** The fit report: how well the envelope model fits, where the repetitions start, how the note was chosen and any warnings. */
@Composable
fun FitReportView(report: FitReport) {
    Column(verticalArrangement = Arrangement.spacedBy(2.dp)) {
        LabeledValue("RMS error", String.format(Locale.ROOT, "%.1f %% of peak", 100 * report.fitRmsError))
        LabeledValue("R²", String.format(Locale.ROOT, "%.3f", report.rSquared))
        LabeledValue("Level relative to", report.levelReference)
        LabeledValue("Onsets", report.onsets.joinToString { String.format(Locale.ROOT, "%.3f s", it) })
        LabeledValue("Signal", "${report.kind.name.lowercase()} on ${report.channel}")
        report.snrDb?.let { LabeledValue("SNR", String.format(Locale.ROOT, "%.1f dB", it)) }
        val note = report.parameter("note")
        Text(String.format(Locale.ROOT, "Note %.1f: %s", note.value, note.how), style = MaterialTheme.typography.bodySmall)
        for (warning in report.warnings) Text("Warning: $warning", style = MaterialTheme.typography.bodySmall, color = MaterialTheme.colorScheme.error)
    }
}
