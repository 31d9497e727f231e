package org.hapticon.app.feature.sensors

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Card
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp

/** The Sensors screen's electrotactile section: opens the per-person calibration of the 3×3 electrode array. */
@Composable
internal fun ElectrotactileSection(actions: SensorsActions) {
    Card(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            SectionTitle("Electrotactile array")
            Text(
                "Compliance grains on a 3×3 electrode array (Shaping Compliance). Calibrate each person before stimulating.",
                style = MaterialTheme.typography.bodySmall,
            )
            OutlinedButton(onClick = actions.onOpenElectrotactile) { Text("Calibrate electrodes") }
        }
    }
}
