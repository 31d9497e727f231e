package org.hapticon.app.feature.icons

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.IconRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.playOffMain
import org.hapticon.messaging.RendererKind
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.Fidelity

/** The icon list: what the screen shows, and playing an icon when it is pressed. */
class IconsViewModel(
    iconRepository: IconRepository,
    private val player: HapticPlayer,
) : ViewModel() {

    private val nowPlaying = MutableStateFlow<NowPlaying?>(null)
    private var clearWhenDone: Job? = null

    val uiState: StateFlow<IconsUiState> =
        combine(iconRepository.icons(), nowPlaying) { icons, playing ->
            IconsUiState.Success(icons = icons, renderer = player.capabilities.renderer, nowPlaying = playing)
        }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), IconsUiState.Loading)

    /** Plays [icon] on the vibrator (rendered off the main thread); the UI shows it as playing until it ends. */
    fun play(icon: HapticIcon) {
        clearWhenDone?.cancel()
        clearWhenDone = viewModelScope.launch {
            when (val playback = player.playOffMain(icon)) {
                is Playback.Playing -> {
                    nowPlaying.value = NowPlaying(icon.name, playback.renderer, playback.durationMillis, playback.fidelity)
                    delay(playback.durationMillis)
                    nowPlaying.value = null
                }
                Playback.Unsupported -> nowPlaying.value = null
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
    ) : IconsUiState
}

/** An icon being played, and how faithfully. */
data class NowPlaying(val iconName: String, val renderer: RendererKind, val durationMillis: Long, val fidelity: Fidelity)
