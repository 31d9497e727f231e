package org.hapticon.app.feature.sensors

import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.foundation.border
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.heightIn
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.remember
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.text.style.TextAlign
import androidx.compose.foundation.selection.selectable
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import java.util.Locale
import org.hapticon.app.designsystem.HapticonIcons
import androidx.lifecycle.viewmodel.viewModelFactory
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.compose.viewModel
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.data.ElectrodeLevelsStore
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.electrotactile.StoredCalibration

/**
 * The electrotactile calibration over [stimulator], its levels stored in the app's files. [key] names the
 * calibration's ViewModel: a new key starts a fresh calibration (the compliance study's rounds).
 */
@Composable
fun ElectrotactileCalibrationRoute(stimulator: StimulatorLink, onBack: () -> Unit, key: String? = null) {
    val files = LocalContext.current.filesDir
    val viewModel: ElectrotactileCalibrationViewModel = viewModel(
        key = key,
        factory = viewModelFactory { initializer { ElectrotactileCalibrationViewModel(stimulator, ElectrodeLevelsStore.inFolder(files)) } },
    )
    ElectrotactileCalibrationRoute(viewModel, onBack)
}

/**
 * The electrotactile calibration wired to [viewModel]; [onBack] returns to the Sensors screen. Export and import go
 * through the system's document picker (Storage Access Framework: ACTION_CREATE_DOCUMENT / ACTION_OPEN_DOCUMENT), so
 * the file can live in Downloads, a USB stick or a cloud folder and the app needs no storage permission.
 */
@Composable
fun ElectrotactileCalibrationRoute(viewModel: ElectrotactileCalibrationViewModel, onBack: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val stored by viewModel.storedCalibration.collectAsStateWithLifecycle()
    val resolver = LocalContext.current.contentResolver
    val exportFile = rememberLauncherForActivityResult(ActivityResultContracts.CreateDocument(CALIBRATION_MIME_TYPE)) { uri ->
        if (uri != null) viewModel.exportTo { resolver.openOutputStream(uri, "wt") }
    }
    // Any type: a file shared from a laptop or a chat often arrives as text/plain or application/octet-stream.
    val importFile = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        if (uri != null) viewModel.importFrom { resolver.openInputStream(uri) }
    }
    val actions = remember(viewModel, onBack, exportFile, importFile) {
        ElectrotactileActions(
            onGiveStimulus = viewModel::giveStimulus,
            onNotYet = viewModel::notYet,
            onClearAndPainFree = viewModel::clearAndPainFree,
            onTooStrong = viewModel::tooStrong,
            onSendWholeArrayCheck = viewModel::sendWholeArrayCheck,
            onWholeArrayOk = viewModel::wholeArrayOk,
            onSelectElectrode = viewModel::selectElectrode,
            onWeaker = viewModel::weaker,
            onStronger = viewModel::stronger,
            onRestart = viewModel::restart,
            onBack = onBack,
            onExport = { exportFile.launch(CALIBRATION_FILE_NAME) },
            onImport = { importFile.launch(arrayOf("*/*")) },
        )
    }
    ElectrotactileCalibrationScreen(uiState, actions, stored)
}

/** The type the export declares: the calibration file is JSON. */
private const val CALIBRATION_MIME_TYPE = "application/json"

/** The name the export suggests, as `hapticon board calibrate --save` examples use. */
private const val CALIBRATION_FILE_NAME = "electrotactile-calibration.json"

/** What the electrotactile calibration screen can ask for. */
@Immutable
class ElectrotactileActions(
    val onGiveStimulus: () -> Unit = {},
    val onNotYet: () -> Unit = {},
    val onClearAndPainFree: () -> Unit = {},
    val onTooStrong: () -> Unit = {},
    val onSendWholeArrayCheck: () -> Unit = {},
    val onWholeArrayOk: () -> Unit = {},
    /** Whole-array check: the electrode the person says stands out (0..8). */
    val onSelectElectrode: (Int) -> Unit = {},
    /** Whole-array check: the selected electrode a step weaker. */
    val onWeaker: () -> Unit = {},
    /** Whole-array check: the selected electrode a step stronger. */
    val onStronger: () -> Unit = {},
    val onRestart: () -> Unit = {},
    val onBack: () -> Unit = {},
    /** Save the stored calibration to a file the researcher picks. */
    val onExport: () -> Unit = {},
    /** Read a calibration file the researcher picks (from `hapticon board calibrate --save` or another phone). */
    val onImport: () -> Unit = {},
)

/**
 * Shaping Compliance's calibration, step by step: the 3×3 array with each electrode's current, the electrode
 * being calibrated and its next stimulus, then the whole-array check, then the person's limit.
 */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun ElectrotactileCalibrationScreen(uiState: ElectrotactileUiState, actions: ElectrotactileActions, stored: StoredCalibration? = null) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("Electrotactile calibration") },
                navigationIcon = { IconButton(onClick = actions.onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back") } },
            )
        },
    ) { padding ->
        Column(
            Modifier.fillMaxSize().padding(padding).verticalScroll(rememberScrollState()).padding(16.dp),
            verticalArrangement = Arrangement.spacedBy(16.dp),
        ) {
            Text(
                "Each electrode in turn: a ${ElectrotactileCalibration.STIMULUS_MILLIS} ms stimulus from " +
                    "${mA(AmplitudeSteps.milliampsOf(ElectrotactileCalibration.START_STEP))}, one step (13.5 µA) stronger until it is " +
                    "clear and pain-free; then all nine while pressing (${ElectrotactileCalibration.CHECK_GRAINS} grains). " +
                    "${mA(AmplitudeSteps.milliampsOf(AmplitudeSteps.STEPS))} is the hard cap.",
                style = MaterialTheme.typography.bodyMedium,
            )
            ElectrodeGrid(uiState, actions.onSelectElectrode)
            when (uiState) {
                is ElectrotactileUiState.Electrode -> ElectrodeStep(uiState, actions)
                is ElectrotactileUiState.WholeArrayCheck -> WholeArrayStep(uiState, actions)
                is ElectrotactileUiState.Done -> DoneStep(uiState, actions)
            }
            uiState.message?.let { message ->
                // A board's refusal must be seen, not only logged: the error colours, and read out at once.
                Card(
                    colors = if (uiState.problem) {
                        CardDefaults.cardColors(
                            containerColor = MaterialTheme.colorScheme.errorContainer,
                            contentColor = MaterialTheme.colorScheme.onErrorContainer,
                        )
                    } else {
                        CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.surfaceVariant)
                    },
                    modifier = Modifier.fillMaxWidth().semantics { liveRegion = if (uiState.problem) LiveRegionMode.Assertive else LiveRegionMode.Polite },
                ) {
                    if (uiState.problem) {
                        // Not by colour alone: the warning sign says "error" in greyscale and to colour-blind eyes too.
                        Row(Modifier.padding(12.dp), horizontalArrangement = Arrangement.spacedBy(8.dp)) {
                            Icon(HapticonIcons.Warning, contentDescription = null)
                            Text(message, style = MaterialTheme.typography.bodyMedium)
                        }
                    } else {
                        Text(message, Modifier.padding(12.dp), style = MaterialTheme.typography.bodyMedium)
                    }
                }
            }
            StoredCalibrationSection(stored, actions)
        }
    }
}

/**
 * What the compliance study will use, and the way to move it: export to a file, or import one made with
 * `hapticon board calibrate --save` on a laptop or exported from another phone.
 */
@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun StoredCalibrationSection(stored: StoredCalibration?, actions: ElectrotactileActions) {
    Text("Stored calibration", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
    Text(
        stored?.let { "The compliance study uses ${ElectrodeLevelsStore.describe(it)}." }
            ?: "None yet: the compliance study needs a finished calibration, or one imported from a file.",
        style = MaterialTheme.typography.bodyMedium,
    )
    FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        OutlinedButton(onClick = actions.onExport, enabled = stored != null) { Text("Export file") }
        OutlinedButton(onClick = actions.onImport) { Text("Import file") }
    }
}

/**
 * The 3×3 array, row by row as the electrodes are numbered: each cell shows its current; the one being calibrated (or, in
 * the whole-array check, the one selected) is outlined. In the check each cell is a button that selects its electrode.
 */
@Composable
private fun ElectrodeGrid(uiState: ElectrotactileUiState, onSelect: (Int) -> Unit) {
    val check = uiState as? ElectrotactileUiState.WholeArrayCheck
    val current = (uiState as? ElectrotactileUiState.Electrode)?.electrode ?: check?.selected
    val size = ElectrodePattern.SIZE
    Column(verticalArrangement = Arrangement.spacedBy(6.dp), modifier = if (check == null) Modifier.semantics(mergeDescendants = true) {} else Modifier) {
        for (row in 0 until size) {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.spacedBy(6.dp)) {
                for (column in 0 until size) {
                    val e = row * size + column
                    val step = uiState.steps[e]
                    val active = e == current
                    val pending = check == null && current != null && e > current
                    Box(
                        // Grows with the font: the current must stay readable at the largest text size.
                        Modifier
                            .weight(1f)
                            .heightIn(min = 56.dp)
                            .background(
                                if (active) MaterialTheme.colorScheme.primaryContainer else MaterialTheme.colorScheme.surfaceVariant,
                                MaterialTheme.shapes.small,
                            )
                            .then(if (active) Modifier.border(2.dp, MaterialTheme.colorScheme.primary, MaterialTheme.shapes.small) else Modifier)
                            .then(if (check != null) Modifier.selectable(active, role = Role.RadioButton, onClick = { onSelect(e) }) else Modifier)
                            .semantics { contentDescription = "Electrode ${e + 1}: ${if (pending) "not yet calibrated" else mA(AmplitudeSteps.milliampsOf(step))}" },
                        contentAlignment = Alignment.Center,
                    ) {
                        // A 4 dp margin keeps the current off the cell's edge; too wide for it, "mA" goes to a second line.
                        Column(Modifier.padding(vertical = 6.dp, horizontal = 4.dp), horizontalAlignment = Alignment.CenterHorizontally) {
                            Text("${e + 1}", style = MaterialTheme.typography.labelSmall)
                            Text(
                                if (pending) "—" else mA(AmplitudeSteps.milliampsOf(step)),
                                style = MaterialTheme.typography.labelLarge, textAlign = TextAlign.Center,
                            )
                        }
                    }
                }
            }
        }
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun ElectrodeStep(state: ElectrotactileUiState.Electrode, actions: ElectrotactileActions) {
    val row = state.electrode / ElectrodePattern.SIZE + 1
    val column = state.electrode % ElectrodePattern.SIZE + 1
    Text(
        "Electrode ${state.electrode + 1} of ${ElectrotactileCalibration.ELECTRODES} (row $row, column $column)",
        style = MaterialTheme.typography.titleMedium,
        modifier = Modifier.semantics { heading() },
    )
    Text(
        String.format(Locale.ROOT, "Next stimulus: %s, step %d of %d, %d ms", mA(state.milliamps), state.step, AmplitudeSteps.STEPS, ElectrotactileCalibration.STIMULUS_MILLIS),
        style = MaterialTheme.typography.bodyLarge,
    )
    if (!state.boardReady) Text("No framed board is streaming: connect one on the Sensors screen to give the stimulus.", style = MaterialTheme.typography.bodySmall)
    Button(onClick = actions.onGiveStimulus, enabled = state.boardReady) { Text("Give stimulus") }
    if (state.atCap) Text("At the 2.7 mA cap: it cannot go higher.", color = MaterialTheme.colorScheme.error, style = MaterialTheme.typography.bodyMedium)
    FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        OutlinedButton(onClick = actions.onNotYet, enabled = !state.atCap) { Text("Not yet: stronger") }
        OutlinedButton(onClick = actions.onTooStrong, enabled = state.step > 0) { Text("Too strong") }
        Button(onClick = actions.onClearAndPainFree) { Text("Clear and pain-free") }
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun WholeArrayStep(state: ElectrotactileUiState.WholeArrayCheck, actions: ElectrotactileActions) {
    Text("Whole-array check", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
    Text(
        "All nine electrodes at their levels, ${ElectrotactileCalibration.CHECK_GRAINS} grains over a full press. Send it to the board " +
            "and ask the person to press until it feels pain-free and uniform over the whole area: tap the electrode that stands out " +
            "and make it weaker or stronger, or lower all while it is too strong.",
        style = MaterialTheme.typography.bodyMedium,
    )
    if (!state.boardReady) Text("No framed board is streaming: connect one on the Sensors screen.", style = MaterialTheme.typography.bodySmall)
    val selected = state.selected
    FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        OutlinedButton(onClick = actions.onWeaker, enabled = selected != null) { Text(selected?.let { "Electrode ${it + 1} weaker" } ?: "Tap an electrode to adjust it") }
        if (selected != null) OutlinedButton(onClick = actions.onStronger, enabled = state.steps[selected] < AmplitudeSteps.STEPS) { Text("Electrode ${selected + 1} stronger") }
    }
    FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
        Button(onClick = actions.onSendWholeArrayCheck, enabled = state.boardReady) { Text(if (state.sent) "Send again" else "Send to board") }
        OutlinedButton(onClick = actions.onTooStrong) { Text("Too strong: all weaker") }
        Button(onClick = actions.onWholeArrayOk) { Text("Uniform and pain-free") }
    }
}

@Composable
private fun DoneStep(state: ElectrotactileUiState.Done, actions: ElectrotactileActions) {
    Text("Calibrated", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
    Text(
        state.limitMilliamps?.let { "This person's limit: ${mA(it)} (the highest electrode). Stimulation above it is refused." }
            ?: "Every electrode was lowered to 0 mA: no electrotactile stimulation for this person.",
        style = MaterialTheme.typography.bodyLarge,
    )
    OutlinedButton(onClick = actions.onRestart) { Text("Start again") }
}

private fun mA(milliamps: Double): String = String.format(Locale.ROOT, "%.3f mA", milliamps)
