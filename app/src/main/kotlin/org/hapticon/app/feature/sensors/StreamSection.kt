package org.hapticon.app.feature.sensors

import org.hapticon.app.ui.LivePlot
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import java.util.Locale
import org.hapticon.app.ui.LabeledValue

/** One live channel of the stream section: its name, latest value and plot. */
@Composable
internal fun ChannelRow(channel: ChannelUi, stream: StreamUi) {
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

/** The stream section's counters: frames, bad frames, dropped bytes, gaps and rate. */
@Composable
internal fun StatsSection(stream: StreamUi) {
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
