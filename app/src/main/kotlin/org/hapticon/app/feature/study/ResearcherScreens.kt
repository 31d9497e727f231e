package org.hapticon.app.feature.study

import org.hapticon.app.study.ExportResult
import org.hapticon.app.study.SessionSummary
import android.content.ActivityNotFoundException
import android.content.Intent
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.itemsIndexed
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.material3.AlertDialog
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.HorizontalDivider
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Slider
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.text.input.KeyboardType
import androidx.compose.ui.text.input.PasswordVisualTransformation
import androidx.compose.ui.unit.dp
import java.io.File
import java.util.Locale
import kotlin.math.roundToInt
import org.hapticon.app.ui.Sticker
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.NoiseFiles
import org.hapticon.app.study.StudyExporter
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.study.Stimulus
import org.hapticon.study.StudyTask
import org.hapticon.app.study.StoredProtocol
import org.hapticon.study.LikertScale
import org.hapticon.study.design.OrderScheme
import org.hapticon.app.ui.WrappingButtonShape
import org.hapticon.app.ui.ButtonRow

/** What the researcher screen can ask for. */
@Immutable
class ResearcherActions(
    val onLock: () -> Unit = {},
    val onSelect: (String) -> Unit = {},
    val onEdit: (String) -> Unit = {},
    val onDuplicate: (StoredProtocol) -> Unit = {},
    val onDelete: (String) -> Unit = {},
    /** Starts the next session; true: even without headphones (after the warning). */
    val onStartSession: (Boolean) -> Unit = {},
    val onDismissHeadphoneWarning: () -> Unit = {},
    val onExport: () -> Unit = {},
    val onSetCollector: (String, String) -> Unit = { _, _ -> },
    val onUpload: () -> Unit = {},
    val onOpenCompliance: () -> Unit = {},
)

/** The researcher screen: protocol, next session, sessions, export, share and upload; a spinner while they are read. */
@Composable
fun ResearcherScreen(state: ResearcherUiState, actions: ResearcherActions) {
    when (state) {
        is ResearcherUiState.Loading -> Box(Modifier.fillMaxSize(), contentAlignment = Alignment.Center) {
            CircularProgressIndicator(Modifier.semantics { contentDescription = "Loading the study" })
        }
        is ResearcherUiState.Success -> ResearcherContent(state, actions)
    }
}

@Composable
private fun ResearcherContent(state: ResearcherUiState.Success, actions: ResearcherActions) {
    LazyColumn(Modifier.fillMaxSize(), contentPadding = PaddingValues(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        item { ResearcherHeader(actions.onLock) }
        item { ProtocolSection(state, actions) }
        item {
            // Shaping Compliance's study runs on the FSR board, not as an icon protocol: its own runner.
            OutlinedButton(onClick = actions.onOpenCompliance, modifier = Modifier.fillMaxWidth(), shape = WrappingButtonShape) { Text("Compliance study (Shaping Compliance, FSR board)") }
        }
        item { Text("Sessions", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() }) }
        if (state.sessions.isEmpty()) item { Text("No sessions yet.", style = MaterialTheme.typography.bodyMedium) }
        itemsIndexed(state.sessions, key = { _, s -> s.id }) { _, s -> SessionLine(s, running = s.id == state.activeSessionId) }
        item { HorizontalDivider() }
        item { ExportSection(state.export, actions.onExport) }
        item { CollectorSettings(state, actions) }
    }
    if (state.headphoneWarning) HeadphoneWarning(actions)
}

/** The screen's title and the lock that hands the phone back to the participant. */
@Composable
private fun ResearcherHeader(onLock: () -> Unit) {
    Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
        Text("Study · researcher", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
        TextButton(onClick = onLock) { Text("Lock") }
    }
}

/** The chosen protocol: its summary, editing, and starting the next participant's session. */
@Composable
private fun ProtocolSection(state: ResearcherUiState.Success, actions: ResearcherActions) {
    val selected = state.selected
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        if (selected != null) {
            DropdownField(
                label = "Protocol",
                choice = SingleChoice(state.protocols, selected) {
                    "${it.protocol.title} (${it.protocol.id} r${it.protocol.revision})" + if (it.readOnly) " · default" else ""
                },
                onSelect = { actions.onSelect(it.protocol.id) },
            )
            val masking = selected.masking
            Text(
                "${selected.protocol.tasks.size} tasks · task order ${selected.protocol.taskOrder.jsonName} · seed ${selected.seed} · masking " +
                    if (masking.isOn) "${masking.color.label} at ${"%.0f".format(Locale.ROOT, masking.cappedLevelDbfs)} dBFS" else "off",
                style = MaterialTheme.typography.bodyMedium,
            )
            ButtonRow(spacing = 8.dp) {
                if (selected.readOnly) {
                    OutlinedButton(onClick = { actions.onDuplicate(selected) }) { Text("Duplicate to edit") }
                } else {
                    OutlinedButton(onClick = { actions.onEdit(selected.protocol.id) }) { Text("Edit") }
                    OutlinedButton(onClick = { actions.onDuplicate(selected) }) { Text("Duplicate") }
                    OutlinedButton(onClick = { actions.onDelete(selected.protocol.id) }) { Text("Delete") }
                }
            }
            Button(onClick = { actions.onStartSession(false) }, modifier = Modifier.fillMaxWidth()) {
                Text("Start session for ${state.nextParticipant}")
            }
        }
        state.message?.let { Text(it, style = MaterialTheme.typography.bodyMedium) }
    }
}

/** One stored session: who, which protocol, how far, and whether it finished. */
@Composable
private fun SessionLine(s: SessionSummary, running: Boolean) {
    Text(
        "${s.participant} · ${s.protocolId} · ${s.answers} of ${s.trials} rated · " +
            when {
                s.finished -> "finished"
                running -> "running"
                else -> "incomplete"
            },
        style = MaterialTheme.typography.bodyMedium,
    )
}

/** Exporting the sessions as CSV and JSON, what the last export wrote and checked, and sharing its files. */
@Composable
private fun ExportSection(export: ExportResult?, onExport: () -> Unit) {
    val context = LocalContext.current
    fun share(file: File, type: String) {
        try {
            context.startActivity(Intent.createChooser(StudyExporter.shareIntent(context, file, type), "Share ${file.name}"))
        } catch (e: ActivityNotFoundException) {
            android.util.Log.w("Study", "no app to share with: ${e.message}")
        }
    }
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Text("Export", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
        Button(onClick = onExport) { Text("Export CSV + JSON") }
        if (export != null) {
            Text("${export.csvFile.name}, ${export.jsonFile.name}: ${export.rows} rows", style = MaterialTheme.typography.bodySmall)
            for (check in export.checks) Text("${check.participant}: ${check.summary}", style = MaterialTheme.typography.bodyMedium)
            ButtonRow(spacing = 8.dp) {
                OutlinedButton(onClick = { share(export.csvFile, "text/csv") }) { Text("Share CSV") }
                OutlinedButton(onClick = { share(export.jsonFile, "application/json") }) { Text("Share JSON") }
            }
        }
    }
}

/** Asked before a session with masking noise starts while no headphones are connected. */
@Composable
private fun HeadphoneWarning(actions: ResearcherActions) {
    AlertDialog(
        onDismissRequest = actions.onDismissHeadphoneWarning,
        title = { Text("No headphones connected") },
        text = { Text("The masking noise will play from the speaker, where the experimenter hears it too. Connect headphones, or start anyway.") },
        confirmButton = { TextButton(onClick = { actions.onStartSession(true) }) { Text("Start anyway") } },
        dismissButton = { TextButton(onClick = actions.onDismissHeadphoneWarning) { Text("Cancel") } },
    )
}

@Composable
private fun CollectorSettings(state: ResearcherUiState.Success, actions: ResearcherActions) {
    var url by rememberSaveable(state.collectorUrl) { mutableStateOf(state.collectorUrl) }
    var token by rememberSaveable(state.collectorToken) { mutableStateOf(state.collectorToken) }
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Text("Upload to the study collector", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
        OutlinedTextField(
            url, { url = it }, label = { Text("Collector URL") }, singleLine = true,
            keyboardOptions = KeyboardOptions(keyboardType = KeyboardType.Uri), modifier = Modifier.fillMaxWidth(),
        )
        OutlinedTextField(
            token, { token = it }, label = { Text("Upload token") }, singleLine = true,
            supportingText = { Text("hapticon collect token add --study ${state.selected?.protocol?.id ?: "ID"} --role upload") },
            visualTransformation = PasswordVisualTransformation(), modifier = Modifier.fillMaxWidth(),
        )
        ButtonRow(spacing = 8.dp) {
            OutlinedButton(onClick = { actions.onSetCollector(url, token) }) { Text("Save collector") }
            val failed = state.upload is UploadState.Failed
            Button(onClick = actions.onUpload, enabled = state.upload != UploadState.Uploading && state.collectorUrl.isNotBlank()) {
                Text(if (failed) "Retry upload" else "Upload")
            }
        }
        when (val upload = state.upload) {
            UploadState.Idle -> Unit
            UploadState.Uploading -> Text("Uploading…")
            is UploadState.Done -> Text(upload.message)
            is UploadState.Failed -> ErrorText("${upload.message}. Nothing is lost: the results stay on the phone.")
        }
    }
}

/** What the protocol editor can ask for: each change is a transform of the draft, a task or a stimulus. */
@Immutable
class ProtocolEditorActions(
    val onBack: () -> Unit = {},
    val onEdit: ((ProtocolDraft) -> ProtocolDraft) -> Unit = {},
    val onSetPoints: (Int) -> Unit = {},
    val onEditTask: (Int, (StudyTask) -> StudyTask) -> Unit = { _, _ -> },
    val onEditStimulus: (Int, Int, (Stimulus) -> Stimulus) -> Unit = { _, _, _ -> },
    val onSave: () -> Unit = {},
    val onSetJson: (String) -> Unit = {},
    val onExportJson: () -> Unit = {},
    val onImportJson: () -> Unit = {},
)

/** The protocol editor: every field of the draft, the study module's validation message, JSON import and export. */
@Composable
fun ProtocolEditorScreen(state: ProtocolEditorUiState, actions: ProtocolEditorActions) {
    LazyColumn(Modifier.fillMaxSize(), contentPadding = PaddingValues(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        item {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
                Text("Edit protocol", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                TextButton(onClick = actions.onBack) { Text("Back") }
            }
        }
        val editing = when (state) {
            ProtocolEditorUiState.Loading -> return@LazyColumn
            is ProtocolEditorUiState.Error -> {
                item { Text(state.message, style = MaterialTheme.typography.bodyMedium) }
                return@LazyColumn
            }
            is ProtocolEditorUiState.Success -> state
        }
        val draft = editing.draft
        editing.message?.let { item { Text(it, style = MaterialTheme.typography.bodyMedium) } }
        item {
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                Text("${draft.id} · revision ${draft.revision}", style = MaterialTheme.typography.labelLarge)
                TextRow("Title", draft.title) { v -> actions.onEdit { it.copy(title = v) } }
                DropdownField("Scale points", SingleChoice((2..LikertScale.MAX_POINTS).toList(), draft.points) { "$it" }, actions.onSetPoints)
                DropdownField("Task order", SingleChoice(OrderScheme.entries, draft.taskOrder) { it.jsonName }, { v -> actions.onEdit { it.copy(taskOrder = v) } })
                TextRow("Seed", draft.seed.toString(), KeyboardType.Number) { v -> v.toLongOrNull()?.let { s -> actions.onEdit { it.copy(seed = s) } } }
                DropdownField("Masking noise", SingleChoice(NoiseColor.entries, draft.masking.color) { it.label }, { v ->
                    actions.onEdit { it.copy(masking = it.masking.copy(color = v)) }
                })
                if (draft.masking.isOn) MaskingLevel(draft.masking) { level -> actions.onEdit { it.copy(masking = it.masking.copy(levelDbfs = level)) } }
            }
        }
        itemsIndexed(draft.tasks) { t, task ->
            Card(Modifier.fillMaxWidth()) {
                Column(Modifier.padding(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                    Text("Task ${t + 1}: ${task.id}", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                    TextRow("Task ${t + 1} title", task.title) { v -> actions.onEditTask(t) { it.copy(title = v) } }
                    TextRow("Task ${t + 1} instructions", task.instructions) { v -> actions.onEditTask(t) { it.copy(instructions = v) } }
                    TextRow("Task ${t + 1} question", task.question) { v -> actions.onEditTask(t) { it.copy(question = v) } }
                    DropdownField("Task ${t + 1} stimulus order", SingleChoice(OrderScheme.entries, task.stimulusOrder) { it.jsonName }, { v ->
                        actions.onEditTask(t) { it.copy(stimulusOrder = v) }
                    })
                    task.stimuli.forEachIndexed { s, stimulus ->
                        HorizontalDivider()
                        Text("Stimulus ${s + 1}: ${stimulus.id}", style = MaterialTheme.typography.labelLarge)
                        val icons = if (editing.icons.any { it == stimulus.icon }) editing.icons else listOf(stimulus.icon) + editing.icons
                        DropdownField("Task ${t + 1} stimulus ${s + 1} icon", SingleChoice(icons, stimulus.icon) { it.name }, { icon ->
                            actions.onEditStimulus(t, s) { it.copy(icon = icon) }
                        })
                        TextRow("Task ${t + 1} stimulus ${s + 1} text", stimulus.text.orEmpty()) { v ->
                            actions.onEditStimulus(t, s) { it.copy(text = v.ifEmpty { null }) }
                        }
                        val stickers = listOf<String?>(null) + Sticker.entries.map { "sticker_${it.wireName}" }
                        DropdownField("Task ${t + 1} stimulus ${s + 1} sticker", SingleChoice((stickers + stimulus.sticker).distinct(), stimulus.sticker) { it ?: "none" }, { v ->
                            actions.onEditStimulus(t, s) { it.copy(sticker = v) }
                        })
                    }
                }
            }
        }
        item {
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                val problem = editing.problem
                if (problem != null) ErrorText(problem) else Text("The protocol is valid.", style = MaterialTheme.typography.bodyMedium)
                Button(onClick = actions.onSave, enabled = problem == null) { Text("Save") }
                Text("Protocol JSON", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                OutlinedTextField(editing.json, actions.onSetJson, label = { Text("Protocol JSON") }, minLines = 4, modifier = Modifier.fillMaxWidth())
                ButtonRow(spacing = 8.dp) {
                    OutlinedButton(onClick = actions.onExportJson) { Text("Export JSON") }
                    OutlinedButton(onClick = actions.onImportJson, enabled = editing.json.isNotBlank()) { Text("Import JSON") }
                }
            }
        }
    }
}

@Composable
private fun TextRow(label: String, value: String, keyboard: KeyboardType = KeyboardType.Text, onChange: (String) -> Unit) {
    OutlinedTextField(
        value, onChange, label = { Text(label) },
        keyboardOptions = KeyboardOptions(keyboardType = keyboard),
        modifier = Modifier.fillMaxWidth().semantics { contentDescription = label },
    )
}

/** The masking level in dBFS, from the floor to the hard cap (the rendered file's level). */
@Composable
private fun MaskingLevel(masking: MaskingSetting, onChange: (Double) -> Unit) {
    val level = masking.cappedLevelDbfs
    Text("Masking level: ${level.roundToInt()} dBFS (at most ${NoiseFiles.MAX_LEVEL_DBFS.roundToInt()})", style = MaterialTheme.typography.bodyMedium)
    Slider(
        value = level.toFloat(),
        onValueChange = { onChange(it.roundToInt().toDouble()) },
        valueRange = NoiseFiles.MIN_LEVEL_DBFS.toFloat()..NoiseFiles.MAX_LEVEL_DBFS.toFloat(),
        modifier = Modifier.semantics {
            contentDescription = "Masking level"
            stateDescription = "${level.roundToInt()} dBFS"
        },
    )
}
