package org.hapticon.app.feature.sensors

import org.hapticon.sensor.glove.GloveChannels
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.ButtonRow

/** The Sensors screen's flex-sensor glove section: finger channels, calibration and handshake. */
@OptIn(ExperimentalLayoutApi::class)
@Composable
internal fun GloveSection(glove: GloveUi, actions: SensorsActions) {
    Card(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            SectionTitle("Flex-sensor glove")
            val channels = (glove.channelNames.indices.toList() + listOf(glove.thumbChannel, glove.middleChannel)).distinct().sorted()
            val name = { c: Int -> glove.channelNames.getOrNull(c) ?: "ch$c" }
            val current = GloveChannels(glove.thumbChannel, glove.middleChannel, glove.adcBits.takeIf { glove.adcBitsFromDevice == null })
            FlowRow(horizontalArrangement = Arrangement.spacedBy(12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                DropdownField("Thumb channel", SingleChoice(channels, glove.thumbChannel, name), { actions.onGloveChannels(current.copy(thumb = it)) })
                DropdownField("Middle-finger channel", SingleChoice(channels, glove.middleChannel, name), { actions.onGloveChannels(current.copy(middle = it)) })
                if (glove.adcBitsFromDevice == null) {
                    DropdownField("ADC resolution", SingleChoice(listOf(10, 12), glove.adcBits) { "$it bit" }, { actions.onGloveChannels(current.copy(adcBits = it)) })
                }
            }
            ButtonRow {
                Button(onClick = actions.onOpenCalibration) { Text("Calibrate glove") }
                OutlinedButton(onClick = actions.onOpenHandshake) { Text("Handshake") }
            }
        }
    }
}
