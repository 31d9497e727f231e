package org.hapticon.app.feature.study

import android.content.ActivityNotFoundException
import android.content.Intent
import androidx.compose.foundation.layout.Arrangement
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
import androidx.compose.material3.HorizontalDivider
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Slider
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
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
import org.hapticon.app.feature.chat.Sticker
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.NoiseFiles
import org.hapticon.app.study.StudyExporter
import org.hapticon.app.ui.DropdownField
import org.hapticon.study.LikertScale
import org.hapticon.study.design.OrderScheme

/** The researcher screen: protocol, next session, sessions, export, share and upload. */
@Composable
fun ResearcherScreen(state: ResearcherUiState, viewModel: ResearcherViewModel, onEdit: (String) -> Unit) {
    val context = LocalContext.current
    fun share(file: File, type: String) {
        try {
            context.startActivity(Intent.createChooser(StudyExporter.shareIntent(context, file, type), "Share ${file.name}"))
        } catch (e: ActivityNotFoundException) {
            android.util.Log.w("Study", "no app to share with: ${e.message}")
        }
    }
    LazyColumn(Modifier.fillMaxSize(), contentPadding = PaddingValues(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        item {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
                Text("Study · researcher", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                TextButton(onClick = viewModel::lock) { Text("Lock") }
            }
        }
        item {
            val selected = state.selected
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                if (selected != null) {
                    DropdownField(
                        label = "Protocol",
                        options = state.protocols,
                        selected = selected,
                        optionLabel = { "${it.protocol.title} (${it.protocol.id} r${it.protocol.revision})" + if (it.readOnly) " · default" else "" },
                        onSelect = { viewModel.select(it.protocol.id) },
                    )
                    val masking = selected.masking
                    Text(
                        "${selected.protocol.tasks.size} tasks · task order ${selected.protocol.taskOrder.jsonName} · seed ${selected.seed} · masking " +
                            if (masking.isOn) "${masking.color.label} at ${"%.0f".format(Locale.ROOT, masking.cappedLevelDbfs)} dBFS" else "off",
                        style = MaterialTheme.typography.bodyMedium,
                    )
                    Row(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
                        if (selected.readOnly) {
                            OutlinedButton(onClick = { viewModel.duplicate(selected) }) { Text("Duplicate to edit") }
                        } else {
                            OutlinedButton(onClick = { onEdit(selected.protocol.id) }) { Text("Edit") }
                            OutlinedButton(onClick = { viewModel.duplicate(selected) }) { Text("Duplicate") }
                            OutlinedButton(onClick = { viewModel.delete(selected.protocol.id) }) { Text("Delete") }
                        }
                    }
                    Button(onClick = { viewModel.startSession() }, modifier = Modifier.fillMaxWidth()) {
                        Text("Start session for ${state.nextParticipant}")
                    }
                }
                state.message?.let { Text(it, style = MaterialTheme.typography.bodyMedium) }
            }
        }
        item { Text("Sessions", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() }) }
        if (state.sessions.isEmpty()) item { Text("No sessions yet.", style = MaterialTheme.typography.bodyMedium) }
        itemsIndexed(state.sessions, key = { _, s -> s.id }) { _, s ->
            Text(
                "${s.participant} · ${s.protocolId} · ${s.answers} of ${s.trials} rated · " +
                    when {
                        s.finished -> "finished"
                        s.id == state.activeSessionId -> "running"
                        else -> "incomplete"
                    },
                style = MaterialTheme.typography.bodyMedium,
            )
        }
        item { HorizontalDivider() }
        item {
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                Text("Export", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                Button(onClick = { viewModel.export() }) { Text("Export CSV + JSON") }
                state.export?.let { export ->
                    Text("${export.csvFile.name}, ${export.jsonFile.name}: ${export.rows} rows", style = MaterialTheme.typography.bodySmall)
                    for (check in export.checks) Text("${check.participant}: ${check.summary}", style = MaterialTheme.typography.bodyMedium)
                    Row(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
                        OutlinedButton(onClick = { share(export.csvFile, "text/csv") }) { Text("Share CSV") }
                        OutlinedButton(onClick = { share(export.jsonFile, "application/json") }) { Text("Share JSON") }
                    }
                }
            }
        }
        item { CollectorSettings(state, viewModel) }
    }
    if (state.headphoneWarning) {
        AlertDialog(
            onDismissRequest = viewModel::dismissHeadphoneWarning,
            title = { Text("No headphones connected") },
            text = { Text("The masking noise will play from the speaker, where the experimenter hears it too. Connect headphones, or start anyway.") },
            confirmButton = { TextButton(onClick = { viewModel.startSession(ignoreHeadphones = true) }) { Text("Start anyway") } },
            dismissButton = { TextButton(onClick = viewModel::dismissHeadphoneWarning) { Text("Cancel") } },
        )
    }
}

@Composable
private fun CollectorSettings(state: ResearcherUiState, viewModel: ResearcherViewModel) {
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
        Row(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
            OutlinedButton(onClick = { viewModel.setCollector(url, token) }) { Text("Save collector") }
            val failed = state.upload is UploadState.Failed
            Button(onClick = { viewModel.upload() }, enabled = state.upload != UploadState.Uploading && state.collectorUrl.isNotBlank()) {
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

/** The protocol editor: every field of the draft, the study module's validation message, JSON import and export. */
@Composable
fun ProtocolEditorScreen(state: ProtocolEditorUiState, viewModel: ProtocolEditorViewModel, onBack: () -> Unit) {
    val draft = state.draft
    LazyColumn(Modifier.fillMaxSize(), contentPadding = PaddingValues(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        item {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
                Text("Edit protocol", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                TextButton(onClick = onBack) { Text("Back") }
            }
        }
        state.message?.let { item { Text(it, style = MaterialTheme.typography.bodyMedium) } }
        if (draft == null) return@LazyColumn
        item {
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                Text("${draft.id} · revision ${draft.revision}", style = MaterialTheme.typography.labelLarge)
                TextRow("Title", draft.title) { v -> viewModel.edit { it.copy(title = v) } }
                DropdownField("Scale points", (2..LikertScale.MAX_POINTS).toList(), draft.points, { "$it" }, viewModel::setPoints)
                DropdownField("Task order", OrderScheme.entries, draft.taskOrder, { it.jsonName }, { v -> viewModel.edit { it.copy(taskOrder = v) } })
                TextRow("Seed", draft.seed.toString(), KeyboardType.Number) { v -> v.toLongOrNull()?.let { s -> viewModel.edit { it.copy(seed = s) } } }
                DropdownField("Masking noise", NoiseColor.entries, draft.masking.color, { it.label }, { v ->
                    viewModel.edit { it.copy(masking = it.masking.copy(color = v)) }
                })
                if (draft.masking.isOn) MaskingLevel(draft.masking) { level -> viewModel.edit { it.copy(masking = it.masking.copy(levelDbfs = level)) } }
            }
        }
        itemsIndexed(draft.tasks) { t, task ->
            Card(Modifier.fillMaxWidth()) {
                Column(Modifier.padding(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                    Text("Task ${t + 1}: ${task.id}", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                    TextRow("Task ${t + 1} title", task.title) { v -> viewModel.editTask(t) { it.copy(title = v) } }
                    TextRow("Task ${t + 1} instructions", task.instructions) { v -> viewModel.editTask(t) { it.copy(instructions = v) } }
                    TextRow("Task ${t + 1} question", task.question) { v -> viewModel.editTask(t) { it.copy(question = v) } }
                    DropdownField("Task ${t + 1} stimulus order", OrderScheme.entries, task.stimulusOrder, { it.jsonName }, { v ->
                        viewModel.editTask(t) { it.copy(stimulusOrder = v) }
                    })
                    task.stimuli.forEachIndexed { s, stimulus ->
                        HorizontalDivider()
                        Text("Stimulus ${s + 1}: ${stimulus.id}", style = MaterialTheme.typography.labelLarge)
                        val icons = if (state.icons.any { it == stimulus.icon }) state.icons else listOf(stimulus.icon) + state.icons
                        DropdownField("Task ${t + 1} stimulus ${s + 1} icon", icons, stimulus.icon, { it.name }, { icon ->
                            viewModel.editStimulus(t, s) { it.copy(icon = icon) }
                        })
                        TextRow("Task ${t + 1} stimulus ${s + 1} text", stimulus.text.orEmpty()) { v ->
                            viewModel.editStimulus(t, s) { it.copy(text = v.ifEmpty { null }) }
                        }
                        val stickers = listOf<String?>(null) + Sticker.entries.map { "sticker_${it.wireName}" }
                        DropdownField("Task ${t + 1} stimulus ${s + 1} sticker", (stickers + stimulus.sticker).distinct(), stimulus.sticker, { it ?: "none" }, { v ->
                            viewModel.editStimulus(t, s) { it.copy(sticker = v) }
                        })
                    }
                }
            }
        }
        item {
            Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                val problem = state.problem
                if (problem != null) ErrorText(problem) else Text("The protocol is valid.", style = MaterialTheme.typography.bodyMedium)
                Button(onClick = { viewModel.save() }, enabled = problem == null) { Text("Save") }
                Text("Protocol JSON", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                OutlinedTextField(state.json, viewModel::setJson, label = { Text("Protocol JSON") }, minLines = 4, modifier = Modifier.fillMaxWidth())
                Row(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
                    OutlinedButton(onClick = viewModel::exportJson) { Text("Export JSON") }
                    OutlinedButton(onClick = viewModel::importJson, enabled = state.json.isNotBlank()) { Text("Import JSON") }
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
