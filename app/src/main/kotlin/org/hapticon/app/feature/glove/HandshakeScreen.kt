package org.hapticon.app.feature.glove

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.LinearProgressIndicator
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.runtime.Immutable
import androidx.compose.material3.FilterChip
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.runtime.getValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import java.util.Locale
import org.hapticon.app.playback.VibrationOutput
import org.hapticon.app.sensors.CalibrationStore
import org.hapticon.app.sensors.HandshakeLink
import org.hapticon.sensor.glove.GloveSource
import org.hapticon.sensor.glove.PartnerHand
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.ui.LabeledValue
import org.hapticon.app.ui.SwitchRow

/**
 * The handshake view wired to its [HandshakeViewModel]: the [glove] and its [calibrations], the phone's [vibration],
 * a [simulatedPartner] for the toggle, and the chat's [link] that carries hands over the network.
 */
@Composable
fun HandshakeRoute(
    glove: GloveSource,
    calibrations: CalibrationStore,
    vibration: VibrationOutput,
    simulatedPartner: () -> PartnerHand,
    link: HandshakeLink,
    onBack: () -> Unit,
) {
    val viewModel: HandshakeViewModel = viewModel(
        factory = viewModelFactory {
            initializer { HandshakeViewModel(glove, calibrations, vibration, simulatedPartner(), link = link) }
        },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel, onBack) {
        HandshakeActions(
            onBack = onBack,
            onSimulatedPartner = viewModel::setSimulatedPartner,
            onVibration = viewModel::setVibration,
            onForceFeedback = viewModel::setForceFeedback,
            onNetworkPartner = viewModel::setNetworkPartner,
        )
    }
    HandshakeScreen(uiState, actions)
}

/** What the handshake screen can ask for. */
@Immutable
class HandshakeActions(
    val onBack: () -> Unit = {},
    val onSimulatedPartner: (Boolean) -> Unit = {},
    val onVibration: (Boolean) -> Unit = {},
    val onForceFeedback: (Boolean) -> Unit = {},
    /** Chooses the conversation whose hand is felt, or none. */
    val onNetworkPartner: (String?) -> Unit = {},
)

/** Live angles of both hands, whether the handshake is on, and the pressure on each hand region. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun HandshakeScreen(uiState: HandshakeUiState, actions: HandshakeActions) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("Handshake") },
                navigationIcon = { IconButton(onClick = actions.onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back") } },
            )
        },
    ) { padding ->
        when (uiState) {
            HandshakeUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) { CircularProgressIndicator() }
            is HandshakeUiState.Ready -> Column(
                Modifier.fillMaxSize().padding(padding).verticalScroll(rememberScrollState()).padding(16.dp),
                verticalArrangement = Arrangement.spacedBy(12.dp),
            ) {
                if (!uiState.connected) {
                    Card(colors = CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.surfaceVariant)) {
                        Text(
                            "No glove is streaming. Connect it on the Sensors screen first.",
                            modifier = Modifier.padding(12.dp),
                            style = MaterialTheme.typography.bodyMedium,
                        )
                    }
                }
                SwitchRow("Simulated partner", uiState.simulatedPartner, actions.onSimulatedPartner)
                NetworkPartners(uiState, actions.onNetworkPartner)
                SwitchRow("Phone vibration", uiState.vibrationEnabled, actions.onVibration)
                SwitchRow("Glove force feedback", uiState.forceFeedbackEnabled, actions.onForceFeedback)
                Text(forceFeedbackStatus(uiState), style = MaterialTheme.typography.bodySmall)
                val status = if (uiState.active) "Handshake active" else "No handshake"
                Card(
                    colors = if (uiState.active) {
                        CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.primaryContainer)
                    } else {
                        CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.surfaceVariant)
                    },
                    modifier = Modifier.fillMaxWidth().semantics { liveRegion = LiveRegionMode.Polite },
                ) {
                    Column(Modifier.padding(16.dp)) {
                        Text(status, style = MaterialTheme.typography.headlineSmall)
                        Text(
                            if (uiState.phoneAmplitude > 0) "Phone vibrates at ${uiState.phoneAmplitude}/255" else "Phone vibrator still",
                            style = MaterialTheme.typography.bodyMedium,
                        )
                    }
                }
                Hands(uiState)
                Text("Pressure per region", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
                for (region in uiState.regions) RegionRow(region)
                val calibration = when {
                    uiState.thumbCalibrated && uiState.middleCalibrated -> "Angles use ${uiState.user}'s calibration."
                    !uiState.thumbCalibrated && !uiState.middleCalibrated -> "Angles use the study's mean calibration: calibrate ${uiState.user}'s glove for accurate angles."
                    else -> "Angles use ${uiState.user}'s calibration where there is one, the study's mean otherwise."
                }
                Text(calibration, style = MaterialTheme.typography.bodySmall)
            }
        }
    }
}

@Composable
private fun Hands(state: HandshakeUiState.Ready) {
    Column(verticalArrangement = Arrangement.spacedBy(4.dp)) {
        Text("Angles", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
        // Label and angles side by side while both fit, else the angles whole under the label (font scale 2.0).
        LabeledValue(
            "You", "thumb ${angle(state.selfThumbDegrees, state.thumbFault)} · middle ${angle(state.selfMiddleDegrees, state.middleFault)}",
            labelStyle = MaterialTheme.typography.labelLarge,
        )
        LabeledValue(
            if (state.simulatedPartner) "Partner (simulated)" else "Partner",
            "thumb ${angle(state.partnerThumbDegrees, false)} · middle ${angle(state.partnerMiddleDegrees, false)}",
            labelStyle = MaterialTheme.typography.labelLarge,
        )
    }
}

@Composable
private fun RegionRow(region: RegionUi) {
    val name = region.region.label.replaceFirstChar { it.titlecase(Locale.ROOT) }
    val pressure = "%.2f V".format(Locale.ROOT, region.pressureVolts)
    Column(Modifier.fillMaxWidth().semantics(mergeDescendants = true) {}) {
        Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
            Text(name, style = MaterialTheme.typography.labelLarge)
            Text(pressure, style = MaterialTheme.typography.labelLarge)
        }
        LinearProgressIndicator(
            progress = { region.level },
            modifier = Modifier.fillMaxWidth().semantics {
                contentDescription = "$name pressure"
                stateDescription = pressure
            },
        )
    }
}

/** One chip per chat peer: pressing one shakes hands with them through the broker, pressing it again stops. */
@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun NetworkPartners(state: HandshakeUiState.Ready, onNetworkPartner: (String?) -> Unit) {
    Column(verticalArrangement = Arrangement.spacedBy(4.dp)) {
        Text("Partner over the network", style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
        if (state.peers.isEmpty()) {
            Text("Start a chat first: the people you chat with can shake hands with you.", style = MaterialTheme.typography.bodySmall)
        }
        FlowRow(horizontalArrangement = Arrangement.spacedBy(8.dp)) {
            for (peer in state.peers) {
                val selected = peer == state.networkPeer
                FilterChip(
                    selected = selected,
                    onClick = { onNetworkPartner(if (selected) null else peer) },
                    label = { Text(peer) },
                    modifier = Modifier.semantics { contentDescription = "Shake hands with $peer" },
                )
            }
        }
        state.networkPeer?.let { peer ->
            Text(
                if (state.networkPartnerLive) "$peer's hand is arriving" else "Waiting for $peer's hand (they open the handshake screen with you)",
                style = MaterialTheme.typography.bodySmall,
                modifier = Modifier.semantics { liveRegion = LiveRegionMode.Polite },
            )
        }
    }
}

/** What the force-feedback glove gets, in words. */
internal fun forceFeedbackStatus(state: HandshakeUiState.Ready): String = when {
    !state.forceFeedbackAvailable -> "Force feedback needs a LucidGloves glove streaming on the Sensors screen."
    !state.forceFeedbackEnabled -> "Force feedback off: the glove's servos are released."
    else -> "Servos thumb…pinky ${state.servoValues.joinToString(" · ")} of 1000 (${state.forceFeedbackCommands} commands sent)"
}

private fun angle(degrees: Double, fault: Boolean): String = if (fault) "fault" else "%.1f°".format(Locale.ROOT, degrees)
