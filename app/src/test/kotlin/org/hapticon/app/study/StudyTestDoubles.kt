package org.hapticon.app.study

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.PlaybackCapabilities
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind

/** A [HapticPlayer] that records the icons it was asked to play and "plays" each for [durationMillis]. */
class TestHapticPlayer(private val durationMillis: Long = 560) : HapticPlayer {
    val played = ArrayList<HapticIcon>()

    /** The envelope model of each entry of [played]. */
    val models = ArrayList<EnvelopeModel>()
    val playedPatterns = ArrayList<HapticPattern>()

    /** The usage of every play, icons and patterns, in order. */
    val usages = ArrayList<VibrationUsage>()
    var stops = 0

    override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

    override fun play(icon: HapticIcon, usage: VibrationUsage): Playback = play(icon, EnvelopeModel.DEFAULT, usage)

    override fun play(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback {
        played += icon
        models += model
        usages += usage
        return Playback.Playing(RendererKind.AMPLITUDE_WAVEFORM, durationMillis, Fidelity(0.0, 0.0, "exact"))
    }

    override fun verdict(usage: VibrationUsage) = org.hapticon.core.platform.VibrationVerdict.PLAYS

    override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback {
        usages += usage
        playedPatterns += pattern
        return Playback.Playing(RendererKind.AMPLITUDE_WAVEFORM, durationMillis, Fidelity(0.0, 0.0, "exact"))
    }

    override fun stop() {
        stops++
    }
}

/** A [MaskingNoisePlayer] that records starts and stops, in order. */
class TestMaskingNoise : MaskingNoisePlayer {
    val calls = ArrayList<String>()
    var playing: MaskingSetting? = null
        private set

    override fun start(setting: MaskingSetting) {
        calls += "start ${setting.color} ${setting.levelDbfs}"
        playing = setting
    }

    override fun stop() {
        if (playing != null) calls += "stop"
        playing = null
    }
}

/** In-memory [StudySettingsRepository]. */
class TestStudySettings(initial: StudyPreferences = StudyPreferences()) : StudySettingsRepository {
    private val state = MutableStateFlow(initial)
    override val preferences: StateFlow<StudyPreferences> = state.asStateFlow()
    override fun update(transform: (StudyPreferences) -> StudyPreferences) {
        state.value = transform(state.value)
    }
}

/** A clock that returns 1 700 000 000 000 ms, then one second more on every call. */
class TickingClock(private val startMillis: Long = 1_700_000_000_000L, private val stepMillis: Long = 1_000L) : () -> Long {
    var calls = 0L
        private set

    override fun invoke(): Long = startMillis + stepMillis * calls++
}
