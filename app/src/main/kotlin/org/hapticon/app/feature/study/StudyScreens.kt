package org.hapticon.app.feature.study

import androidx.compose.foundation.Image
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.layout.widthIn
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.selection.selectable
import androidx.compose.foundation.selection.selectableGroup
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.AlertDialog
import androidx.compose.material3.AssistChip
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.Icon
import androidx.compose.material3.LinearProgressIndicator
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.RadioButton
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.LaunchedEffect
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.res.painterResource
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.text.input.KeyboardType
import androidx.compose.ui.text.input.PasswordVisualTransformation
import androidx.compose.ui.text.style.TextAlign
import androidx.compose.ui.unit.dp
import androidx.lifecycle.Lifecycle
import androidx.lifecycle.compose.LifecycleEventEffect
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.data.IconRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.study.StudyComponent
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.ui.Sticker
import org.hapticon.app.data.ElectrodeLevelsStore
import org.hapticon.study.LikertScale
import org.hapticon.study.Stimulus
import org.hapticon.study.StudyStep
import java.io.File

/**
 * The Study destination: the running session when there is one (the app reopens into it), else the PIN gate, the
 * researcher screen or the protocol editor. Sessions play on [player], protocols pick from [icons]; the compliance
 * study drives the [stimulator] and redoes its calibration in [electrotactileCalibration], a screen of the Sensors
 * feature that the app's navigation hands in (a new key each round: a fresh calibration).
 */
@Composable
fun StudyRoute(
    study: StudyComponent?,
    player: HapticPlayer,
    icons: IconRepository,
    stimulator: StimulatorLink,
    electrotactileCalibration: @Composable (key: String, onBack: () -> Unit) -> Unit,
) {
    if (study == null) return
    val researcher: ResearcherViewModel = viewModel(factory = viewModelFactory { initializer { ResearcherViewModel(study) } })
    val state by researcher.uiState.collectAsStateWithLifecycle()
    var editing by rememberSaveable { mutableStateOf<String?>(null) }
    var compliance by rememberSaveable { mutableStateOf(false) }
    // The compliance study's calibration, opened from its runner; each opening is a new round (a fresh calibration).
    var calibrating by rememberSaveable { mutableStateOf(false) }
    var calibrationRound by rememberSaveable { mutableStateOf(0) }
    // Until the stored sessions are read it is not known whether a session is running: the researcher screen's spinner.
    val ready = state as? ResearcherUiState.Success
    val active = ready?.activeSessionId
    when {
        ready == null -> ResearcherScreen(state, ResearcherActions())
        active != null -> SessionRoute(active, study, player, researcher, pinError = state.pinError)
        state.lock != LockState.UNLOCKED -> PinScreen(state.lock, state.pinError, onSetPin = researcher::setPin, onUnlock = { researcher.unlock(it) })
        // The calibration the study redoes before each repetition: a fresh one each time (keyed by the round).
        compliance && calibrating -> electrotactileCalibration("compliance-calibration-$calibrationRound") { calibrating = false }
        compliance -> ComplianceStudyRoute(
            stimulator, calibrationRound,
            onCalibrate = {
                calibrationRound++
                calibrating = true
            },
            onLock = researcher::lock,
            onBack = { compliance = false },
        )
        editing != null -> ProtocolEditorRoute(editing!!, study, icons, onBack = { editing = null })
        else -> ResearcherRoute(ready, researcher, onEdit = { editing = it }, onOpenCompliance = { compliance = true })
    }
}

/** The running session [sessionId], played on [player]; the participant leaves it through the researcher's PIN. */
@Composable
private fun SessionRoute(sessionId: Long, study: StudyComponent, player: HapticPlayer, researcher: ResearcherViewModel, pinError: String?) {
    val session: StudySessionViewModel = viewModel(
        key = "study-session-$sessionId",
        factory = viewModelFactory { initializer { StudySessionViewModel(sessionId, study.repository, player, study.noise, study.clock) } },
    )
    LifecycleEventEffect(Lifecycle.Event.ON_PAUSE) { session.pause() }
    LifecycleEventEffect(Lifecycle.Event.ON_RESUME) { session.resume() }
    val sessionState by session.uiState.collectAsStateWithLifecycle()
    val actions = remember(session, researcher) {
        SessionActions(
            onStartTask = { session.startTask() },
            onPressIcon = { session.pressIcon() },
            onPressStimulus = { session.pressIcon(it) },
            onFinishExploring = { session.finishExploring() },
            onSelect = { session.select(it) },
            onNext = { session.next() },
            onFinishTask = { session.finishTask() },
            onExit = { researcher.exitSession(it) },
        )
    }
    SessionScreen(sessionState, actions, pinError = pinError)
}

/**
 * The compliance study's runner over [stimulator], reading the stored calibration again whenever
 * [calibrationRound] changes (back from a calibration). Leaving a running session calls [onLock] first.
 */
@Composable
private fun ComplianceStudyRoute(stimulator: StimulatorLink, calibrationRound: Int, onCalibrate: () -> Unit, onLock: () -> Unit, onBack: () -> Unit) {
    val context = LocalContext.current
    val runner: ComplianceViewModel = viewModel(
        factory = viewModelFactory {
            initializer {
                val levels = ElectrodeLevelsStore.inFolder(context.filesDir)
                ComplianceViewModel(stimulator, levels::stored, File(context.filesDir, "compliance"), File(context.cacheDir, "exports"))
            }
        },
    )
    // Back from the calibration: read what it stored.
    LaunchedEffect(calibrationRound) { runner.refreshCalibration() }
    ComplianceRoute(
        runner,
        onCalibrate = onCalibrate,
        onBack = {
            // Leaving a running session asks for the PIN again, as the Likert sessions' way out does.
            val running = runner.uiState.value
            if (running is ComplianceUiState.Trial || running is ComplianceUiState.Calibrate) onLock()
            runner.finish()
            onBack()
        },
    )
}

/** The protocol editor for the stored protocol [id], its stimuli picked from [icons]. */
@Composable
private fun ProtocolEditorRoute(id: String, study: StudyComponent, icons: IconRepository, onBack: () -> Unit) {
    val editor: ProtocolEditorViewModel = viewModel(
        key = "protocol-editor-$id",
        factory = viewModelFactory { initializer { ProtocolEditorViewModel(id, study.repository, icons) } },
    )
    val editorState by editor.uiState.collectAsStateWithLifecycle()
    val actions = remember(editor, onBack) {
        ProtocolEditorActions(
            onBack = onBack,
            onEdit = editor::edit,
            onSetPoints = editor::setPoints,
            onEditTask = editor::editTask,
            onEditStimulus = editor::editStimulus,
            onSave = { editor.save() },
            onSetJson = editor::setJson,
            onExportJson = editor::exportJson,
            onImportJson = editor::importJson,
        )
    }
    ProtocolEditorScreen(editorState, actions)
}

/** The unlocked researcher screen: protocols, sessions, export and upload, wired to [researcher]. */
@Composable
private fun ResearcherRoute(ready: ResearcherUiState.Success, researcher: ResearcherViewModel, onEdit: (String) -> Unit, onOpenCompliance: () -> Unit) {
    val actions = remember(researcher) {
        ResearcherActions(
            onLock = researcher::lock,
            onSelect = researcher::select,
            onEdit = onEdit,
            onDuplicate = { researcher.duplicate(it) },
            onDelete = { researcher.delete(it) },
            onStartSession = { researcher.startSession(ignoreHeadphones = it) },
            onDismissHeadphoneWarning = researcher::dismissHeadphoneWarning,
            onExport = { researcher.export() },
            onSetCollector = { url, token -> researcher.setCollector(url, token) },
            onUpload = { researcher.upload() },
            onOpenCompliance = onOpenCompliance,
        )
    }
    ResearcherScreen(ready, actions)
}

/** First use: set the researcher PIN (twice); afterwards: enter it. A wrong PIN shows "wrong PIN". */
@Composable
fun PinScreen(lock: LockState, error: String?, onSetPin: (String, String) -> Unit, onUnlock: (String) -> Unit) {
    var pin by rememberSaveable { mutableStateOf("") }
    var confirm by rememberSaveable { mutableStateOf("") }
    val setting = lock == LockState.SET_PIN
    Column(
        Modifier.fillMaxSize().padding(24.dp),
        verticalArrangement = Arrangement.spacedBy(16.dp, Alignment.CenterVertically),
        horizontalAlignment = Alignment.CenterHorizontally,
    ) {
        Text(
            if (setting) "Set a researcher PIN" else "Researcher mode",
            style = MaterialTheme.typography.headlineSmall,
            modifier = Modifier.semantics { heading() },
        )
        Text(
            if (setting) "4 to 12 digits. Participants need it to leave a session, so keep it to yourself." else "Enter the PIN to open the researcher screen.",
            style = MaterialTheme.typography.bodyMedium,
        )
        PinField("PIN", pin) { pin = it }
        if (setting) PinField("Repeat PIN", confirm) { confirm = it }
        error?.let { ErrorText(it) }
        Button(
            onClick = {
                if (setting) onSetPin(pin, confirm) else onUnlock(pin)
                pin = ""
                confirm = ""
            },
            enabled = pin.isNotEmpty(),
        ) { Text(if (setting) "Set PIN" else "Unlock") }
    }
}

@Composable
private fun PinField(label: String, value: String, onChange: (String) -> Unit) {
    OutlinedTextField(
        value = value,
        onValueChange = { text -> onChange(text.filter(Char::isDigit).take(12)) },
        label = { Text(label) },
        singleLine = true,
        visualTransformation = PasswordVisualTransformation(),
        keyboardOptions = KeyboardOptions(keyboardType = KeyboardType.NumberPassword),
        modifier = Modifier.semantics { contentDescription = label },
    )
}

@Composable
internal fun ErrorText(message: String) {
    Text(
        message,
        color = MaterialTheme.colorScheme.error,
        style = MaterialTheme.typography.bodyMedium,
        modifier = Modifier.semantics { liveRegion = LiveRegionMode.Polite },
    )
}

/** What the participant's session screen can ask for. */
@Immutable
class SessionActions(
    val onStartTask: () -> Unit = {},
    val onPressIcon: () -> Unit = {},
    /** Plays a stimulus of a task that shows its icons together. */
    val onPressStimulus: (String) -> Unit = {},
    val onFinishExploring: () -> Unit = {},
    val onSelect: (Int) -> Unit = {},
    val onNext: () -> Unit = {},
    val onFinishTask: () -> Unit = {},
    /** Leaves the session with the researcher's PIN. */
    val onExit: (String) -> Unit = {},
)

/**
 * The participant's screens: task intro, for a task that shows its icons together the chat screen of all of them
 * (pressed freely, then on to the questions), trials (the partner's message as a chat bubble, the icon chip, the
 * statement and the rating scale), task end, done. The only way out is the "Researcher" button, which asks for the PIN.
 */
@Composable
fun SessionScreen(state: SessionUiState, actions: SessionActions, pinError: String?) {
    var asking by rememberSaveable { mutableStateOf(false) }
    Column(Modifier.fillMaxSize().padding(16.dp).verticalScroll(rememberScrollState()), verticalArrangement = Arrangement.spacedBy(16.dp)) {
        Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween, verticalAlignment = Alignment.CenterVertically) {
            Text((state as? SessionUiState.Active)?.participant.orEmpty(), style = MaterialTheme.typography.labelMedium)
            TextButton(onClick = { asking = true }, modifier = Modifier.semantics { contentDescription = "Researcher: leave the session with the PIN" }) {
                Text("Researcher")
            }
        }
        when (state) {
            SessionUiState.Loading -> CircularProgressIndicator(Modifier.semantics { contentDescription = "Loading the session" })
            is SessionUiState.Failed -> ErrorText(state.message)
            is SessionUiState.Active -> {
                LinearProgressIndicator(
                    progress = { if (state.trials == 0) 0f else state.answered.toFloat() / state.trials },
                    modifier = Modifier.fillMaxWidth().semantics { contentDescription = "Progress: ${state.answered} of ${state.trials} rated" },
                )
                when (val step = state.step) {
                    is StudyStep.TaskIntro -> StepText("Task ${step.taskPosition}: ${step.task.title}", step.task.instructions, "Start", actions.onStartTask)
                    is StudyStep.Explore -> ExploreContent(state, step, actions.onPressStimulus, actions.onFinishExploring)
                    is StudyStep.Trial -> TrialContent(state, step, actions.onPressIcon, actions.onSelect, actions.onNext)
                    is StudyStep.TaskEnd -> StepText("Task ${step.taskPosition} done", "Thank you. Take a short break if you like.", "Continue", actions.onFinishTask)
                    StudyStep.Done -> StepText("All done", "Thank you for taking part! Please hand the phone back to the researcher.", null) {}
                }
            }
        }
    }
    if (asking) {
        var pin by rememberSaveable { mutableStateOf("") }
        AlertDialog(
            onDismissRequest = { asking = false },
            title = { Text("Researcher PIN") },
            text = {
                Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
                    PinField("PIN", pin) { pin = it }
                    pinError?.let { ErrorText(it) }
                }
            },
            // A right PIN ends the session and this screen with it; a wrong one shows pinError here.
            confirmButton = { TextButton(onClick = { actions.onExit(pin); pin = "" }) { Text("Leave session") } },
            dismissButton = { TextButton(onClick = { asking = false }) { Text("Cancel") } },
        )
    }
}

@Composable
private fun StepText(title: String, body: String, button: String?, onClick: () -> Unit) {
    Text(title, style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
    if (body.isNotBlank()) Text(body, style = MaterialTheme.typography.bodyLarge)
    if (button != null) Button(onClick = onClick, modifier = Modifier.fillMaxWidth()) { Text(button) }
}

@Composable
private fun TrialContent(state: SessionUiState.Active, step: StudyStep.Trial, onPressIcon: () -> Unit, onSelect: (Int) -> Unit, onNext: () -> Unit) {
    Text("${step.task.title} · ${step.trial} of ${step.task.stimuli.size}", style = MaterialTheme.typography.titleMedium)
    PartnerMessage(step.stimulus, step.stimulus.number ?: step.trial, state.playing, state.iconPressed, onPressIcon)
    Text(step.question, style = MaterialTheme.typography.titleLarge)
    LikertScaleControl(state.scale, state.selected, onSelect)
    if (!state.iconPressed) Text("Press the haptic icon to feel it first.", style = MaterialTheme.typography.bodyMedium)
    Button(onClick = onNext, enabled = state.canContinue, modifier = Modifier.fillMaxWidth()) { Text("Next") }
}

/**
 * The paper's chat screen: every message of the task with its numbered icon, pressed freely; then on to the questions.
 */
@Composable
private fun ExploreContent(state: SessionUiState.Active, step: StudyStep.Explore, onPressStimulus: (String) -> Unit, onFinishExploring: () -> Unit) {
    Text("Task ${step.taskPosition}: ${step.task.title}", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
    Text(step.task.instructions, style = MaterialTheme.typography.bodyLarge)
    step.stimuli.forEachIndexed { i, stimulus ->
        PartnerMessage(stimulus, stimulus.number ?: (i + 1), playing = false, pressed = stimulus.id in state.pressedStimuli) { onPressStimulus(stimulus.id) }
    }
    Button(onClick = onFinishExploring, modifier = Modifier.fillMaxWidth()) { Text("Go to the questions") }
}

/** The virtual partner's message: a received chat bubble with its text and/or sticker, and the icon chip. */
@Composable
private fun PartnerMessage(stimulus: Stimulus, number: Int, playing: Boolean, pressed: Boolean, onPressIcon: () -> Unit) {
    Card(
        shape = RoundedCornerShape(topStart = 4.dp, topEnd = 16.dp, bottomEnd = 16.dp, bottomStart = 16.dp),
        colors = CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.secondaryContainer),
        modifier = Modifier.widthIn(max = 320.dp),
    ) {
        Column(Modifier.padding(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            Text("Partner", style = MaterialTheme.typography.labelMedium)
            stimulus.text?.let { Text(it, style = MaterialTheme.typography.bodyLarge) }
            stimulus.sticker?.let { id ->
                val sticker = stickerOf(id)
                if (sticker != null) {
                    Image(painterResource(sticker.drawable), contentDescription = "${sticker.label} sticker", modifier = Modifier.size(96.dp))
                } else {
                    Text("[$id]", style = MaterialTheme.typography.bodyLarge)
                }
            }
            AssistChip(
                onClick = onPressIcon,
                label = { Text("Haptic icon $number") },
                leadingIcon = { Icon(HapticonIcons.Vibration, contentDescription = null) },
                modifier = Modifier.semantics {
                    contentDescription = "Play haptic icon $number"
                    stateDescription = when {
                        playing -> "playing"
                        pressed -> "felt"
                        else -> "not felt yet"
                    }
                },
            )
        }
    }
}

/** The app's sticker for a protocol sticker id: `sticker_hug` or `hug`; null for one this build does not have. */
internal fun stickerOf(id: String): Sticker? = Sticker.of(id.removePrefix("sticker_"))

/**
 * A Likert item: one radio button per point (1..points) in a selectable group, each read as "N of points" with its
 * label when the scale has one per point. A label per point is written under each point; two anchors under the ends.
 */
@Composable
fun LikertScaleControl(scale: LikertScale, selected: Int?, onSelect: (Int) -> Unit, modifier: Modifier = Modifier) {
    Column(modifier.fillMaxWidth()) {
        Row(Modifier.fillMaxWidth().selectableGroup(), horizontalArrangement = Arrangement.SpaceBetween) {
            for (value in 1..scale.points) {
                val label = pointLabel(scale, value)
                Column(
                    Modifier
                        .weight(1f)
                        .selectable(selected = selected == value, onClick = { onSelect(value) }, role = Role.RadioButton)
                        .semantics { contentDescription = "$value of ${scale.points}" + (label?.let { ": $it" } ?: "") },
                    horizontalAlignment = Alignment.CenterHorizontally,
                ) {
                    RadioButton(selected = selected == value, onClick = null)
                    Text("$value", style = MaterialTheme.typography.labelLarge)
                    // A fully labelled scale shows every point's label under it, as the instrument was published
                    // (showing only the ends would put a different scale in front of the participant).
                    if (scale.labels.size == scale.points) {
                        Text(
                            scale.labels[value - 1],
                            style = MaterialTheme.typography.bodySmall,
                            textAlign = TextAlign.Center,
                            modifier = Modifier.padding(horizontal = 2.dp),
                        )
                    }
                }
            }
        }
        if (scale.labels.size == 2) {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
                Text(scale.labels.first(), style = MaterialTheme.typography.bodySmall, modifier = Modifier.weight(1f))
                Box(Modifier.weight(1f), contentAlignment = Alignment.CenterEnd) {
                    Text(scale.labels.last(), style = MaterialTheme.typography.bodySmall)
                }
            }
        }
    }
}

private fun pointLabel(scale: LikertScale, value: Int): String? = when (scale.labels.size) {
    scale.points -> scale.labels[value - 1]
    2 -> when (value) {
        1 -> scale.labels[0]
        scale.points -> scale.labels[1]
        else -> null
    }
    else -> null
}
