package org.hapticon.app.feature.icons

import org.hapticon.app.data.PatternFileAccess
import org.hapticon.app.playback.label
import androidx.compose.foundation.clickable
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.items
import androidx.compose.material3.Card
import androidx.compose.material3.CardDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.runtime.Immutable
import androidx.compose.runtime.LaunchedEffect
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.rememberCoroutineScope
import androidx.compose.runtime.setValue
import androidx.compose.ui.platform.LocalContext
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import android.net.Uri
import java.io.IOException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.core.pattern.HapticPattern
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import java.util.Locale
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.core.HapticIcon
import org.hapticon.app.ui.EnvelopeThumbnail

/**
 * The icon list wired to its [IconsViewModel], with the user's [patterns] (null: the icons only): the file picker and
 * files shared to Hapticon ([pendingPatternFile]) import, the share sheet exports, and a pattern opens in its editor.
 */
@Composable
fun IconsRoute(icons: IconRepository, player: HapticPlayer, patterns: RoomPatternRepository?, pendingPatternFile: MutableStateFlow<Uri?>) {
    val viewModel: IconsViewModel = viewModel(
        factory = viewModelFactory { initializer { IconsViewModel(icons, player, patterns) } },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val iconsActions = remember(viewModel) { IconsActions(onPlay = viewModel::play) }
    if (patterns == null) {
        IconsScreen(uiState, iconsActions)
        return
    }
    val context = LocalContext.current
    val scope = rememberCoroutineScope()
    var editing by remember { mutableStateOf<HapticPattern?>(null) }
    val importUri: (Uri) -> Unit = { uri ->
        scope.launch {
            try {
                val (bytes, name) = withContext(Dispatchers.IO) { PatternFileAccess.read(context, uri) }
                viewModel.import(bytes, name)
            } catch (e: IOException) {
                viewModel.importFailed(e.message ?: "the file could not be read")
            }
        }
    }
    val picker = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri -> uri?.let(importUri) }
    val shared by pendingPatternFile.collectAsStateWithLifecycle()
    LaunchedEffect(shared) {
        shared?.let { uri ->
            pendingPatternFile.value = null
            importUri(uri)
        }
    }
    editing?.let { pattern ->
        PatternEditorRoute(pattern, patterns, player, onDone = { editing = null })
        return
    }
    val actions = remember(viewModel) {
        PatternListActions(
            // Any type: .ahap and .haptic have no registered MIME type, and providers label JSON differently.
            onImport = { picker.launch(arrayOf("*/*")) },
            onPlay = viewModel::play,
            onEdit = { editing = it },
            onExport = { pattern, format ->
                val export = patterns.export(pattern, format)
                context.startActivity(PatternFileAccess.share(context, pattern, format, export.text))
                viewModel.showExportNotes(pattern, format, export.notes)
            },
            onDelete = viewModel::delete,
            onDismissMessage = viewModel::dismissImportMessage,
        )
    }
    IconsScreen(uiState, iconsActions, patternActions = actions)
}

/** What the Icons screen can ask for. */
@Immutable
class IconsActions(val onPlay: (HapticIcon) -> Unit = {})

/** The icon list: each icon with its parameters and envelope; pressing one plays it. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun IconsScreen(uiState: IconsUiState, actions: IconsActions, patternActions: PatternListActions? = null) {
    Scaffold(topBar = { TopAppBar(title = { Text("Haptic icons") }) }) { padding ->
        when (uiState) {
            IconsUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) {
                CircularProgressIndicator()
            }
            is IconsUiState.Success -> LazyColumn(
                contentPadding = PaddingValues(16.dp),
                verticalArrangement = Arrangement.spacedBy(12.dp),
                modifier = Modifier.fillMaxSize().padding(padding),
            ) {
                item {
                    Text(
                        "Tap an icon to feel it. This phone plays icons as: ${uiState.renderer.label}.",
                        style = MaterialTheme.typography.bodyMedium,
                    )
                }
                items(uiState.icons, key = { it.name }) { icon ->
                    IconCard(icon, playing = uiState.nowPlaying?.takeIf { it.iconName == icon.name && !it.isPattern }, actions.onPlay)
                }
                if (patternActions != null) {
                    item(key = "patterns-header") { PatternsHeader(uiState.patterns.size, patternActions) }
                    uiState.importMessage?.let { message ->
                        item(key = "import-message") { ImportMessageCard(message, patternActions.onDismissMessage) }
                    }
                    items(uiState.patterns, key = { "pattern:" + it.pattern.name }) { item ->
                        PatternCard(item, uiState.nowPlaying?.takeIf { it.isPattern && it.iconName == item.pattern.name }, patternActions)
                    }
                }
            }
        }
    }
}

@Composable
private fun IconCard(icon: HapticIcon, playing: NowPlaying?, onPlay: (HapticIcon) -> Unit) {
    val colors = if (playing != null) {
        CardDefaults.cardColors(containerColor = MaterialTheme.colorScheme.primaryContainer)
    } else {
        CardDefaults.cardColors()
    }
    Card(
        colors = colors,
        modifier = Modifier
            .fillMaxWidth()
            .clickable(role = Role.Button, onClickLabel = "play") { onPlay(icon) }
            .semantics {
                contentDescription = "Play ${icon.name}"
                stateDescription = if (playing != null) "playing" else "not playing"
            },
    ) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            Row(verticalAlignment = Alignment.CenterVertically) {
                Text(icon.name.replaceFirstChar { it.titlecase(Locale.ROOT) }, style = MaterialTheme.typography.titleMedium)
            }
            Text(describe(icon), style = MaterialTheme.typography.bodySmall)
            EnvelopeThumbnail(icon)
            if (playing != null) {
                Text(
                    "Playing ${playing.durationMillis} ms as ${playing.renderer.label} · " +
                        "RMS error ${"%.3f".format(Locale.ROOT, playing.fidelity.rmsError)}",
                    style = MaterialTheme.typography.labelMedium,
                )
            }
        }
    }
}

/**
 * One line with every parameter, e.g. "A 0.005 s · S 0.01 s · L 0.5 · R 0.005 s · note 57 (220.0 Hz) · 3× every 0.27 s".
 * Each value is joined to its letter and unit by no-break spaces, so a narrow screen or a large font wraps
 * between parameters, never between a number and its unit.
 */
internal fun describe(icon: HapticIcon): String {
    fun n(x: Double) = if (x == Math.floor(x) && x < 1e6) x.toLong().toString() else x.toString()
    val nb = '\u00A0'
    val repeat = if (icon.count > 1) " · ${icon.count}×${nb}every$nb${n(icon.period)}${nb}s" else ""
    return "A$nb${n(icon.attack)}${nb}s · S$nb${n(icon.sustain)}${nb}s · L$nb${n(icon.level)} · R$nb${n(icon.release)}${nb}s · " +
        "note$nb${n(icon.note)}$nb(${"%.1f".format(Locale.ROOT, icon.frequency)}${nb}Hz)$repeat"
}
