package org.hapticon.app.feature.sensors

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.selection.selectable
import androidx.compose.foundation.selection.selectableGroup
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.RadioButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.unit.dp

/** The Sensors screen's USB boards section: the plugged-in serial boards, one to choose. */
@Composable
internal fun DevicesSection(state: SensorsUiState.Ready, actions: SensorsActions) {
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
