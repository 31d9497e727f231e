package org.hapticon.app.screenshots

import org.hapticon.app.feature.icons.IconsActions
import org.hapticon.app.feature.icons.IconsScreen
import org.hapticon.app.feature.icons.IconsUiState
import org.hapticon.app.feature.icons.NowPlaying
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind
import org.junit.Test

/** The Icons tab: loading, the four presets, and one of them playing. */
class IconsScreenshotTest : ScreenshotTest() {
    @Test
    fun icons_presets_listed() = screen("icons", Variant.MAIN) {
        IconsScreen(IconsUiState.Success(HapticIcon.PRESETS, RendererKind.AMPLITUDE_WAVEFORM, nowPlaying = null), IconsActions())
    }

    @Test
    fun icons_loading_showsProgress() = screen("icons-loading") {
        IconsScreen(IconsUiState.Loading, IconsActions())
    }

    @Test
    fun icons_playing_highlightsIcon() = screen("icons-playing") {
        val playing = NowPlaying("knock", RendererKind.AMPLITUDE_WAVEFORM, 810, Fidelity(0.02, 0.08, "close to the study's sound"))
        IconsScreen(IconsUiState.Success(HapticIcon.PRESETS, RendererKind.AMPLITUDE_WAVEFORM, playing), IconsActions())
    }
}
