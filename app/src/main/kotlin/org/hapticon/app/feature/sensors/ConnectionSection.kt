package org.hapticon.app.feature.sensors

import org.hapticon.sensor.live.SessionState
import org.hapticon.app.ui.SegmentedChoice
import org.hapticon.app.ui.SingleChoice
import org.hapticon.sensor.live.StopCause
import org.hapticon.sensor.protocol.BAUD_RATES
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.ButtonRow

/** The Sensors screen's connection section: protocol, baud rate, Connect/Disconnect and the connection's state. */
@OptIn(ExperimentalLayoutApi::class)
@Composable
internal fun ConnectionSection(state: SensorsUiState.Ready, actions: SensorsActions) {
    val locked = !state.canConnect && state.canDisconnect
    Column(verticalArrangement = Arrangement.spacedBy(8.dp)) {
        SectionTitle("Connection")
        Text("Protocol", style = MaterialTheme.typography.labelMedium)
        SegmentedChoice(SingleChoice(state.protocols, state.protocol) { it.label }, actions.onSelectProtocol, enabled = !locked)
        FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            DropdownField(
                label = "Baud rate",
                choice = SingleChoice(BAUD_RATES, state.baudRate) { "$it baud" },
                onSelect = actions.onSelectBaudRate,
                enabled = !locked,
            )
        }
        ButtonRow {
            Button(onClick = actions.onConnect, enabled = state.canConnect) { Text("Connect") }
            OutlinedButton(onClick = actions.onDisconnect, enabled = state.canDisconnect) { Text("Disconnect") }
        }
        ConnectionStatus(state.connection, state.stream?.counters?.frames ?: 0)
    }
}

@Composable
private fun ConnectionStatus(connection: SessionState, frames: Long) {
    val (text, isError) = when (connection) {
        SessionState.Idle -> return
        is SessionState.RequestingPermission -> "Waiting for USB permission for ${connection.device.usbIds}…" to false
        is SessionState.Opening -> "Opening ${connection.device.chipFamily} board ${connection.device.usbIds}…" to false
        is SessionState.Streaming -> "Streaming ${connection.protocol.label} from ${connection.device.usbIds} at ${connection.baudRate} baud" to false
        is SessionState.PermissionDenied ->
            "USB permission denied for ${connection.device.usbIds}. Hapticon can't read the board unless you allow access; " +
                "tap Connect to ask again." to true
        is SessionState.Failed -> "Could not open ${connection.device.usbIds}: ${connection.message}" to true
        is SessionState.Stopped -> when (connection.cause) {
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
