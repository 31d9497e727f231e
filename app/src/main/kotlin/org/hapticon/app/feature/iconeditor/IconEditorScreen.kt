package org.hapticon.app.feature.iconeditor

import androidx.compose.runtime.getValue
import androidx.compose.runtime.Immutable
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.ui.EditorScaffold
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.app.ui.PlayAndSave
import org.hapticon.app.ui.ValidatedField

/** What the editor can ask for. */
@Immutable
class IconEditorActions(
    val onChange: (IconField, String) -> Unit = { _, _ -> },
    val onPlay: () -> Unit = {},
    val onSave: () -> Unit = {},
    val onBack: () -> Unit = {},
)

@Composable
fun IconEditorRoute(icons: RoomIconRepository, player: HapticPlayer, onDone: () -> Unit) {
    val viewModel: IconEditorViewModel = viewModel(factory = viewModelFactory { initializer { IconEditorViewModel(icons, player) } })
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onDone) {
        IconEditorActions(onChange = viewModel::update, onPlay = viewModel::play, onSave = { viewModel.save(onDone) }, onBack = onDone)
    }
    IconEditorScreen(uiState, actions)
}

/** Seven parameters and a name, a live envelope plot, each field's validation message under it, play and save. */
@Composable
fun IconEditorScreen(uiState: IconEditorUiState, actions: IconEditorActions) {
    EditorScaffold("New haptic icon", actions.onBack) {
        uiState.icon?.let { EnvelopeThumbnail(it, Modifier.fillMaxWidth().height(96.dp)) }
            ?: Text("Fix the fields below to see the envelope", style = MaterialTheme.typography.bodySmall)
        for (field in IconField.entries) {
            ValidatedField(uiState.fields[field].orEmpty(), field.label, uiState.errors[field]) { actions.onChange(field, it) }
        }
        PlayAndSave(uiState.icon != null, actions.onPlay, actions.onSave)
    }
}
