package org.hapticon.app.feature.sensors

import org.hapticon.sensor.grains.ForceInput
import org.hapticon.app.ui.SegmentedChoice
import org.hapticon.app.ui.SingleChoice
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.FlowRow
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Card
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Slider
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import java.util.Locale
import kotlin.math.roundToInt
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SwitchRow
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.GrainSettings

/** The Sensors screen's FSR grain section (Shaping Compliance's grains on the phone's vibrator). */
@OptIn(ExperimentalLayoutApi::class)
@Composable
internal fun GrainsSection(grains: GrainUi, actions: SensorsActions) {
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
                    choice = SingleChoice(channels, grains.channel) { grains.channelNames.getOrNull(it) ?: "ch$it" },
                    onSelect = actions.onGrainChannel,
                )
                DropdownField(
                    label = "Force reads as",
                    choice = SingleChoice(listOf<ForceInput?>(null) + ForceInput.entries, grains.input) { it?.label ?: "Automatic" },
                    onSelect = actions.onForceInput,
                )
                if (grains.deviceSampleRateHz == null) {
                    DropdownField(
                        label = "Sample rate",
                        choice = SingleChoice(SAMPLE_RATES, grains.fallbackSampleRateHz) { "$it Hz" },
                        onSelect = actions.onFallbackSampleRate,
                    )
                }
            }
            grains.deviceSampleRateHz?.let { Text("Sample rate from the board: $it Hz", style = MaterialTheme.typography.bodySmall) }
            // Shaping Compliance: grains = bins − 1 (003_8ca1dc8f53472543.txt:95), so a full press fires exactly this many grains.
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
            SegmentedChoice(
                SingleChoice(BinDistribution.entries, grains.distribution) { d -> d.name.lowercase().replaceFirstChar { it.titlecase(Locale.ROOT) } },
                actions.onDistribution,
            )
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

private val SAMPLE_RATES = listOf(25, 50, 100, 200, 250, 500, 1000)
