package org.hapticon.app.feature.gesture

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.material3.Button
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import java.util.Locale

/**
 * The saved recordings fitted as one batch with the strongest gesture as the level reference (as
 * `hapticon fit --reference strongest` does for a directory): a button to fit them, each recording's icon and
 * level, and a button to save them all as custom icons. Stateless: [state] from [RecorderViewModel].
 */
@Composable
fun StrongestBatchSection(state: RecorderUiState.Ready, onFit: () -> Unit, onSave: () -> Unit) {
    if (state.savedRecordings.size < 2) return
    Text("Fit all saved recordings together", style = MaterialTheme.typography.titleMedium)
    Text(
        "Levels are measured against the strongest gesture of the saved recordings, so a light gesture stays lighter than a strong one.",
        style = MaterialTheme.typography.bodySmall,
    )
    Button(onClick = onFit, enabled = !state.batchFitting) { Text(if (state.batchFitting) "Fitting…" else "Fit all (strongest = 1)") }
    val batch = state.batch ?: return
    for (item in batch) {
        Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.SpaceBetween) {
            Text(item.recordingName, Modifier.weight(1f))
            Text(String.format(Locale.ROOT, "level %.2f · %d × %.2f s", item.fit.icon.level, item.fit.icon.count, item.fit.icon.duration))
        }
    }
    batch.firstOrNull()?.let { Text("Reference: ${it.fit.report.levelReference}", style = MaterialTheme.typography.bodySmall) }
    OutlinedButton(onClick = onSave) { Text("Save all ${batch.size} icons") }
}
