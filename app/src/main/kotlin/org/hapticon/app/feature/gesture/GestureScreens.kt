package org.hapticon.app.feature.gesture

import android.net.Uri
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.FilterChip
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.PrimaryTabRow
import androidx.compose.material3.Slider
import androidx.compose.material3.Tab
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableIntStateOf
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.ExperimentalComposeUiApi
import androidx.compose.ui.Modifier
import androidx.compose.ui.input.pointer.pointerInteropFilter
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.semantics.clearAndSetSemantics
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.AppContainer
import org.hapticon.app.feature.sensors.LivePlot
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.TouchGestureSource
import org.hapticon.app.sensors.PlotSource
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.app.ui.LabeledValue
import org.hapticon.app.ui.SwitchRow
import org.hapticon.gesture.Recording
import org.hapticon.gesture.extraction.FitReport
import org.hapticon.gesture.recognition.GestureLabel
import java.io.FileNotFoundException
import java.util.Locale

/** The Gestures destination's three parts, in tab order. */
enum class GestureTab(val label: String) { RECORD("Record"), TEACH("Teach"), RECOGNISE("Recognise") }

/** The Gestures destination: record and make an icon, teach a personal model, recognise live and send. */
@Composable
fun GesturesRoute(container: AppContainer) {
    val gestures = container.gestures ?: run {
        Text("Gestures are not available in this build", Modifier.padding(16.dp))
        return
    }
    val chat = container.chat
    val recorder: RecorderViewModel = viewModel(factory = viewModelFactory { initializer { RecorderViewModel(gestures, chat?.icons, container.player) } })
    val teach: TeachViewModel = viewModel(factory = viewModelFactory { initializer { TeachViewModel(gestures) } })
    val recognition: RecognitionViewModel = viewModel(
        factory = viewModelFactory {
            initializer {
                RecognitionViewModel(gestures, chat?.repository, user = { chat?.settings?.preferences?.value?.userName }, onSent = { chat?.sync?.wake() })
            }
        },
    )
    var tab by rememberSaveable { mutableStateOf(GestureTab.RECORD) }
    val context = LocalContext.current
    val opener = { uri: Uri -> { context.contentResolver.openInputStream(uri) ?: throw FileNotFoundException("cannot open $uri") } }
    val importRecording = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { recorder.importFile(opener(it), it.lastPathSegment ?: "file") }
    }
    val importModel = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { teach.importModel(opener(it), it.lastPathSegment ?: "file") }
    }
    Column(Modifier.fillMaxSize()) {
        GestureTabs(tab) { tab = it }
        when (tab) {
            GestureTab.RECORD -> {
                val state by recorder.uiState.collectAsStateWithLifecycle()
                RecorderScreen(state, recorder.plot, gestures, recorder, onImport = { importRecording.launch(arrayOf("text/*", "audio/*", "application/octet-stream")) })
            }
            GestureTab.TEACH -> {
                val state by teach.uiState.collectAsStateWithLifecycle()
                TeachScreen(state, teach.plot, gestures, teach, onImportModel = { importModel.launch(arrayOf("application/json", "text/*", "application/octet-stream")) })
            }
            GestureTab.RECOGNISE -> {
                val state by recognition.uiState.collectAsStateWithLifecycle()
                RecognitionScreen(state, gestures, recognition)
            }
        }
    }
}

@OptIn(ExperimentalMaterial3Api::class)
@Composable
private fun GestureTabs(selected: GestureTab, onSelect: (GestureTab) -> Unit) {
    PrimaryTabRow(selectedTabIndex = selected.ordinal) {
        for (tab in GestureTab.entries) Tab(selected = tab == selected, onClick = { onSelect(tab) }, text = { Text(tab.label) })
    }
}

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
private fun SourcePicker(selected: GestureSourceKind, enabled: Boolean, onSelect: (GestureSourceKind) -> Unit) {
    DropdownField("Source", GestureSourceKind.entries, selected, { it.label }, onSelect, enabled = enabled)
}

@Composable
private fun LivePlots(plot: PlotSource, channels: List<String>, revision: Long) {
    channels.take(MAX_PLOTTED).forEachIndexed { i, name -> NamedPlot(name) { LivePlot(plot, i, revision, name) } }
}

/** A plot under its channel's name: without it several stacked plots cannot be told apart. */
@Composable
private fun NamedPlot(name: String, plot: @Composable () -> Unit) {
    // The plot's own description names the channel for TalkBack; the visible name would only repeat it.
    Text(name, style = MaterialTheme.typography.labelMedium, modifier = Modifier.clearAndSetSemantics {})
    plot()
}

@Composable
private fun Message(message: String?, onDismiss: () -> Unit) {
    if (message == null) return
    Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
        Text(message, Modifier.weight(1f), style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.error)
        TextButton(onClick = onDismiss) { Text("Dismiss") }
    }
}

/** Record or import a take, trim it, make an icon, play and save it; the saved recordings below. */
@Composable
fun RecorderScreen(state: RecorderUiState, plot: PlotSource, gestures: GestureComponent?, actions: RecorderViewModel?, onImport: () -> Unit) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions?.dismissMessage() }
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            SourcePicker(state.sourceKind, !state.recording) { actions?.selectSource(it) }
        }
        if (state.sourceKind == GestureSourceKind.TOUCH && gestures != null) TouchPad(gestures.touch)
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            if (state.recording) {
                Button(onClick = { actions?.stopRecording() }) { Text("Stop") }
            } else {
                Button(onClick = { actions?.startRecording() }, enabled = state.sourceAvailable) { Text("Record") }
            }
            OutlinedButton(onClick = onImport, enabled = !state.recording) { Text("Import WAV or CSV") }
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
                TextButton(onClick = { actions?.openRecording(saved.id) }, modifier = Modifier.semantics { contentDescription = "Open ${saved.name}" }) { Text("Open") }
                TextButton(onClick = { actions?.deleteRecording(saved.id) }, modifier = Modifier.semantics { contentDescription = "Delete ${saved.name}" }) { Text("Delete") }
            }
        }
    }
}

@Composable
private fun TrimAndFit(state: RecorderUiState, take: Recording, actions: RecorderViewModel?) {
    val source = remember(take) { RecordingPlotSource(take) }
    val last = take.frameCount.toFloat()
    Text("Trim", style = MaterialTheme.typography.titleMedium)
    take.channels.take(MAX_PLOTTED).forEachIndexed { i, channel ->
        NamedPlot(channel.name) { LivePlot(source, i, 0, channel.name, description = "Plot of the recorded ${channel.name}") }
    }
    Text(String.format(Locale.ROOT, "Keep %.2f s to %.2f s of %.2f s", state.trimFrom / take.sampleRate, state.trimTo / take.sampleRate, take.durationSeconds))
    Slider(
        value = state.trimFrom.toFloat(), onValueChange = { actions?.setTrim(it.toInt(), state.trimTo) }, valueRange = 0f..last,
        modifier = Modifier.semantics { contentDescription = "Trim start" },
    )
    Slider(
        value = state.trimTo.toFloat(), onValueChange = { actions?.setTrim(state.trimFrom, it.toInt()) }, valueRange = 0f..last,
        modifier = Modifier.semantics { contentDescription = "Trim end" },
    )
    var recordingName by rememberSaveable { mutableStateOf("") }
    var labelIndex by rememberSaveable { mutableIntStateOf(-1) }
    val labelOptions = listOf(-1) + GestureLabel.ALL.indices
    OutlinedTextField(recordingName, { recordingName = it }, label = { Text("Recording name") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
        DropdownField("Label", labelOptions, labelIndex, { if (it < 0) "no label" else GestureLabel.ALL[it].id }, { labelIndex = it })
        OutlinedButton(
            onClick = { actions?.saveRecording(recordingName, GestureLabel.ALL.getOrNull(labelIndex)) },
            enabled = recordingName.isNotBlank(),
        ) { Text("Save recording") }
    }
    Text("Make an icon", style = MaterialTheme.typography.titleMedium)
    DropdownField("Fit channel", take.channels.map { it.name }, state.fitChannel ?: take.channels.first().name, { it }, { actions?.selectFitChannel(it) })
    OutlinedTextField(state.iconName, { actions?.setIconName(it) }, label = { Text("Icon name") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    Button(onClick = { actions?.makeIcon() }, enabled = !state.fitting) { Text(if (state.fitting) "Fitting…" else "Make icon") }
    state.fit?.let { fit ->
        EnvelopeThumbnail(fit.icon, Modifier.fillMaxWidth().height(96.dp))
        val icon = fit.icon
        Text(
            String.format(Locale.ROOT, "attack %.3f s · sustain %.3f s · level %.2f · release %.3f s · note %.1f · period %.3f s · count %d",
                icon.attack, icon.sustain, icon.level, icon.release, icon.note, icon.period, icon.count),
            style = MaterialTheme.typography.bodySmall,
        )
        FitReportView(fit.report)
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            OutlinedButton(onClick = { actions?.play() }) { Text("Play") }
            Button(onClick = { actions?.saveIcon() }, enabled = state.iconName.isNotBlank()) { Text("Save icon") }
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

/** Choose labels and takes, record the takes one by one, train, see the accuracy; or import a model. */
@OptIn(androidx.compose.foundation.layout.ExperimentalLayoutApi::class)
@Composable
fun TeachScreen(state: TeachUiState, plot: PlotSource, gestures: GestureComponent?, actions: TeachViewModel?, onImportModel: () -> Unit) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions?.dismissMessage() }
        Text(state.model?.let { "Model: ${it.labels.joinToString { l -> l.id }} from ${it.channels.joinToString()} at ${it.sampleRate} Hz" } ?: "No model yet")
        SourcePicker(state.sourceKind, !state.recording) { actions?.selectSource(it) }
        Text("Gestures to teach", style = MaterialTheme.typography.titleMedium)
        FlowRow(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
            for (label in GestureLabel.ALL) {
                FilterChip(selected = label in state.labels, onClick = { actions?.toggleLabel(label) }, label = { Text(label.id) }, enabled = !label.isNone)
            }
        }
        DropdownField("Takes per gesture", (1..TeachViewModel.MAX_TAKES).toList(), state.takesPerLabel, { it.toString() }, { actions?.setTakesPerLabel(it) })
        if (state.sourceKind == GestureSourceKind.TOUCH && gestures != null) TouchPad(gestures.touch)
        val (done, wanted) = state.progress
        val next = state.next
        if (next != null) {
            Text("Take ${(state.recorded[next] ?: 0) + 1} of ${state.takesPerLabel}: ${next.id}. " + if (next.isNone) "Press Record and rest your hand." else "Press Record, rest, do it once, rest, press Stop.")
            if (state.recording) {
                Button(onClick = { actions?.stopTake() }) { Text("Stop") }
                Text(String.format(Locale.ROOT, "%.1f s", state.seconds))
                LivePlots(plot, state.channels, state.plotRevision)
            } else {
                Button(onClick = { actions?.startTake() }) { Text("Record ${next.id}") }
            }
        } else {
            Text("All $wanted takes recorded")
        }
        Text("$done of $wanted takes", style = MaterialTheme.typography.bodySmall)
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            Button(onClick = { actions?.train() }, enabled = done > 0 && !state.training && !state.recording) { Text(if (state.training) "Training…" else "Train") }
            OutlinedButton(onClick = { actions?.clearExamples() }, enabled = done > 0 && !state.recording) { Text("Clear takes") }
        }
        state.result?.let { r ->
            LabeledValue("Training accuracy", String.format(Locale.ROOT, "%.1f %%", 100 * r.trainingAccuracy))
            LabeledValue("Validation accuracy", r.validationAccuracy?.let { String.format(Locale.ROOT, "%.1f %% (last take of each held out)", 100 * it) } ?: "needs 2 takes per gesture")
            LabeledValue("Windows", r.windows.toString())
            LabeledValue("Training time", "${r.trainingMillis} ms")
        }
        OutlinedButton(onClick = onImportModel) { Text("Import model file") }
    }
}

/** Live recognition with the stored model, and sending recognised gestures to a conversation. */
@Composable
fun RecognitionScreen(state: RecognitionUiState, gestures: GestureComponent?, actions: RecognitionViewModel?) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions?.dismissMessage() }
        Text(state.model?.let { "Model: ${it.labels.joinToString { l -> l.id }}" } ?: "No model: teach or import one in the Teach tab")
        SourcePicker(state.sourceKind, !state.running) { actions?.selectSource(it) }
        if (state.sourceKind == GestureSourceKind.TOUCH && gestures != null) TouchPad(gestures.touch)
        if (state.running) {
            Button(onClick = { actions?.stop() }) { Text("Stop recognising") }
        } else {
            Button(onClick = { actions?.start() }, enabled = state.model != null) { Text("Start recognising") }
        }
        Text(
            state.decision?.let { String.format(Locale.ROOT, "%s (%.0f %%)", it.id, 100 * it.let { state.probability }) } ?: "—",
            style = MaterialTheme.typography.headlineMedium,
            modifier = Modifier.semantics { contentDescription = "Recognised: ${state.decision?.id ?: "nothing yet"}" },
        )
        state.lastEvent?.let { Text("Last gesture: ${it.id}") }
        if (state.peers.isEmpty()) {
            Text("Start a conversation in Chats to send recognised gestures", style = MaterialTheme.typography.bodySmall)
        } else {
            val peer = state.peer ?: state.peers.first()
            DropdownField("Conversation", state.peers, peer, { it }, { actions?.selectPeer(it) })
            SwitchRow("Send recognised gestures to $peer", state.sendEnabled, { actions?.setSendEnabled(it) })
        }
        for (sent in state.sent) {
            Text(String.format(Locale.ROOT, "Sent %s (%s) to %s at %.1f s", sent.icon, sent.label.id, sent.peer, sent.atSeconds), style = MaterialTheme.typography.bodySmall)
        }
    }
}

/** Channels plotted live at most (the rest are recorded but not drawn). */
private const val MAX_PLOTTED = 6
