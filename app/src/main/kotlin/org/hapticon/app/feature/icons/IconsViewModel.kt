package org.hapticon.app.feature.icons

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.PatternImportOutcome
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.PatternPlan
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.playOffMain
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind

/** The icon list: what the screen shows, and playing an icon when it is pressed. */
class IconsViewModel(
    iconRepository: IconRepository,
    private val player: HapticPlayer,
    private val patterns: RoomPatternRepository? = null,
) : ViewModel() {

    private val nowPlaying = MutableStateFlow<NowPlaying?>(null)
    private val importMessage = MutableStateFlow<String?>(null)
    private var clearWhenDone: Job? = null

    // Each pattern's playback plan (control-point fitting) is made when the stored patterns change, not again
    // on every press or message.
    private val patternItems = (patterns?.patterns() ?: flowOf(emptyList())).map { stored ->
        stored.map { PatternItem(it.pattern, it.source, planFor(player, it.pattern).summary) }
    }

    val uiState: StateFlow<IconsUiState> =
        combine(iconRepository.icons(), nowPlaying, patternItems, importMessage) { icons, playing, items, message ->
            IconsUiState.Success(
                icons = icons, renderer = player.capabilities.renderer, nowPlaying = playing,
                patterns = items,
                importMessage = message,
            )
        }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), IconsUiState.Loading)

    /**
     * Plays [icon] on the vibrator (rendered off the main thread) as a press in the open app ([VibrationUsage.TOUCH]);
     * the UI shows it as playing until it ends, or why Android did not play it.
     */
    fun play(icon: HapticIcon) = show(icon.name, isPattern = false) { player.playOffMain(icon, VibrationUsage.TOUCH) }

    /** Plays [pattern] on the vibrator (the best way this phone can: [AdaptiveHapticPlayer.planFor]), off the main thread, as [play] does. */
    fun play(pattern: HapticPattern) = show(pattern.name, isPattern = true) { player.playOffMain(pattern, VibrationUsage.TOUCH) }

    /** Imports a pattern file from outside; the screen shows what was imported, with notes, or the one-line error. */
    fun import(bytes: ByteArray, fileName: String) {
        val repository = patterns ?: return
        viewModelScope.launch {
            val taken = repository.patterns().first().map { it.pattern.name }.toSet()
            importMessage.value = when (val outcome = repository.import(bytes, fileName, taken)) {
                is PatternImportOutcome.Imported -> "Imported ${outcome.pattern.name} from $fileName" +
                    outcome.notes.joinToString("") { "\n• $it" }
                is PatternImportOutcome.Failed -> "Not imported: ${outcome.message}"
            }
        }
    }

    /** A file that could not even be read (no permission, gone): said like an import error. */
    fun importFailed(message: String) {
        importMessage.value = "Not imported: $message"
    }

    /** After an export: what the format could not keep, if anything (e.g. more breakpoints than it allows). */
    fun showExportNotes(pattern: HapticPattern, format: PatternFormat, notes: List<String>) {
        if (notes.isNotEmpty()) importMessage.value = "Exported ${pattern.name} as .${format.extension}" + notes.joinToString("") { "\n• $it" }
    }

    fun dismissImportMessage() {
        importMessage.value = null
    }

    fun delete(pattern: HapticPattern) {
        val repository = patterns ?: return
        viewModelScope.launch { repository.delete(pattern.name) }
    }

    private fun show(name: String, isPattern: Boolean, play: suspend () -> Playback) {
        clearWhenDone?.cancel()
        clearWhenDone = viewModelScope.launch {
            when (val playback = play()) {
                is Playback.Playing -> {
                    nowPlaying.value = NowPlaying(name, playback.renderer, playback.durationMillis, playback.fidelity, isPattern)
                    delay(playback.durationMillis)
                    nowPlaying.value = null
                }
                Playback.Unsupported -> nowPlaying.value = null
                is Playback.Ignored -> {
                    nowPlaying.value = null
                    importMessage.value = "$name did not play: ${playback.verdict.explanation}."
                }
            }
        }
    }

    override fun onCleared() {
        player.stop()
    }
}

/** What the icon list shows. */
sealed interface IconsUiState {
    data object Loading : IconsUiState

    data class Success(
        val icons: List<HapticIcon>,
        /** How this phone plays icons. */
        val renderer: RendererKind,
        /** The icon playing now, if any. */
        val nowPlaying: NowPlaying?,
        /** The user's imported and edited patterns. */
        val patterns: List<PatternItem> = emptyList(),
        /** What the last import did (one line, plus the reader's notes), or why Android did not play a pressed icon, until dismissed. */
        val importMessage: String? = null,
    ) : IconsUiState
}

/** An icon or pattern being played, and how faithfully. */
data class NowPlaying(
    val iconName: String,
    val renderer: RendererKind,
    val durationMillis: Long,
    val fidelity: Fidelity,
    val isPattern: Boolean = false,
)

/** A stored pattern as the list shows it: where it came from and how this phone plays it ([PatternPlan.summary]). */
data class PatternItem(val pattern: HapticPattern, val source: String?, val playedAs: String)

/** How [player] would play [pattern]: the adaptive player's own plan, else the steps a plain vibrator gets. */
internal fun planFor(player: HapticPlayer, pattern: HapticPattern): PatternPlan =
    (player as? AdaptiveHapticPlayer)?.planFor(pattern)
        ?: player.capabilities.let { PatternPlan.of(DeviceCapabilities(it.hasVibrator, it.hasAmplitudeControl, it.apiLevel), pattern) }
