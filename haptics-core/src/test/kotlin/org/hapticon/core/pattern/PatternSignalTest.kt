package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.stream
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import kotlin.math.PI
import kotlin.math.sin

class PatternSignalTest {
    @Test
    fun constantFrequency_isAmplitudeTimesSine() {
        val pattern = HapticPattern("tone", listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(1.0, 1.0)), listOf(FrequencyKey(0.0, 220.0)))
        val signal = pattern.signal()
        for (t in listOf(0.001, 0.25, 0.5013, 0.999)) {
            assertEquals(t * sin(2 * PI * 220.0 * t), signal.sample(t), 1e-9)
        }
    }

    @Test
    fun rampingFrequency_integratesThePhase() {
        // 100 → 200 Hz over 1 s: φ(t) = 100 t + 50 t², so φ(0.25) = 28.125 cycles.
        val pattern = HapticPattern(
            "chirp",
            listOf(AmplitudeKey(0.0, 1.0), AmplitudeKey(2.0, 1.0)),
            listOf(FrequencyKey(0.0, 100.0), FrequencyKey(1.0, 200.0)),
        )
        val signal = pattern.signal()
        assertEquals(sin(2 * PI * 0.125), signal.sample(0.25), 1e-9)
        // After the last key the frequency holds at 200 Hz from φ(1) = 150 cycles.
        assertEquals(sin(2 * PI * (200.0 * 0.3013)), signal.sample(1.3013), 1e-9)
    }

    @Test
    fun transient_isAHannBurstOfIntensitySquared() {
        val pattern = HapticPattern("tap", emptyList(), listOf(FrequencyKey(0.0, 100.0)), listOf(Transient(0.1, 0.8, 0.5)))
        val hz = FrequencyMapping.DEFAULT.hertzOfSharpness(0.5)
        val signal = pattern.signal()
        // At the middle of the 20 ms burst the Hann window is 1.
        assertEquals(0.64 * sin(2 * PI * hz * 0.010), signal.sample(0.110), 1e-12)
        assertEquals(0.0, signal.sample(0.0999), 0.0)
        assertEquals(0.12, signal.length, 1e-12)
    }

    @Test
    fun stream_rendersRoundOfDurationTimesRateSamples() {
        val stream = HapticIcon.KNOCK.toPattern().signal().stream(48_000)
        assertEquals(26_880L, stream.totalSamples)
    }

    @Test
    fun sample_nonFiniteTime_throws() {
        val signal = HapticIcon.HIT.toPattern().signal()
        assertThrows(IllegalArgumentException::class.java) { signal.sample(Double.NaN) }
        assertThrows(IllegalArgumentException::class.java) { signal.sample(Double.POSITIVE_INFINITY) }
    }

    @Test
    fun pattern_invalidValues_nameTheField() {
        val e = assertThrows(PatternException::class.java) {
            HapticPattern("x", listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(-1.0, 0.5)), listOf(FrequencyKey(0.0, 100.0)))
        }
        assertEquals("amplitude[1].time", e.field)
        assertEquals("amplitude[0].amplitude", assertThrows(PatternException::class.java) {
            HapticPattern("x", listOf(AmplitudeKey(0.0, Double.NaN)), listOf(FrequencyKey(0.0, 100.0)))
        }.field)
        assertEquals("frequency", assertThrows(PatternException::class.java) { HapticPattern("x", emptyList(), emptyList()) }.field)
        assertEquals("duration", assertThrows(PatternException::class.java) {
            HapticPattern("x", listOf(AmplitudeKey(0.0, 0.1), AmplitudeKey(3600.001, 0.1)), listOf(FrequencyKey(0.0, 100.0)))
        }.field)
    }

    @Test
    fun pattern_longerThanTheSafetyCap_isAValueButNotPlayable() {
        val long = HapticPattern("x", listOf(AmplitudeKey(0.0, 0.1), AmplitudeKey(31.0, 0.1)), listOf(FrequencyKey(0.0, 100.0)))
        val hour = HapticPattern("x", listOf(AmplitudeKey(0.0, 0.1), AmplitudeKey(3600.0, 0.1)), listOf(FrequencyKey(0.0, 100.0)))
        assertEquals(3600.0, hour.duration, 0.0)
        val refused = assertThrows(PatternException::class.java) { long.checkPlayable() }
        assertEquals("duration: plays for 31.000 s, longer than the 30.0 s safety cap for playing", refused.message)
        // Every actuator path asks first: the waveform, the on/off pattern and the envelope effect.
        assertEquals("duration", assertThrows(PatternException::class.java) { long.vibrationWaveform() }.field)
        assertEquals("duration", assertThrows(PatternException::class.java) { long.onOffWaveform() }.field)
        assertEquals("duration", assertThrows(PatternException::class.java) {
            PatternEnvelope.of(long, EnvelopeEffectInfo(16, 20, 1000, 60_000), null)
        }.field)
        val thirty = HapticPattern("x", listOf(AmplitudeKey(0.0, 0.1), AmplitudeKey(30.0, 0.1)), listOf(FrequencyKey(0.0, 100.0)))
        assertEquals(thirty, thirty.checkPlayable())
    }
}
