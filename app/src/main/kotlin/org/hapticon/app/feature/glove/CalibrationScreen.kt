package org.hapticon.app.feature.glove

import androidx.compose.foundation.layout.Arrangement
import org.hapticon.app.ui.SegmentedChoice
import org.hapticon.app.ui.SingleChoice
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.LinearProgressIndicator
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.text.input.ImeAction
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import java.util.Locale
import org.hapticon.app.sensors.CalibrationStore
import org.hapticon.sensor.glove.GloveSource
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.sensors.SavedCalibration
import org.hapticon.sensor.glove.CalibrationState
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.SensorFault

/** The calibration flow wired to its [CalibrationViewModel]. */
@Composable
fun CalibrationRoute(glove: GloveSource, calibrations: CalibrationStore, onBack: () -> Unit) {
    val viewModel: CalibrationViewModel = viewModel(
        factory = viewModelFactory { initializer { CalibrationViewModel(glove, calibrations) } },
    )
    CalibrationRoute(viewModel, onBack)
}

/** The calibration flow for [viewModel]. */
@Composable
fun CalibrationRoute(viewModel: CalibrationViewModel, onBack: () -> Unit) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onBack) {
        CalibrationActions(
            onBack = onBack,
            onUserChange = viewModel::setUser,
            onSelectFinger = viewModel::selectFinger,
            onBeginPose = viewModel::beginPose,
            onRestart = viewModel::restart,
        )
    }
    CalibrationScreen(uiState, actions)
}

/** What the glove calibration screen can ask for. */
@Immutable
class CalibrationActions(
    val onBack: () -> Unit = {},
    val onUserChange: (String) -> Unit = {},
    val onSelectFinger: (GloveFinger) -> Unit = {},
    val onBeginPose: () -> Unit = {},
    val onRestart: () -> Unit = {},
)

/** Per finger: hold each pose until it settles, then see the fitted α, β and R², or why it failed. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun CalibrationScreen(uiState: CalibrationUiState, actions: CalibrationActions) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("Glove calibration") },
                navigationIcon = { IconButton(onClick = actions.onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back") } },
            )
        },
    ) { padding ->
        when (uiState) {
            CalibrationUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) { CircularProgressIndicator() }
            is CalibrationUiState.Ready -> Column(
                Modifier.fillMaxSize().padding(padding).verticalScroll(rememberScrollState()).padding(16.dp),
                verticalArrangement = Arrangement.spacedBy(16.dp),
            ) {
                OutlinedTextField(
                    value = uiState.userInput,
                    onValueChange = actions.onUserChange,
                    label = { Text("Participant") },
                    singleLine = true,
                    keyboardOptions = KeyboardOptions(imeAction = ImeAction.Done),
                    supportingText = { Text("Calibrations are saved per participant") },
                    modifier = Modifier.fillMaxWidth(),
                )
                SegmentedChoice(SingleChoice(GloveFinger.entries, uiState.finger, ::fingerName), actions.onSelectFinger)
                if (!uiState.connected) {
                    Card(colors = CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.surfaceVariant)) {
                        Text(
                            "No glove is streaming. Connect it on the Sensors screen and choose its thumb and middle-finger channels.",
                            modifier = Modifier.padding(12.dp),
                            style = MaterialTheme.typography.bodyMedium,
                        )
                    }
                }
                FlowStep(uiState, actions.onBeginPose, actions.onRestart)
                LiveSensor(uiState.live)
                SavedSection(uiState.user, uiState.saved)
            }
        }
    }
}

@Composable
private fun FlowStep(state: CalibrationUiState.Ready, onBeginPose: () -> Unit, onRestart: () -> Unit) {
    val finger = fingerName(state.finger).lowercase(Locale.ROOT)
    // Every pose is taken takesPerPose times, round by round, and averaged.
    val total = state.poses.size * state.takesPerPose
    val captured = when (val s = state.state) {
        is CalibrationState.WaitingForPose -> (s.take - 1) * state.poses.size + s.poseIndex
        is CalibrationState.Settling -> (s.take - 1) * state.poses.size + s.poseIndex
        is CalibrationState.Calibrated, is CalibrationState.Failed -> total
    }
    val round = { take: Int -> if (state.takesPerPose > 1) " (take $take of ${state.takesPerPose})" else "" }
    Card(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            Text("Takes captured: $captured of $total", style = MaterialTheme.typography.labelLarge)
            LinearProgressIndicator(
                progress = { captured.toFloat() / total },
                modifier = Modifier.fillMaxWidth().semantics {
                    contentDescription = "Calibration progress"
                    stateDescription = "$captured of $total takes captured"
                },
            )
            Column(Modifier.semantics(mergeDescendants = true) { liveRegion = LiveRegionMode.Polite }, verticalArrangement = Arrangement.spacedBy(8.dp)) {
                when (val s = state.state) {
                    is CalibrationState.WaitingForPose -> {
                        Text("Hold ${degrees(s.targetDegrees)}${round(s.take)}", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                        Text(
                            "Bend the $finger to ${degrees(s.targetDegrees)} and keep it still, then tap Start. " +
                                "The pose is captured once ${state.windowSamples} readings agree within ${"%.0f".format(Locale.ROOT, state.maxSpreadPercent)} %.",
                            style = MaterialTheme.typography.bodyMedium,
                        )
                    }
                    is CalibrationState.Settling -> {
                        Text("Settling at ${degrees(s.targetDegrees)}${round(s.take)}…", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                        Text("${s.windowFill} of ${state.windowSamples} steady readings", style = MaterialTheme.typography.bodyMedium)
                        s.relativeSpread?.let {
                            Text(
                                "Still moving: spread ${"%.1f".format(Locale.ROOT, it * 100)} % (needs ≤ ${"%.0f".format(Locale.ROOT, state.maxSpreadPercent)} %)",
                                style = MaterialTheme.typography.bodyMedium,
                            )
                        }
                        if (s.faults > 0) Text("${s.faults} sensor faults: the reading started over", color = MaterialTheme.colorScheme.error)
                    }
                    is CalibrationState.Calibrated -> {
                        Text("Calibrated", style = MaterialTheme.typography.headlineSmall, modifier = Modifier.semantics { heading() })
                        FitLines(s.fit.calibration, s.fit.rSquared, s.fit.rmsAngleErrorDegrees)
                        Text("Saved for ${state.user}", style = MaterialTheme.typography.bodySmall)
                    }
                    is CalibrationState.Failed -> {
                        Text("Calibration failed", style = MaterialTheme.typography.headlineSmall, color = MaterialTheme.colorScheme.error, modifier = Modifier.semantics { heading() })
                        Text(s.reason, style = MaterialTheme.typography.bodyMedium)
                    }
                }
            }
            Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
                when (val s = state.state) {
                    is CalibrationState.WaitingForPose ->
                        Button(onClick = onBeginPose, enabled = state.connected) { Text("Start ${degrees(s.targetDegrees)} pose") }
                    is CalibrationState.Settling -> Unit
                    is CalibrationState.Calibrated -> OutlinedButton(onClick = onRestart) { Text("Calibrate again") }
                    is CalibrationState.Failed -> Button(onClick = onRestart) { Text("Try again") }
                }
                if (state.state is CalibrationState.Settling || captured > 0) {
                    OutlinedButton(onClick = onRestart) { Text("Start over") }
                }
            }
        }
    }
}

@Composable
private fun FitLines(calibration: FlexCalibration, rSquared: Double, rmsDegrees: Double) {
    Text("α = ${"%.4f".format(Locale.ROOT, calibration.alphaPerDegree)} per degree", style = MaterialTheme.typography.bodyMedium)
    Text("β = ${"%.2f".format(Locale.ROOT, calibration.betaKiloohms)} kΩ", style = MaterialTheme.typography.bodyMedium)
    if (!rSquared.isNaN()) Text("R² = ${"%.4f".format(Locale.ROOT, rSquared)}", style = MaterialTheme.typography.bodyMedium)
    if (!rmsDegrees.isNaN()) Text("RMS angle error ${"%.2f".format(Locale.ROOT, rmsDegrees)}°", style = MaterialTheme.typography.bodyMedium)
}

@Composable
private fun LiveSensor(live: LiveReading) {
    val text = when {
        live.kiloohms != null -> "Sensor now: ${"%.1f".format(Locale.ROOT, live.kiloohms)} kΩ"
        live.fault != null -> "Sensor fault: ${faultText(live.fault)}"
        else -> "No reading yet"
    }
    Text(text, style = MaterialTheme.typography.bodyMedium)
}

@Composable
private fun SavedSection(user: String, saved: Map<GloveFinger, SavedCalibration?>) {
    Column(verticalArrangement = Arrangement.spacedBy(4.dp)) {
        Text("Calibrations of $user", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
        for (finger in GloveFinger.entries) {
            val s = saved[finger]
            val line = if (s == null) {
                val d = FlexCalibration.defaultFor(finger)
                "${fingerName(finger)}: not calibrated (study mean α ${"%.3f".format(Locale.ROOT, d.alphaPerDegree)}, β ${"%.2f".format(Locale.ROOT, d.betaKiloohms)} kΩ is used)"
            } else {
                "${fingerName(finger)}: α ${"%.4f".format(Locale.ROOT, s.calibration.alphaPerDegree)}, β ${"%.2f".format(Locale.ROOT, s.calibration.betaKiloohms)} kΩ, " +
                    "R² ${"%.4f".format(Locale.ROOT, s.rSquared)}"
            }
            Text(line, style = MaterialTheme.typography.bodySmall)
        }
    }
}

internal fun fingerName(finger: GloveFinger): String = when (finger) {
    GloveFinger.THUMB -> "Thumb"
    GloveFinger.MIDDLE -> "Middle finger"
}

private fun degrees(value: Double): String = if (value == Math.rint(value)) "${value.toLong()}°" else "%.1f°".format(Locale.ROOT, value)

private fun faultText(fault: SensorFault): String = when (fault) {
    SensorFault.NOT_A_NUMBER -> "no valid value on this channel"
    SensorFault.SHORT_CIRCUIT -> "short circuit"
    SensorFault.OPEN_CIRCUIT -> "open circuit (sensor unplugged?)"
    SensorFault.COUNT_OUT_OF_RANGE -> "ADC count out of range"
}
