package org.hapticon.app.feature.gesture

import android.view.MotionEvent
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
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
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.setValue
import androidx.compose.ui.ExperimentalComposeUiApi
import androidx.compose.ui.Modifier
import androidx.compose.ui.input.pointer.pointerInteropFilter
import androidx.compose.ui.layout.onSizeChanged
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.IntSize
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.SwitchRow
import org.hapticon.gesture.social.ContactFrame
import java.util.Locale
import org.hapticon.app.ui.ButtonRow

/** The Social touch tab wired to [viewModel]; [onImportModel] and [onClassifyFile] open the file picker. */
@Composable
fun SocialTouchRoute(viewModel: SocialTouchViewModel, onImportModel: () -> Unit, onClassifyFile: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onImportModel, onClassifyFile) {
        SocialTouchActions(
            onContact = viewModel::contact,
            onImportModel = onImportModel,
            onClassifyFile = onClassifyFile,
            onTeaching = viewModel::setTeaching,
            onTeachLabel = viewModel::setTeachLabel,
            onTrain = viewModel::train,
            onClearExamples = viewModel::clearExamples,
            onSelectPeer = viewModel::selectPeer,
            onSetSendEnabled = viewModel::setSendEnabled,
            onDismissMessage = viewModel::dismissMessage,
        )
    }
    SocialTouchScreen(uiState, actions)
}

/** What the Social touch tab can ask for. */
@Immutable
class SocialTouchActions(
    val onContact: (ContactFrame) -> Unit = {},
    val onImportModel: () -> Unit = {},
    val onClassifyFile: () -> Unit = {},
    val onTeaching: (Boolean) -> Unit = {},
    val onTeachLabel: (String) -> Unit = {},
    val onTrain: () -> Unit = {},
    val onClearExamples: () -> Unit = {},
    val onSelectPeer: (String) -> Unit = {},
    val onSetSendEnabled: (Boolean) -> Unit = {},
    val onDismissMessage: () -> Unit = {},
)

/** Touch the pad, lift, and see the message's class and probability; teach classes and train here, or import a model. */
@Composable
fun SocialTouchScreen(uiState: SocialTouchUiState, actions: SocialTouchActions) {
    when (uiState) {
        SocialTouchUiState.Loading -> GestureLoading()
        is SocialTouchUiState.Ready -> SocialTouchContent(uiState, actions)
    }
}

@Composable
private fun SocialTouchContent(state: SocialTouchUiState.Ready, actions: SocialTouchActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Message(state.message, actions.onDismissMessage)
        Text(
            if (state.modelLabels.isEmpty()) {
                "No social-touch model: teach one below, or import one made by hapticon train --classifier logitboost"
            } else {
                "Model: ${state.modelLabels.size} classes: ${state.modelLabels.joinToString()}"
            },
        )
        ContactPad(actions.onContact)
        Text(
            when {
                state.touching -> "Touching · ${touches(state.touches)}"
                state.touches > 0 -> "${touches(state.touches)}: a second without contact ends the message"
                else -> "Touch the pad as you would touch a person; a second without contact ends the message"
            },
            style = MaterialTheme.typography.bodySmall,
        )
        val latest = state.latest
        Text(
            latest?.let { String.format(Locale.ROOT, "%s (%.0f %%)", it.label, 100 * it.probability) } ?: "—",
            style = MaterialTheme.typography.headlineMedium,
            modifier = Modifier.semantics { contentDescription = "Recognised touch: ${latest?.label ?: "nothing yet"}" },
        )
        latest?.let { Text(String.format(Locale.ROOT, "%s over %.1f s · %s", touches(it.touches), it.seconds, it.source), style = MaterialTheme.typography.bodySmall) }
        ButtonRow {
            OutlinedButton(onClick = actions.onImportModel) { Text("Import model") }
            OutlinedButton(onClick = actions.onClassifyFile, enabled = state.modelLabels.isNotEmpty()) { Text("Classify a contact CSV") }
        }
        TeachSection(state, actions)
        if (state.peers.isNotEmpty()) {
            val peer = state.peer ?: state.peers.first()
            DropdownField("Conversation", SingleChoice(state.peers, peer) { it }, actions.onSelectPeer)
            SwitchRow("Send recognised touches to $peer as their icon", state.sendEnabled, actions.onSetSendEnabled)
        }
        for (result in state.results.drop(1)) {
            Text(String.format(Locale.ROOT, "%s (%.0f %%) · %s · %s", result.label, 100 * result.probability, touches(result.touches), result.source), style = MaterialTheme.typography.bodySmall)
        }
    }
}

@Composable
private fun TeachSection(state: SocialTouchUiState.Ready, actions: SocialTouchActions) {
    Text("Teach", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
    SwitchRow("Touches become examples instead of being recognised", state.teaching, actions.onTeaching)
    if (state.teaching) {
        OutlinedTextField(state.teachLabel, actions.onTeachLabel, label = { Text("Class, e.g. surprise") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    }
    if (state.examples.isNotEmpty()) {
        Text(state.examples.entries.joinToString(" · ") { "${it.key}: ${it.value}" }, style = MaterialTheme.typography.bodyMedium)
    }
    ButtonRow {
        Button(onClick = actions.onTrain, enabled = state.examples.size >= 2 && !state.training) { Text(if (state.training) "Training…" else "Train") }
        OutlinedButton(onClick = actions.onClearExamples, enabled = state.examples.isNotEmpty()) { Text("Clear examples") }
    }
}

/**
 * The pad the social touch is given on: every pointer sample (batched ones included) becomes a [ContactFrame] —
 * the event's uptime in seconds, the screen's pressure as intensity (at least [MIN_CONTACT_PRESSURE] while a
 * finger is down, since some screens report 0), the position across the pad (0..1) and [MotionEvent.getSize]
 * as contact area; lifting the finger gives a frame of no contact.
 */
@OptIn(ExperimentalComposeUiApi::class)
@Composable
internal fun ContactPad(onContact: (ContactFrame) -> Unit) {
    var size by remember { mutableStateOf(IntSize.Zero) }
    Box(
        Modifier
            .fillMaxWidth()
            .height(200.dp)
            .background(MaterialTheme.colorScheme.secondaryContainer, MaterialTheme.shapes.medium)
            .onSizeChanged { size = it }
            .semantics { contentDescription = "Social touch pad: touch, stroke, pat or squeeze here" }
            .pointerInteropFilter { event ->
                contactFrames(event, size).forEach(onContact)
                true
            },
    ) {
        Text("Touch here", Modifier.padding(12.dp), style = MaterialTheme.typography.labelLarge)
    }
}

/** The contact frames of [event] on a pad of [size] px: its batched samples, then the current one (no contact when lifted). */
internal fun contactFrames(event: MotionEvent, size: IntSize): List<ContactFrame> {
    val w = size.width.coerceAtLeast(1).toDouble()
    val h = size.height.coerceAtLeast(1).toDouble()
    fun frame(timeMillis: Long, x: Float, y: Float, pressure: Float, area: Float, down: Boolean) = ContactFrame(
        timeMillis / 1000.0,
        if (down) maxOf(pressure.toDouble(), MIN_CONTACT_PRESSURE) else 0.0,
        (x / w).coerceIn(0.0, 1.0),
        (y / h).coerceIn(0.0, 1.0),
        if (down) area.toDouble() else 0.0,
    )
    val lifted = event.actionMasked == MotionEvent.ACTION_UP || event.actionMasked == MotionEvent.ACTION_CANCEL
    val frames = ArrayList<ContactFrame>(event.historySize + 1)
    for (i in 0 until event.historySize) {
        frames += frame(event.getHistoricalEventTime(i), event.getHistoricalX(i), event.getHistoricalY(i), event.getHistoricalPressure(i), event.getHistoricalSize(i), true)
    }
    frames += frame(event.eventTime, event.x, event.y, event.pressure, event.size, !lifted)
    return frames
}

private fun touches(n: Int): String = if (n == 1) "1 touch" else "$n touches"

/** The smallest intensity of a finger that is down: a screen reporting pressure 0 must still count as contact. */
internal const val MIN_CONTACT_PRESSURE: Double = 0.01
