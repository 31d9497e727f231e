package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Test

/** [HapticPlayer.play] with a model on a player that renders only the default one. */
class HapticPlayerModelTest {
    private class DefaultOnlyPlayer : HapticPlayer {
        val played = ArrayList<String>()
        override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

        override fun play(icon: HapticIcon, usage: VibrationUsage): Playback {
            played += icon.name
            return Playback.Playing(RendererKind.AMPLITUDE_WAVEFORM, 560, Fidelity(0.0, 0.0, "exact"))
        }

        override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback = Playback.Unsupported

        override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS

        override fun stop() = Unit
    }

    @Test
    fun play_defaultModel_playsThroughThePlayersOwnRenderer() {
        val player = DefaultOnlyPlayer()
        assertEquals(560L, (player.play(HapticIcon.KNOCK, EnvelopeModel.DEFAULT, VibrationUsage.TOUCH) as Playback.Playing).durationMillis)
        assertEquals(listOf("knock"), player.played)
    }

    @Test
    fun play_anotherModel_isUnsupportedAndPlaysNothing() {
        val player = DefaultOnlyPlayer()
        assertEquals(Playback.Unsupported, player.play(HapticIcon.KNOCK, EnvelopeModel.PAPER, VibrationUsage.TOUCH))
        assertEquals(emptyList<String>(), player.played)
    }
}
