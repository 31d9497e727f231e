package org.hapticon.app.feature.sensors

import org.hapticon.sensor.glove.GloveChannels
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.protocol.SensorProtocol
import androidx.activity.compose.BackHandler
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.items
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.sensor.glove.SessionGloveSource
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.live.UsbDevices
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.sensor.grains.BinDistribution

/** The screens inside the Sensors destination. */
private enum class SensorsPane { STREAM, CALIBRATION, HANDSHAKE, ELECTROTACTILE }

/**
 * The Sensors destination: the stream screen, and the screens opened from it (Back returns). The glove screens
 * belong to the glove feature: the app's navigation hands them in as [gloveCalibration] and [handshake].
 */
@Composable
fun SensorsRoute(
    usbDevices: UsbDevices,
    session: SensorSession,
    grainEngine: GrainEngine,
    glove: SessionGloveSource,
    stimulator: StimulatorLink,
    gloveCalibration: @Composable (onBack: () -> Unit) -> Unit,
    handshake: @Composable (onBack: () -> Unit) -> Unit,
) {
    var pane by rememberSaveable { mutableStateOf(SensorsPane.STREAM) }
    BackHandler(enabled = pane != SensorsPane.STREAM) { pane = SensorsPane.STREAM }
    val back = { pane = SensorsPane.STREAM }
    when (pane) {
        SensorsPane.STREAM -> {
            val viewModel: SensorsViewModel = viewModel(
                factory = viewModelFactory {
                    initializer { SensorsViewModel(usbDevices, session, grainEngine, glove) }
                },
            )
            SensorsRoute(
                viewModel,
                onOpenCalibration = { pane = SensorsPane.CALIBRATION },
                onOpenHandshake = { pane = SensorsPane.HANDSHAKE },
                onOpenElectrotactile = { pane = SensorsPane.ELECTROTACTILE },
            )
        }
        SensorsPane.CALIBRATION -> gloveCalibration(back)
        SensorsPane.HANDSHAKE -> handshake(back)
        SensorsPane.ELECTROTACTILE -> ElectrotactileCalibrationRoute(stimulator, onBack = back)
    }
}

/** The stream screen wired to [viewModel]. */
@Composable
fun SensorsRoute(viewModel: SensorsViewModel, onOpenCalibration: () -> Unit, onOpenHandshake: () -> Unit, onOpenElectrotactile: () -> Unit = {}) {
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val actions = remember(viewModel) {
        SensorsActions(
            onSelectDevice = viewModel::selectDevice,
            onSelectProtocol = viewModel::selectProtocol,
            onSelectBaudRate = viewModel::selectBaudRate,
            onConnect = viewModel::connect,
            onDisconnect = viewModel::disconnect,
            onGrainsEnabled = viewModel::setGrainsEnabled,
            onGrainChannel = viewModel::setGrainChannel,
            onForceInput = viewModel::setForceInput,
            onGrainCount = viewModel::setGrainCount,
            onDistribution = viewModel::setDistribution,
            onGrainAmplitude = viewModel::setGrainAmplitude,
            onFallbackSampleRate = viewModel::setFallbackSampleRate,
            onGloveChannels = viewModel::setGloveChannels,
            onOpenCalibration = onOpenCalibration,
            onOpenHandshake = onOpenHandshake,
            onOpenElectrotactile = onOpenElectrotactile,
        )
    }
    SensorsScreen(uiState, actions)
}

/** What the Sensors screen can ask for. */
@Immutable
class SensorsActions(
    val onSelectDevice: (String) -> Unit = {},
    val onSelectProtocol: (SensorProtocol) -> Unit = {},
    val onSelectBaudRate: (Int) -> Unit = {},
    val onConnect: () -> Unit = {},
    val onDisconnect: () -> Unit = {},
    val onGrainsEnabled: (Boolean) -> Unit = {},
    val onGrainChannel: (Int) -> Unit = {},
    val onForceInput: (ForceInput?) -> Unit = {},
    val onGrainCount: (Int) -> Unit = {},
    val onDistribution: (BinDistribution) -> Unit = {},
    val onGrainAmplitude: (Int) -> Unit = {},
    val onFallbackSampleRate: (Int) -> Unit = {},
    val onGloveChannels: (GloveChannels) -> Unit = {},
    val onOpenCalibration: () -> Unit = {},
    val onOpenHandshake: () -> Unit = {},
    val onOpenElectrotactile: () -> Unit = {},
)

/** Boards, connection, live channels, counters, FSR grains, the glove and the electrotactile array. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun SensorsScreen(uiState: SensorsUiState, actions: SensorsActions) {
    Scaffold(topBar = { TopAppBar(title = { Text("Sensors") }) }) { padding ->
        when (uiState) {
            SensorsUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) { CircularProgressIndicator() }
            SensorsUiState.NoUsbHost -> NoUsbHost(Modifier.padding(padding))
            is SensorsUiState.Ready -> LazyColumn(
                contentPadding = PaddingValues(16.dp),
                verticalArrangement = Arrangement.spacedBy(16.dp),
                modifier = Modifier.fillMaxSize().padding(padding),
            ) {
                item(key = "devices") { DevicesSection(uiState, actions) }
                item(key = "connection") { ConnectionSection(uiState, actions) }
                val stream = uiState.stream
                if (stream != null) {
                    item(key = "channels-title") { SectionTitle("Live channels") }
                    items(stream.channels, key = { "channel-${it.index}" }) { channel -> ChannelRow(channel, stream) }
                    item(key = "stats") { StatsSection(stream) }
                }
                item(key = "grains") { GrainsSection(uiState.grains, actions) }
                item(key = "glove") { GloveSection(uiState.glove, actions) }
                item(key = "electrotactile") { ElectrotactileSection(actions) }
            }
        }
    }
}

@Composable
private fun NoUsbHost(modifier: Modifier) {
    Column(modifier.fillMaxSize().padding(24.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        Icon(HapticonIcons.Usb, contentDescription = null, tint = MaterialTheme.colorScheme.onSurfaceVariant)
        Text("This phone can't host USB devices", style = MaterialTheme.typography.titleLarge, modifier = Modifier.semantics { heading() })
        Text(
            "Sensor boards (flex-sensor gloves, force-feedback gloves, FSR boards) plug into the phone through " +
                "USB OTG, and this phone does not support USB host mode. Use a phone with USB OTG to stream sensors; " +
                "haptic icons still play on this phone's vibrator.",
            style = MaterialTheme.typography.bodyMedium,
        )
    }
}

@Composable
internal fun SectionTitle(text: String) {
    Text(text, style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
}
