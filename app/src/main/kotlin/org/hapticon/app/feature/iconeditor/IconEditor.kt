package org.hapticon.app.feature.iconeditor

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import androidx.lifecycle.ViewModel
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewModelScope
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.playOffMain
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException

/** The editor's fields, in the order shown; [key] is the field name HapticIcon's validation uses. */
enum class IconField(val key: String, val label: String) {
    NAME("name", "Name"),
    ATTACK("attack", "Attack (s)"),
    SUSTAIN("sustain", "Sustain (s)"),
    LEVEL("level", "Level (0–1)"),
    RELEASE("release", "Release (s)"),
    NOTE("note", "Note (MIDI)"),
    PERIOD("period", "Period (s)"),
    COUNT("count", "Count"),
}

/** The editor: the text of every field and either the icon they make or the first problem, by field. */
data class IconEditorUiState(
    val fields: Map<IconField, String>,
    val icon: HapticIcon?,
    val errors: Map<IconField, String>,
    val saved: Boolean = false,
)

class IconEditorViewModel(
    private val icons: RoomIconRepository,
    private val player: HapticPlayer,
    start: HapticIcon = HapticIcon("custom", 0.1, 0.3, 0.8, 0.2, 60.0, 0.0, 1),
) : ViewModel() {
    private val fields = MutableStateFlow(
        mapOf(
            IconField.NAME to start.name, IconField.ATTACK to start.attack.toString(), IconField.SUSTAIN to start.sustain.toString(),
            IconField.LEVEL to start.level.toString(), IconField.RELEASE to start.release.toString(), IconField.NOTE to start.note.toString(),
            IconField.PERIOD to start.period.toString(), IconField.COUNT to start.count.toString(),
        ),
    )
    private val saved = MutableStateFlow(false)

    val uiState: StateFlow<IconEditorUiState> = fields.map { validate(it) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, validate(fields.value))

    fun update(field: IconField, text: String) {
        saved.value = false
        fields.value = fields.value + (field to text)
    }

    fun play() {
        uiState.value.icon?.let { viewModelScope.launch { player.playOffMain(it) } }
    }

    fun save(onSaved: () -> Unit = {}) {
        val icon = uiState.value.icon ?: return
        viewModelScope.launch {
            icons.save(icon)
            onSaved()
        }
    }

    companion object {
        /** Parses and validates [fields]: numbers first, then HapticIcon's own rules, whose exception names the field. */
        fun validate(fields: Map<IconField, String>): IconEditorUiState {
            val errors = mutableMapOf<IconField, String>()
            fun number(field: IconField): Double = fields[field]?.trim()?.toDoubleOrNull()
                ?: 0.0.also { errors[field] = "Enter a number" }
            val attack = number(IconField.ATTACK)
            val sustain = number(IconField.SUSTAIN)
            val level = number(IconField.LEVEL)
            val release = number(IconField.RELEASE)
            val note = number(IconField.NOTE)
            val period = number(IconField.PERIOD)
            val count = fields[IconField.COUNT]?.trim()?.toIntOrNull() ?: 0.also { errors[IconField.COUNT] = "Enter a whole number" }
            if (errors.isNotEmpty()) return IconEditorUiState(fields, null, errors)
            return try {
                val icon = HapticIcon(fields[IconField.NAME].orEmpty().trim(), attack, sustain, level, release, note, period, count)
                IconEditorUiState(fields, icon, emptyMap())
            } catch (e: IconValidationException) {
                val field = IconField.entries.firstOrNull { it.key == e.field } ?: IconField.NAME
                IconEditorUiState(fields, null, mapOf(field to (e.message ?: "Not valid")))
            }
        }
    }
}

@Composable
fun IconEditorRoute(icons: RoomIconRepository, player: HapticPlayer, onDone: () -> Unit) {
    val viewModel: IconEditorViewModel = viewModel(factory = viewModelFactory { initializer { IconEditorViewModel(icons, player) } })
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    IconEditorScreen(uiState, viewModel::update, viewModel::play, onSave = { viewModel.save(onDone) }, onBack = onDone)
}

/** Seven parameters and a name, a live envelope plot, each field's validation message under it, play and save. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun IconEditorScreen(
    uiState: IconEditorUiState,
    onChange: (IconField, String) -> Unit,
    onPlay: () -> Unit,
    onSave: () -> Unit,
    onBack: () -> Unit,
) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("New haptic icon") },
                navigationIcon = { IconButton(onClick = onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Close the editor") } },
            )
        },
    ) { padding ->
        Column(
            Modifier.fillMaxSize().padding(padding).padding(16.dp).verticalScroll(rememberScrollState()),
            verticalArrangement = Arrangement.spacedBy(8.dp),
        ) {
            uiState.icon?.let { EnvelopeThumbnail(it, Modifier.fillMaxWidth().height(96.dp)) }
                ?: Text("Fix the fields below to see the envelope", style = MaterialTheme.typography.bodySmall)
            for (field in IconField.entries) {
                val error = uiState.errors[field]
                OutlinedTextField(
                    value = uiState.fields[field].orEmpty(),
                    onValueChange = { onChange(field, it) },
                    label = { Text(field.label) },
                    isError = error != null,
                    supportingText = error?.let { { Text(it) } },
                    singleLine = true,
                    modifier = Modifier.fillMaxWidth(),
                )
            }
            Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
                OutlinedButton(onClick = onPlay, enabled = uiState.icon != null) { Text("Play") }
                Button(onClick = onSave, enabled = uiState.icon != null) { Text("Save") }
            }
        }
    }
}
