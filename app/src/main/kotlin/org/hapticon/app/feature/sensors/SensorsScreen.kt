package org.hapticon.app.feature.sensors

import androidx.activity.compose.BackHandler
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.items
import androidx.compose.foundation.selection.selectable
import androidx.compose.foundation.selection.selectableGroup
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.RadioButton
import androidx.compose.material3.Scaffold
import androidx.compose.material3.SegmentedButton
import androidx.compose.material3.SegmentedButtonDefaults
import androidx.compose.material3.SingleChoiceSegmentedButtonRow
import androidx.compose.material3.Slider
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
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.Role
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
import kotlin.math.roundToInt
import org.hapticon.app.AppContainer
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.feature.glove.CalibrationRoute
import org.hapticon.app.feature.glove.HandshakeRoute
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.LabeledValue
import org.hapticon.app.ui.SwitchRow
import org.hapticon.sensor.glove.GloveChannels
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.live.ConnectionState
import org.hapticon.sensor.live.StopCause
import org.hapticon.sensor.protocol.BAUD_RATES
import org.hapticon.sensor.protocol.SensorProtocol

/** The screens inside the Sensors destination. */
private enum class SensorsPane { STREAM, CALIBRATION, HANDSHAKE }

/** The Sensors destination: the stream screen, and the glove screens opened from it (Back returns). */
@Composable
fun SensorsRoute(container: AppContainer) {
    var pane by rememberSaveable { mutableStateOf(SensorsPane.STREAM) }
    BackHandler(enabled = pane != SensorsPane.STREAM) { pane = SensorsPane.STREAM }
    when (pane) {
        SensorsPane.STREAM -> {
            val viewModel: SensorsViewModel = viewModel(
                factory = viewModelFactory {
                    initializer { SensorsViewModel(container.usbDevices, container.sensorHub, container.grainEngine, container.glove) }
                },
            )
            SensorsRoute(
                viewModel,
                onOpenCalibration = { pane = SensorsPane.CALIBRATION },
                onOpenHandshake = { pane = SensorsPane.HANDSHAKE },
            )
        }
        SensorsPane.CALIBRATION -> CalibrationRoute(container, onBack = { pane = SensorsPane.STREAM })
        SensorsPane.HANDSHAKE -> HandshakeRoute(container, onBack = { pane = SensorsPane.STREAM })
    }
}

/** The stream screen wired to [viewModel]. */
@Composable
fun SensorsRoute(viewModel: SensorsViewModel, onOpenCalibration: () -> Unit, onOpenHandshake: () -> Unit) {
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
)

/** Boards, connection, live channels, counters, FSR grains and the glove. */
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
private fun SectionTitle(text: String) {
    Text(text, style = MaterialTheme.typography.titleMedium, modifier = Modifier.semantics { heading() })
}

@Composable
private fun DevicesSection(state: SensorsUiState.Ready, actions: SensorsActions) {
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        SectionTitle("USB boards")
        if (state.devices.isEmpty()) {
            Text(
                "No USB serial board plugged in. Connect a board with a USB OTG adapter; Android then offers to open Hapticon.",
                style = MaterialTheme.typography.bodyMedium,
            )
        }
        Column(Modifier.selectableGroup(), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            for (device in state.devices) {
                val selected = device.id == state.selectedDeviceId
                Card(
                    colors = if (selected) CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.secondaryContainer) else CardDefaults.cardColors(),
                    modifier = Modifier
                        .fillMaxWidth()
                        .selectable(selected = selected, role = Role.RadioButton, onClick = { actions.onSelectDevice(device.id) }),
                ) {
                    Row(Modifier.padding(12.dp), verticalAlignment = Alignment.CenterVertically) {
                        RadioButton(selected = selected, onClick = null)
                        Column(Modifier.padding(start = 12.dp)) {
                            Text(device.productName ?: "USB serial board", style = MaterialTheme.typography.titleSmall)
                            Text("${device.chipFamily} · ${device.usbIds}", style = MaterialTheme.typography.bodySmall)
                        }
                    }
                }
            }
        }
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun ConnectionSection(state: SensorsUiState.Ready, actions: SensorsActions) {
    val locked = !state.canConnect && state.canDisconnect
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        SectionTitle("Connection")
        Text("Protocol", style = MaterialTheme.typography.labelMedium)
        val protocols = SensorProtocol.entries
        SingleChoiceSegmentedButtonRow(Modifier.fillMaxWidth()) {
            protocols.forEachIndexed { i, protocol ->
                SegmentedButton(
                    selected = protocol == state.protocol,
                    onClick = { actions.onSelectProtocol(protocol) },
                    enabled = !locked,
                    shape = SegmentedButtonDefaults.itemShape(i, protocols.size),
                    label = { Text(protocol.label) },
                )
            }
        }
        FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            DropdownField(
                label = "Baud rate",
                options = BAUD_RATES,
                selected = state.baudRate,
                optionLabel = { "$it baud" },
                onSelect = actions.onSelectBaudRate,
                enabled = !locked,
            )
        }
        Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            Button(onClick = actions.onConnect, enabled = state.canConnect) { Text("Connect") }
            OutlinedButton(onClick = actions.onDisconnect, enabled = state.canDisconnect) { Text("Disconnect") }
        }
        ConnectionStatus(state.connection, state.stream?.counters?.frames ?: 0)
    }
}

@Composable
private fun ConnectionStatus(connection: ConnectionState, frames: Long) {
    val (text, isError) = when (connection) {
        ConnectionState.Idle -> return
        is ConnectionState.RequestingPermission -> "Waiting for USB permission for ${connection.device.usbIds}…" to false
        is ConnectionState.Opening -> "Opening ${connection.device.chipFamily} board ${connection.device.usbIds}…" to false
        is ConnectionState.Streaming -> "Streaming ${connection.protocol.label} from ${connection.device.usbIds} at ${connection.baudRate} baud" to false
        is ConnectionState.PermissionDenied ->
            "USB permission denied for ${connection.device.usbIds}. Hapticon can't read the board unless you allow access; " +
                "tap Connect to ask again." to true
        is ConnectionState.Failed -> "Could not open ${connection.device.usbIds}: ${connection.message}" to true
        is ConnectionState.Stopped -> when (connection.cause) {
            StopCause.UNPLUGGED -> "Board unplugged. The $frames frames received before are kept below." to true
            StopCause.ENDED -> "Stream ended after $frames frames." to false
            StopCause.FAILED -> "Reading failed: ${connection.message}. The $frames frames received before are kept below." to true
            StopCause.BY_USER -> "Disconnected. The $frames frames received are kept below." to false
        }
    }
    Card(
        colors = if (isError) {
            CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.errorContainer, contentColor = MaterialTheme.colorScheme.onErrorContainer)
        } else {
            CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.surfaceVariant)
        },
        modifier = Modifier.fillMaxWidth().semantics { liveRegion = LiveRegionMode.Polite },
    ) {
        Row(Modifier.padding(12.dp), verticalAlignment = Alignment.CenterVertically, horizontalArrangement = Arrangement.spacedBy(12.dp)) {
            if (isError) Icon(HapticonIcons.Warning, contentDescription = null)
            Text(text, style = MaterialTheme.typography.bodyMedium)
        }
    }
}

@Composable
private fun ChannelRow(channel: ChannelUi, stream: StreamUi) {
    Column(Modifier.fillMaxWidth()) {
        Row(
            Modifier.fillMaxWidth().semantics(mergeDescendants = true) {},
            horizontalArrangement = Arrangement.SpaceBetween,
        ) {
            Text(channel.name, style = MaterialTheme.typography.labelLarge)
            Text(channel.valueText, style = MaterialTheme.typography.labelLarge)
        }
        if (channel.plotted) LivePlot(stream.plot, channel.index, stream.samples, label = channel.name)
    }
}

@Composable
private fun StatsSection(stream: StreamUi) {
    val c = stream.counters
    Column(verticalArrangement = Arrangement.spacedBy(4.dp)) {
        SectionTitle("Stream statistics")
        stream.deviceDescription?.let { Text(it, style = MaterialTheme.typography.bodySmall) }
        LabeledValue("Frames", c.frames.toString())
        LabeledValue("Bad frames", c.badFrames.toString())
        LabeledValue("Dropped bytes", c.droppedBytes.toString())
        if (c.truncatedFrames > 0) LabeledValue("Cut off by the end of the stream", c.truncatedFrames.toString())
        if (c.sequenceGaps > 0 || c.lostFrames > 0) {
            LabeledValue("Sequence gaps", c.sequenceGaps.toString())
            LabeledValue("Lost frames", c.lostFrames.toString())
        }
        LabeledValue("Bytes", c.bytes.toString())
        stream.measuredRateHz?.let { LabeledValue("Rate", "%.0f frames/s".format(Locale.ROOT, it)) }
        stream.outputError?.let { Text("Output stopped: $it", color = MaterialTheme.colorScheme.error, style = MaterialTheme.typography.bodySmall) }
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun GrainsSection(grains: GrainUi, actions: SensorsActions) {
    Card(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            SwitchRow("FSR grains", grains.enabled, actions.onGrainsEnabled)
            Text(
                "Plays a short burst on the phone's vibrator each time the pressed force crosses into another bin.",
                style = MaterialTheme.typography.bodySmall,
            )
            FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                val channels = grains.channelNames.indices.toList().ifEmpty { listOf(grains.channel) }
                DropdownField(
                    label = "Force channel",
                    options = channels,
                    selected = grains.channel,
                    optionLabel = { grains.channelNames.getOrNull(it) ?: "ch$it" },
                    onSelect = actions.onGrainChannel,
                )
                DropdownField(
                    label = "Force reads as",
                    options = listOf<ForceInput?>(null) + ForceInput.entries,
                    selected = grains.input,
                    optionLabel = { it?.label ?: "Automatic" },
                    onSelect = actions.onForceInput,
                )
                if (grains.deviceSampleRateHz == null) {
                    DropdownField(
                        label = "Sample rate",
                        options = SAMPLE_RATES,
                        selected = grains.fallbackSampleRateHz,
                        optionLabel = { "$it Hz" },
                        onSelect = actions.onFallbackSampleRate,
                    )
                }
            }
            grains.deviceSampleRateHz?.let { Text("Sample rate from the board: $it Hz", style = MaterialTheme.typography.bodySmall) }
            // Shaping Compliance: grains = bins − 1, so a full press fires exactly this many grains.
            Text("Grains per full press: ${grains.count} (${grains.count + 1} force bins)", style = MaterialTheme.typography.labelMedium)
            Slider(
                value = grains.count.toFloat(),
                onValueChange = { actions.onGrainCount(it.roundToInt()) },
                valueRange = GrainSettings.STUDY_MIN_GRAIN_COUNT.toFloat()..GrainSettings.STUDY_MAX_GRAIN_COUNT.toFloat(),
                steps = GrainSettings.STUDY_MAX_GRAIN_COUNT - GrainSettings.STUDY_MIN_GRAIN_COUNT - 1,
                modifier = Modifier.semantics {
                    contentDescription = "Grain count"
                    stateDescription = "${grains.count} grains"
                },
            )
            Text("Distribution", style = MaterialTheme.typography.labelMedium)
            val distributions = BinDistribution.entries
            SingleChoiceSegmentedButtonRow(Modifier.fillMaxWidth()) {
                distributions.forEachIndexed { i, distribution ->
                    SegmentedButton(
                        selected = distribution == grains.distribution,
                        onClick = { actions.onDistribution(distribution) },
                        shape = SegmentedButtonDefaults.itemShape(i, distributions.size),
                        label = { Text(distribution.name.lowercase().replaceFirstChar { it.titlecase(Locale.ROOT) }) },
                    )
                }
            }
            Text("Burst strength: ${(grains.amplitude * 100 / 255)} %", style = MaterialTheme.typography.labelMedium)
            Slider(
                value = grains.amplitude.toFloat(),
                onValueChange = { actions.onGrainAmplitude(it.roundToInt()) },
                valueRange = 1f..255f,
                modifier = Modifier.semantics {
                    contentDescription = "Burst strength"
                    stateDescription = "${grains.amplitude * 100 / 255} percent"
                },
            )
            if (grains.enabled) Text("Grains played: ${grains.grainsPlayed}", style = MaterialTheme.typography.bodyMedium)
            grains.error?.let { Text(it, color = MaterialTheme.colorScheme.error, style = MaterialTheme.typography.bodySmall) }
        }
    }
}

@OptIn(ExperimentalLayoutApi::class)
@Composable
private fun GloveSection(glove: GloveUi, actions: SensorsActions) {
    Card(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            SectionTitle("Flex-sensor glove")
            val channels = (glove.channelNames.indices.toList() + listOf(glove.thumbChannel, glove.middleChannel)).distinct().sorted()
            val name = { c: Int -> glove.channelNames.getOrNull(c) ?: "ch$c" }
            val current = GloveChannels(glove.thumbChannel, glove.middleChannel, glove.adcBits.takeIf { glove.adcBitsFromDevice == null })
            FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                DropdownField("Thumb channel", channels, glove.thumbChannel, name, { actions.onGloveChannels(current.copy(thumb = it)) })
                DropdownField("Middle-finger channel", channels, glove.middleChannel, name, { actions.onGloveChannels(current.copy(middle = it)) })
                if (glove.adcBitsFromDevice == null) {
                    DropdownField("ADC resolution", listOf(10, 12), glove.adcBits, { "$it bit" }, { actions.onGloveChannels(current.copy(adcBits = it)) })
                }
            }
            Row(horizontalArrangement = Arrangement.spacedBy(12.dp)) {
                Button(onClick = actions.onOpenCalibration) { Text("Calibrate glove") }
                OutlinedButton(onClick = actions.onOpenHandshake) { Text("Handshake") }
            }
        }
    }
}

private val SAMPLE_RATES = listOf(25, 50, 100, 200, 250, 500, 1000)
