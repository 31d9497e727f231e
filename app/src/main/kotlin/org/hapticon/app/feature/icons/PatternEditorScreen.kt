package org.hapticon.app.feature.icons

import androidx.compose.runtime.getValue
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.ui.EditorScaffold
import org.hapticon.app.ui.PatternThumbnail
import org.hapticon.app.ui.PlayAndSave
import org.hapticon.app.ui.ValidatedField
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.edited

@Composable
fun PatternEditorRoute(pattern: HapticPattern, repository: RoomPatternRepository, player: HapticPlayer, onDone: () -> Unit) {
    val viewModel: PatternEditorViewModel = viewModel(
        key = "pattern-editor:${pattern.name}",
        factory = viewModelFactory { initializer { PatternEditorViewModel(pattern, repository, player) } },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    PatternEditorScreen(uiState, viewModel::update, viewModel::play, onSave = { viewModel.save(onDone) }, onBack = onDone)
}

/** The original and the edited pattern plotted, the edits with their validation messages, how this phone plays it, play and save. */
@Composable
fun PatternEditorScreen(
    uiState: PatternEditorUiState,
    onChange: (PatternEditField, String) -> Unit,
    onPlay: () -> Unit,
    onSave: () -> Unit,
    onBack: () -> Unit,
) {
    EditorScaffold("Edit ${uiState.original.name}", onBack) {
        Text("Original: ${describe(uiState.original, null)}", style = MaterialTheme.typography.bodySmall)
        PatternThumbnail(uiState.original, Modifier.fillMaxWidth().height(64.dp))
        val preview = uiState.preview
        if (preview != null) {
            Text("Edited: ${describe(preview, null)}", style = MaterialTheme.typography.bodySmall)
            PatternThumbnail(preview, Modifier.fillMaxWidth().height(96.dp))
            uiState.playedAs?.let { Text("This phone: $it", style = MaterialTheme.typography.labelMedium) }
        } else {
            Text("Fix the fields below to see the edited pattern", style = MaterialTheme.typography.bodySmall)
        }
        for (field in PatternEditField.entries) {
            ValidatedField(uiState.fields[field].orEmpty(), field.label, uiState.errors[field]) { onChange(field, it) }
        }
        PlayAndSave(preview != null, onPlay, onSave)
    }
}
