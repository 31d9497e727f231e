package org.hapticon.app.feature.gesture

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.gesture.TouchGestureSource
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.SwitchRow
import java.util.Locale

/** The Recognise tab wired to [viewModel]; [touch] is the touchscreen source the pad feeds. */
@Composable
fun RecognitionRoute(viewModel: RecognitionViewModel, touch: TouchGestureSource?) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel) {
        RecognitionActions(
            onSelectSource = viewModel::selectSource,
            onStart = viewModel::start,
            onStop = viewModel::stop,
            onSelectPeer = viewModel::selectPeer,
            onSetSendEnabled = viewModel::setSendEnabled,
            onDismissMessage = viewModel::dismissMessage,
        )
    }
    RecognitionScreen(uiState, touch, actions)
}

/** What the Recognise tab can ask for. */
@Immutable
class RecognitionActions(
    val onSelectSource: (GestureSourceKind) -> Unit = {},
    val onStart: () -> Unit = {},
    val onStop: () -> Unit = {},
    val onSelectPeer: (String) -> Unit = {},
    val onSetSendEnabled: (Boolean) -> Unit = {},
    val onDismissMessage: () -> Unit = {},
)

/** Live recognition with the stored model, and sending recognised gestures to a conversation. */
@Composable
fun RecognitionScreen(uiState: RecognitionUiState, touch: TouchGestureSource?, actions: RecognitionActions) {
    when (uiState) {
        RecognitionUiState.Loading -> GestureLoading()
        is RecognitionUiState.Ready -> RecognitionContent(uiState, touch, actions)
    }
}

@Composable
private fun RecognitionContent(state: RecognitionUiState.Ready, touch: TouchGestureSource?, actions: RecognitionActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message) { actions.onDismissMessage() }
        Text(state.model?.let { "Model: ${it.labels.joinToString { l -> l.id }}" } ?: "No model: teach or import one in the Teach tab")
        SourcePicker(state.sourceKind, !state.running) { actions.onSelectSource(it) }
        if (state.sourceKind == GestureSourceKind.TOUCH && touch != null) TouchPad(touch)
        if (state.running) {
            Button(onClick = { actions.onStop() }) { Text("Stop recognising") }
        } else {
            Button(onClick = { actions.onStart() }, enabled = state.model != null) { Text("Start recognising") }
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
            DropdownField("Conversation", SingleChoice(state.peers, peer) { it }, { actions.onSelectPeer(it) })
            SwitchRow("Send recognised gestures to $peer", state.sendEnabled, { actions.onSetSendEnabled(it) })
        }
        for (sent in state.sent) {
            Text(String.format(Locale.ROOT, "Sent %s (%s) to %s at %.1f s", sent.icon, sent.label.id, sent.peer, sent.atSeconds), style = MaterialTheme.typography.bodySmall)
        }
    }
}
