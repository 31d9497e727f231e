package org.hapticon.app.feature.study

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.LinearProgressIndicator
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.text.input.KeyboardType
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.LabeledValue
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.study.compliance.ComplianceProtocol
import java.util.Locale
import org.hapticon.app.ui.ButtonRow

/** The compliance study wired to [viewModel]; [onBack] returns to the researcher screen. */
@Composable
fun ComplianceRoute(viewModel: ComplianceViewModel, onBack: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onBack) {
        ComplianceActions(
            onParticipant = viewModel::setParticipant,
            onParticipantIndex = viewModel::setParticipantIndex,
            onRepetitions = viewModel::setRepetitions,
            onStart = viewModel::start,
            onSendCondition = viewModel::sendCondition,
            onAnswer = viewModel::answer,
            onFinish = viewModel::finish,
            onBack = onBack,
        )
    }
    ComplianceScreen(uiState, actions)
}

/** What the compliance study screen can ask for. */
@Immutable
class ComplianceActions(
    val onParticipant: (String) -> Unit = {},
    val onParticipantIndex: (Int) -> Unit = {},
    val onRepetitions: (Int) -> Unit = {},
    val onStart: () -> Unit = {},
    val onSendCondition: () -> Unit = {},
    val onAnswer: (String) -> Unit = {},
    val onFinish: () -> Unit = {},
    val onBack: () -> Unit = {},
)

/** Shaping Compliance's study: set up a participant, then each condition pressed and answered with a number. */
@Composable
fun ComplianceScreen(uiState: ComplianceUiState, actions: ComplianceActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween, verticalAlignment = Alignment.CenterVertically) {
            Text("Compliance study", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.weight(1f).semantics { heading() })
            // During a trial the way out is below, named for the researcher (it asks for the PIN again).
            if (uiState !is ComplianceUiState.Trial) TextButton(onClick = actions.onBack) { Text("Back") }
        }
        when (uiState) {
            is ComplianceUiState.Setup -> SetupContent(uiState, actions)
            is ComplianceUiState.Trial -> TrialContent(uiState, actions)
            is ComplianceUiState.Done -> DoneContent(uiState, actions)
        }
        uiState.message?.let { ErrorText(it) }
    }
}

@Composable
private fun SetupContent(state: ComplianceUiState.Setup, actions: ComplianceActions) {
    val protocol = state.protocol
    Text(protocol.title, style = MaterialTheme.typography.titleMedium)
    Text(
        "${protocol.conditions.size} conditions (0, 9, 19, 39 grains × 5 electrode shapes) × ${protocol.repetitions} = " +
            "${protocol.conditions.size * protocol.repetitions} trials in random order per participant; answers by magnitude estimation.",
        style = MaterialTheme.typography.bodyMedium,
    )
    OutlinedTextField(state.participant, actions.onParticipant, label = { Text("Participant") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    ButtonRow {
        DropdownField("Participant number", SingleChoice((0 until 40).toList(), state.participantIndex) { (it + 1).toString() }, actions.onParticipantIndex)
        DropdownField("Repetitions", SingleChoice((1..ComplianceProtocol.MAX_REPETITIONS).toList(), protocol.repetitions) { it.toString() }, actions.onRepetitions)
    }
    Text(
        state.levels?.let { steps ->
            "Electrode levels (mA, electrodes 1–9): " + steps.joinToString(" · ") { String.format(Locale.ROOT, "%.2f", AmplitudeSteps.milliampsOf(it)) }
        } ?: "Electrodes not calibrated: Sensors › Electrotactile array",
        style = MaterialTheme.typography.bodyMedium,
    )
    if (!state.boardReady) Text("No framed board is streaming: connect it on the Sensors screen.", style = MaterialTheme.typography.bodySmall)
    Button(onClick = actions.onStart, enabled = state.levels != null, modifier = Modifier.fillMaxWidth()) { Text("Start session") }
}

@Composable
private fun TrialContent(state: ComplianceUiState.Trial, actions: ComplianceActions) {
    val trial = state.trial
    LinearProgressIndicator(progress = { trial.index.toFloat() / state.total }, modifier = Modifier.fillMaxWidth())
    Text("${state.participant} · trial ${trial.index + 1} of ${state.total}", style = MaterialTheme.typography.titleMedium)
    Text(state.instructions, style = MaterialTheme.typography.bodyLarge)
    // The participant holds the phone: the condition itself stays in the answers file, not on screen.
    Text(if (state.sent) "Ready: press the sensor now" else "Waiting for the board…", style = MaterialTheme.typography.bodyMedium)
    var answer by rememberSaveable(trial.index) { mutableStateOf("") }
    OutlinedTextField(
        answer, { answer = it }, label = { Text("How soft, as a number") }, singleLine = true,
        keyboardOptions = KeyboardOptions(keyboardType = KeyboardType.Decimal), modifier = Modifier.fillMaxWidth(),
    )
    ButtonRow {
        Button(onClick = { actions.onAnswer(answer) }, enabled = state.sent && answer.isNotBlank()) { Text("Next") }
        OutlinedButton(onClick = actions.onSendCondition, enabled = state.boardReady) { Text("Send condition again") }
    }
    TextButton(onClick = actions.onBack) { Text("Researcher: end the session") }
}

@Composable
private fun DoneContent(state: ComplianceUiState.Done, actions: ComplianceActions) {
    Text("${state.participant}: ${state.answers} answers saved to ${state.file}", style = MaterialTheme.typography.bodyMedium)
    Text("Normalised geometric means", style = MaterialTheme.typography.titleMedium)
    for ((condition, mean) in state.means) LabeledValue(condition, String.format(Locale.ROOT, "%.2f", mean))
    Button(onClick = actions.onFinish) { Text("Next participant") }
}
