package org.hapticon.app.feature.study

import org.hapticon.app.data.ElectrodeLevelsStore
import android.content.ActivityNotFoundException
import android.content.Intent
import androidx.compose.foundation.Canvas
import androidx.compose.foundation.background
import androidx.compose.foundation.gestures.detectDragGestures
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.aspectRatio
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
import androidx.compose.runtime.mutableStateListOf
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.geometry.CornerRadius
import androidx.compose.ui.geometry.Offset
import androidx.compose.ui.geometry.Size
import androidx.compose.ui.graphics.Path
import androidx.compose.ui.graphics.PathEffect
import androidx.compose.ui.graphics.drawscope.Stroke
import androidx.compose.ui.input.pointer.pointerInput
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.platform.testTag
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.text.input.KeyboardType
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import org.hapticon.app.study.StudyExporter
import org.hapticon.app.ui.ButtonRow
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.LabeledValue
import org.hapticon.app.ui.SegmentedChoice
import org.hapticon.app.ui.SingleChoice
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceProtocol
import org.hapticon.study.compliance.ComplianceTask
import org.hapticon.study.compliance.DrawingPoint
import org.hapticon.study.compliance.RepetitionOrder
import java.io.File

/**
 * The compliance study wired to [viewModel]; [onCalibrate] opens the electrotactile calibration (the runner reads the
 * stored calibration again when it closes), [onBack] returns to the researcher screen.
 */
@Composable
fun ComplianceRoute(viewModel: ComplianceViewModel, onCalibrate: () -> Unit, onBack: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val context = LocalContext.current
    val actions = remember(viewModel, onBack, onCalibrate) {
        ComplianceActions(
            onProtocol = viewModel::selectProtocol,
            onParticipant = viewModel::setParticipant,
            onParticipantIndex = viewModel::setParticipantIndex,
            onStart = viewModel::start,
            onCalibrate = onCalibrate,
            onContinue = viewModel::continueAfterCalibration,
            onSendCondition = viewModel::sendCondition,
            onAnswer = viewModel::answer,
            onDrawing = viewModel::answerDrawing,
            onExport = viewModel::exportAnswers,
            onShare = { file ->
                try {
                    context.startActivity(Intent.createChooser(StudyExporter.shareIntent(context, file, "text/csv"), "Share ${file.name}"))
                } catch (e: ActivityNotFoundException) {
                    android.util.Log.w("Study", "no app to share with: ${e.message}")
                }
            },
            onFinish = viewModel::finish,
            onBack = onBack,
        )
    }
    ComplianceScreen(uiState, actions)
}

/** What the compliance study screen can ask for. */
@Immutable
class ComplianceActions(
    val onProtocol: (String) -> Unit = {},
    val onParticipant: (String) -> Unit = {},
    val onParticipantIndex: (Int) -> Unit = {},
    val onStart: () -> Unit = {},
    val onCalibrate: () -> Unit = {},
    val onContinue: () -> Unit = {},
    val onSendCondition: () -> Unit = {},
    val onAnswer: (String) -> Unit = {},
    val onDrawing: (Boolean?, List<List<DrawingPoint>>) -> Unit = { _, _ -> },
    val onExport: () -> Unit = {},
    val onShare: (File) -> Unit = {},
    val onFinish: () -> Unit = {},
    val onBack: () -> Unit = {},
)

/** Shaping Compliance's study: set up a participant, calibrate, then each condition pressed and answered. */
@Composable
fun ComplianceScreen(uiState: ComplianceUiState, actions: ComplianceActions) {
    Column(Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween, verticalAlignment = Alignment.CenterVertically) {
            Text("Compliance study", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.weight(1f).semantics { heading() })
            // During a session the way out is below, named for the researcher (it asks for the PIN again).
            if (uiState is ComplianceUiState.Setup || uiState is ComplianceUiState.Done) TextButton(onClick = actions.onBack) { Text("Back") }
        }
        when (uiState) {
            is ComplianceUiState.Setup -> SetupContent(uiState, actions)
            is ComplianceUiState.Calibrate -> CalibrateContent(uiState, actions)
            is ComplianceUiState.Trial -> TrialContent(uiState, actions)
            is ComplianceUiState.Done -> DoneContent(uiState, actions)
        }
        uiState.message?.let { ErrorText(it) }
    }
}

/** The protocol in one sentence: its conditions, trials, order, calibrations and answers. */
internal fun describe(protocol: ComplianceProtocol): String {
    val grains = protocol.conditions.map { it.grains }.distinct().joinToString(", ")
    val shapes = protocol.conditions.map { it.mask }.distinct().size
    val order = when (protocol.repetitionOrder) {
        RepetitionOrder.BLOCKS -> "${protocol.repetitions} blocks, each in its own counterbalanced order, with a break between" +
            if (protocol.calibrateEachRepetition) ", calibrated before each" else ", calibrated once"
        RepetitionOrder.SHUFFLED -> "one random order, calibrated once"
    }
    val answer = when (protocol.task) {
        ComplianceTask.MAGNITUDE -> "rated against the bare desk (0) with any signed number"
        ComplianceTask.DRAWING -> "answered yes/no (more compliant than the desk?) and drawn"
    }
    return "$grains grains × $shapes shapes × ${protocol.repetitions} = ${protocol.trialCount} trials in $order; $answer."
}

@Composable
private fun SetupContent(state: ComplianceUiState.Setup, actions: ComplianceActions) {
    DropdownField("Protocol", SingleChoice(state.protocols, state.protocol) { it.title }, { actions.onProtocol(it.id) }, Modifier.fillMaxWidth())
    Text(describe(state.protocol), style = MaterialTheme.typography.bodyMedium)
    OutlinedTextField(state.participant, actions.onParticipant, label = { Text("Participant") }, singleLine = true, modifier = Modifier.fillMaxWidth())
    DropdownField("Participant number (order)", SingleChoice((0 until 48).toList(), state.participantIndex) { (it + 1).toString() }, actions.onParticipantIndex)
    Text(
        state.calibration?.let { "Stored calibration: ${ElectrodeLevelsStore.describe(it)}. The session calibrates again before it starts." }
            ?: "The session starts with the electrotactile calibration.",
        style = MaterialTheme.typography.bodyMedium,
    )
    if (!state.boardReady) Text("No framed board is streaming: connect it on the Sensors screen.", style = MaterialTheme.typography.bodySmall)
    Button(onClick = actions.onStart, enabled = state.participant.isNotBlank(), modifier = Modifier.fillMaxWidth()) { Text("Start session") }
}

@Composable
private fun CalibrateContent(state: ComplianceUiState.Calibrate, actions: ComplianceActions) {
    val repetition = state.next.repetition + 1
    if (state.isBreak) {
        Text("Break", style = MaterialTheme.typography.titleLarge, modifier = Modifier.semantics { heading() })
        Text("Repetition ${repetition - 1} of ${state.protocol.repetitions} is done. Rest for a moment before the next one.", style = MaterialTheme.typography.bodyLarge)
    } else {
        Text("${state.participant}: calibration", style = MaterialTheme.typography.titleLarge, modifier = Modifier.semantics { heading() })
    }
    Text(
        if (state.protocol.calibrateEachRepetition) {
            "Calibrate the electrodes before repetition $repetition: each electrode from 0.8 mA until clear and pain-free, then all nine " +
                "while pressing until the sensation is uniform (the study recalibrates before every repetition)."
        } else {
            "Calibrate the electrodes before the trials: each electrode from 0.8 mA until clear and pain-free, then all nine while " +
                "pressing until the sensation is uniform."
        },
        style = MaterialTheme.typography.bodyMedium,
    )
    Text(
        when {
            state.calibration == null -> "No calibration stored yet."
            state.fresh -> "Calibrated: ${ElectrodeLevelsStore.describe(state.calibration)}."
            else -> "The stored calibration (${ElectrodeLevelsStore.describe(state.calibration)}) is from before this step."
        },
        style = MaterialTheme.typography.bodyMedium,
    )
    ButtonRow {
        OutlinedButton(onClick = actions.onCalibrate) { Text("Calibrate electrodes") }
        Button(onClick = actions.onContinue, enabled = state.fresh) { Text("Continue") }
    }
    TextButton(onClick = actions.onBack) { Text("Researcher: end the session") }
}

@Composable
private fun TrialContent(state: ComplianceUiState.Trial, actions: ComplianceActions) {
    val trial = state.trial
    LinearProgressIndicator(progress = { trial.index.toFloat() / state.total }, modifier = Modifier.fillMaxWidth())
    // A repetition is a block only in Task 1; in a shuffled list it says nothing to the participant.
    val block = if (state.protocol.repetitionOrder == RepetitionOrder.BLOCKS) " · repetition ${trial.repetition + 1} of ${state.protocol.repetitions}" else ""
    Text("${state.participant}$block · trial ${trial.index + 1} of ${state.total}", style = MaterialTheme.typography.titleMedium)
    Text(state.protocol.instructions, style = MaterialTheme.typography.bodyLarge)
    // The participant holds the phone: the condition itself stays in the answers file, not on screen.
    Text(if (state.sent) "Ready: press now" else "Waiting for the board…", style = MaterialTheme.typography.bodyMedium)
    when (state.protocol.task) {
        ComplianceTask.MAGNITUDE -> {
            var answer by rememberSaveable(trial.index) { mutableStateOf("") }
            OutlinedTextField(
                answer, { answer = it }, label = { Text("Compliance (bare desk = 0)") }, singleLine = true,
                keyboardOptions = KeyboardOptions(keyboardType = KeyboardType.Text), modifier = Modifier.fillMaxWidth(),
            )
            ButtonRow {
                Button(onClick = { actions.onAnswer(answer) }, enabled = state.sent && answer.isNotBlank()) { Text("Next") }
                OutlinedButton(onClick = actions.onSendCondition, enabled = state.boardReady) { Text("Send condition again") }
            }
        }
        ComplianceTask.DRAWING -> DrawingAnswer(state, actions)
    }
    TextButton(onClick = actions.onBack) { Text("Researcher: end the session") }
}

@Composable
private fun DrawingAnswer(state: ComplianceUiState.Trial, actions: ComplianceActions) {
    val index = state.trial.index
    var more by rememberSaveable(index) { mutableStateOf<Boolean?>(null) }
    val contours = remember(index) { mutableStateListOf<List<DrawingPoint>>() }
    Text("More compliant than the bare desk?", style = MaterialTheme.typography.titleSmall)
    SegmentedChoice(SingleChoice<Boolean?>(listOf(true, false), more) { if (it == true) "Yes" else "No" }, { more = it })
    Text("Draw the outline of where you felt compliance, inside the device's outline (the dashed square is the stimulated area).", style = MaterialTheme.typography.bodyMedium)
    DrawingCanvas(contours, Modifier.fillMaxWidth())
    ButtonRow {
        Button(onClick = { actions.onDrawing(more, contours.toList()) }, enabled = state.sent && more != null) { Text("Save drawing") }
        OutlinedButton(onClick = { if (contours.isNotEmpty()) contours.removeAt(contours.lastIndex) }, enabled = contours.isNotEmpty()) { Text("Undo outline") }
        OutlinedButton(onClick = actions.onSendCondition, enabled = state.boardReady) { Text("Send condition again") }
    }
}

/**
 * The drawing area of Task 2: the device's outline with the stimulated area as a dashed square (the paper showed the
 * participant "a piece of paper ... with the same shape and size as the stimulation device, indicating the stimulation
 * area with a square", 003_8ca1dc8f53472543.txt:175). Each stroke becomes one closed contour in 0..1 coordinates.
 */
@Composable
internal fun DrawingCanvas(contours: MutableList<List<DrawingPoint>>, modifier: Modifier = Modifier) {
    val stroke = remember { mutableStateListOf<DrawingPoint>() }
    val outline = MaterialTheme.colorScheme.onSurfaceVariant
    val ink = MaterialTheme.colorScheme.primary
    val background = MaterialTheme.colorScheme.surfaceVariant
    Box(
        modifier
            .aspectRatio(1f)
            .background(background, MaterialTheme.shapes.medium)
            .testTag(DRAWING_TAG)
            .semantics {
                contentDescription = "Drawing area: draw the outline of where you felt compliance"
                stateDescription = "${contours.size} outline${if (contours.size == 1) "" else "s"} drawn"
            }
            .pointerInput(Unit) {
                fun point(offset: Offset) = DrawingPoint((offset.x / size.width).toDouble().coerceIn(0.0, 1.0), (offset.y / size.height).toDouble().coerceIn(0.0, 1.0))
                detectDragGestures(
                    onDragStart = { stroke.clear(); stroke += point(it) },
                    onDrag = { change, _ -> stroke += point(change.position) },
                    onDragEnd = {
                        if (stroke.size >= 3) contours += stroke.toList()
                        stroke.clear()
                    },
                    onDragCancel = { stroke.clear() },
                )
            },
    ) {
        Canvas(Modifier.fillMaxSize()) {
            val w = size.width
            val h = size.height
            // The device: a fingertip pad, rounded; the stimulated area: the 3×3 array's square at its centre.
            drawRoundRect(outline, Offset(w * 0.12f, h * 0.06f), Size(w * 0.76f, h * 0.88f), CornerRadius(w * 0.3f), style = Stroke(width = 3f))
            drawRect(outline, Offset(w * 0.3f, h * 0.3f), Size(w * 0.4f, h * 0.4f), style = Stroke(width = 3f, pathEffect = PathEffect.dashPathEffect(floatArrayOf(12f, 8f))))
            fun draw(points: List<DrawingPoint>, closed: Boolean) {
                if (points.size < 2) return
                val path = Path()
                path.moveTo(points[0].x.toFloat() * w, points[0].y.toFloat() * h)
                for (p in points.drop(1)) path.lineTo(p.x.toFloat() * w, p.y.toFloat() * h)
                if (closed) path.close()
                drawPath(path, ink, style = Stroke(width = 6f))
            }
            for (points in contours) draw(points, closed = true)
            draw(stroke.toList(), closed = false)
        }
    }
}

/** The drawing area's test tag. */
internal const val DRAWING_TAG = "compliance-drawing"

@Composable
private fun DoneContent(state: ComplianceUiState.Done, actions: ComplianceActions) {
    Text("${state.participant}: ${state.answers} answers saved to ${state.file.name}", style = MaterialTheme.typography.bodyMedium)
    if (state.protocol.task == ComplianceTask.MAGNITUDE) {
        Text("Median standardized score (answers ÷ SD per repetition)", style = MaterialTheme.typography.titleMedium)
        state.summaryProblem?.let { Text(it, style = MaterialTheme.typography.bodyMedium) }
        for ((id, median) in state.medians) {
            val label = ComplianceCondition.parse(id)?.let(ComplianceViewModel::describe) ?: id
            LabeledValue(label, ComplianceViewModel.format(median))
        }
    }
    ButtonRow {
        OutlinedButton(onClick = actions.onExport) { Text("Export answers") }
        state.exported?.let { file -> OutlinedButton(onClick = { actions.onShare(file) }) { Text("Share CSV") } }
    }
    Button(onClick = actions.onFinish) { Text("Next participant") }
}
