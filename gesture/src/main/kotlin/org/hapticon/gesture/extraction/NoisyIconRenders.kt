package org.hapticon.gesture.extraction

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.IconRenderer
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import java.util.Random
import kotlin.math.roundToInt
import kotlin.math.sqrt

/**
 * A recording made from a known icon, for measuring the fitter: [samples] is the icon rendered by
 * haptics-core's [IconRenderer] (PAPER envelope) between [padSamples] of silence on each side, plus white
 * Gaussian noise; [trueEnvelope] is the noise-free envelope at the same indices.
 */
public class NoisyIconRender(
    /** The icon rendered. */
    public val icon: HapticIcon,
    /** Samples per second. */
    public val sampleRate: Int,
    /** Silence before (and after) the icon, in samples. */
    public val padSamples: Int,
    samples: DoubleArray,
    trueEnvelope: DoubleArray,
) {
    private val signal = samples.copyOf()
    private val envelope = trueEnvelope.copyOf()

    /** A copy of the noisy samples. */
    public fun samples(): DoubleArray = signal.copyOf()

    /** A copy of the true envelope. */
    public fun trueEnvelope(): DoubleArray = envelope.copyOf()

    /** The samples as a one-channel recording (channel "vibration", unit ""). */
    public fun toRecording(): Recording = Recording(sampleRate.toDouble(), listOf(Channel("vibration", "", signal)))
}

/** Random valid icons and their noisy renders, seeded, for the synthetic evaluation (docs/gesture-extraction.md). */
public object NoisyIconRenders {
    /** Silence on each side of a synthetic gesture, in seconds. */
    public const val PAD_SECONDS: Double = 0.25

    /**
     * A random icon within what a hand gesture produces and the fitter can separate: attack and release
     * 5–300 ms, sustain 20–800 ms, level 0.2–1, integer note 45–84 (110 Hz–1 kHz), 1–5 repetitions whose
     * envelopes do not overlap (period = envelope + 60–400 ms of silence).
     */
    public fun randomIcon(random: Random, name: String = "synthetic"): HapticIcon {
        val attack = uniform(random, 0.005, 0.3)
        val sustain = uniform(random, 0.02, 0.8)
        val release = uniform(random, 0.005, 0.3)
        val level = uniform(random, 0.2, 1.0)
        val note = 45 + random.nextInt(40)
        val count = 1 + random.nextInt(5)
        val period = if (count == 1) 0.0 else attack + sustain + release + uniform(random, 0.06, 0.4)
        return HapticIcon(name, attack, sustain, level, release, note.toDouble(), period, count)
    }

    /**
     * [icon] rendered at [sampleRate] with [PAD_SECONDS] of silence each side and white Gaussian noise from
     * [random] at [snrDb] — relative to the mean power of the samples inside the icon's envelopes (true
     * envelope > 0), so gaps between repetitions do not make the noise look smaller. [snrDb] = +∞ adds none.
     */
    public fun render(icon: HapticIcon, snrDb: Double, random: Random, sampleRate: Int = 44_100): NoisyIconRender {
        require(!snrDb.isNaN()) { "SNR must be a number of dB, was NaN" }
        // The fitter recovers the paper trapezoid (a held level), so the synthetic gestures are rendered with it.
        val renderer = IconRenderer(icon, sampleRate, EnvelopeModel.PAPER)
        val pad = (PAD_SECONDS * sampleRate).roundToInt()
        val length = renderer.sampleCount.toInt()
        val samples = DoubleArray(length + 2 * pad)
        val truth = DoubleArray(samples.size)
        val stream = renderer.stream()
        var filled = 0
        while (filled < length) filled += stream.read(samples, pad + filled, length - filled)
        var power = 0.0
        var active = 0
        for (i in 0 until length) {
            truth[pad + i] = renderer.envelopeAt(i.toLong())
            if (truth[pad + i] > 0.0) {
                power += samples[pad + i] * samples[pad + i]
                active++
            }
        }
        if (snrDb != Double.POSITIVE_INFINITY && active > 0) {
            val sigma = sqrt(power / active / Math.pow(10.0, snrDb / 10.0))
            for (i in samples.indices) samples[i] += sigma * random.nextGaussian()
        }
        return NoisyIconRender(icon, sampleRate, pad, samples, truth)
    }

    private fun uniform(random: Random, from: Double, to: Double): Double = from + (to - from) * random.nextDouble()
}
