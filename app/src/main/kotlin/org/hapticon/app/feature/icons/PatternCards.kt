package org.hapticon.app.feature.icons

import androidx.compose.foundation.clickable
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.DropdownMenu
import androidx.compose.material3.DropdownMenuItem
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedCard
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import java.util.Locale
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.ui.PatternThumbnail
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFormat

/** What the pattern part of the icon list can do; the route wires it to the view model, the picker and the share sheet. */
class PatternListActions(
    val onImport: () -> Unit,
    val onPlay: (HapticPattern) -> Unit,
    val onEdit: (HapticPattern) -> Unit,
    val onExport: (HapticPattern, PatternFormat) -> Unit,
    val onDelete: (HapticPattern) -> Unit,
    val onDismissMessage: () -> Unit,
)

/** The import result: what was imported (with the reader's notes) or the one-line reason it was not. */
@Composable
internal fun ImportMessageCard(message: String, onDismiss: () -> Unit) {
    OutlinedCard(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(12.dp)) {
            Text(message, style = MaterialTheme.typography.bodyMedium)
            TextButton(onClick = onDismiss, modifier = Modifier.align(Alignment.End)) { Text("OK") }
        }
    }
}

/** The heading of the pattern section with its import button. */
@Composable
internal fun PatternsHeader(count: Int, actions: PatternListActions) {
    Row(Modifier.fillMaxWidth(), verticalAlignment = Alignment.CenterVertically) {
        Column(Modifier.weight(1f)) {
            Text("Patterns", style = MaterialTheme.typography.titleMedium)
            Text(
                if (count == 0) "Import Apple .ahap, Meta .haptic or Hapticon pattern JSON files, or share one to Hapticon."
                else "Amplitude (filled) and pitch (line) of your imported patterns.",
                style = MaterialTheme.typography.bodySmall,
            )
        }
        TextButton(onClick = actions.onImport) { Text("Import…") }
    }
}

/** One stored pattern: tap to feel it; edit, export in any format, delete. */
@Composable
internal fun PatternCard(item: PatternItem, playing: NowPlaying?, actions: PatternListActions) {
    val pattern = item.pattern
    val colors = if (playing != null) CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.primaryContainer) else CardDefaults.cardColors()
    var menu by remember { mutableStateOf(false) }
    Card(
        colors = colors,
        modifier = Modifier
            .fillMaxWidth()
            .clickable(role = Role.Button, onClickLabel = "play") { actions.onPlay(pattern) }
            .semantics {
                contentDescription = "Play pattern ${pattern.name}"
                stateDescription = if (playing != null) "playing" else "not playing"
            },
    ) {
        Column(Modifier.padding(start = 16.dp, end = 4.dp, top = 8.dp, bottom = 12.dp), verticalArrangement = Arrangement.spacedBy(6.dp)) {
            Row(verticalAlignment = Alignment.CenterVertically) {
                Text(pattern.name, style = MaterialTheme.typography.titleMedium, modifier = Modifier.weight(1f))
                IconButton(onClick = { actions.onEdit(pattern) }) { Icon(HapticonIcons.Edit, contentDescription = "Edit ${pattern.name}") }
                IconButton(onClick = { menu = true }) { Icon(HapticonIcons.Share, contentDescription = "Export ${pattern.name}") }
                DropdownMenu(expanded = menu, onDismissRequest = { menu = false }) {
                    for (format in PatternFormat.entries) {
                        DropdownMenuItem(
                            text = { Text("Export as .${format.extension}") },
                            onClick = { menu = false; actions.onExport(pattern, format) },
                        )
                    }
                    DropdownMenuItem(text = { Text("Delete") }, onClick = { menu = false; actions.onDelete(pattern) })
                }
            }
            Column(Modifier.padding(end = 12.dp), verticalArrangement = Arrangement.spacedBy(6.dp)) {
                Text(describe(pattern, item.source), style = MaterialTheme.typography.bodySmall)
                PatternThumbnail(pattern)
                Text("Here: ${item.playedAs}", style = MaterialTheme.typography.labelMedium)
                if (playing != null) {
                    Text(
                        "Playing ${playing.durationMillis} ms · RMS error ${"%.3f".format(Locale.ROOT, playing.fidelity.rmsError)}",
                        style = MaterialTheme.typography.labelMedium,
                    )
                }
            }
        }
    }
}

/** One line: duration, pitch range, key and tap counts and the source file, e.g. "0.40 s · 110–220 Hz · 3 keys · 1 tap · from boing.ahap". */
internal fun describe(pattern: HapticPattern, source: String?): String {
    val low = pattern.frequency.minOf { it.hertz }
    val high = pattern.frequency.maxOf { it.hertz }
    val pitch = if (low == high) "%.0f Hz".format(Locale.ROOT, low) else "%.0f–%.0f Hz".format(Locale.ROOT, low, high)
    val taps = pattern.transients.size.let { if (it == 0) "" else " · $it tap${if (it == 1) "" else "s"}" }
    val from = source?.let { " · from $it" }.orEmpty()
    return "%.2f s".format(Locale.ROOT, pattern.duration) + " · $pitch · ${pattern.amplitude.size} keys$taps$from"
}
