package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.abs
import kotlin.math.sqrt

/**
 * Renderer (a), for audio-coupled playback where the actuator plays audio: [icon] as PCM16 at
 * [sampleRate], converted from the double-precision samples of an [IconRenderer] with the same
 * [model] and [mode] by [Pcm16.fromSample] (never through float, so values round only once).
 *
 * @property icon the icon rendered.
 * @property sampleRate samples per second, 8000..192000.
 * @property model how the envelope is shaped.
 * @property mode how the carrier is computed.
 * @throws org.hapticon.core.IconValidationException if the icon cannot be rendered at [sampleRate].
 */
public class PcmRenderer(
    public val icon: HapticIcon,
    public val sampleRate: Int,
    public val model: EnvelopeModel = EnvelopeModel.DEFAULT,
    public val mode: RenderMode = RenderMode.EXACT,
) {
    private val renderer = IconRenderer(icon, sampleRate, model, mode)

    /** Number of samples: round(duration · sampleRate), as for [IconRenderer.sampleCount]. */
    public val sampleCount: Long get() = renderer.sampleCount

    /** A new PCM16 stream over the whole render from sample 0; each call starts afresh. */
    public fun stream(): PcmStream = SampleSourceStream(renderer.newSynthesizer(mode), sampleRate)

    /**
     * The whole render in one array (at most 30 s · 192 kHz = 5.76 M samples, 11.5 MB);
     * prefer [stream] when the destination is itself streamed.
     */
    public fun toShortArray(): ShortArray {
        val pcm = ShortArray(sampleCount.toInt())
        val stream = stream()
        var filled = 0
        while (filled < pcm.size) filled += stream.read(pcm, filled, pcm.size - filled)
        return pcm
    }

    /**
     * How far the PCM16 output (value / 32767) is from the exact double signal, over every sample.
     * Rounding alone bounds the max error by 0.5 / 32767 ≈ 1.53e-5; FAST adds at most 1e-6.
     * Streams both, so memory stays constant.
     */
    public fun fidelity(): Fidelity {
        val pcm: PcmStream = SampleSourceStream(renderer.newSynthesizer(mode), sampleRate)
        val ideal = renderer.newSynthesizer(RenderMode.EXACT)
        val pcmBlock = ShortArray(BLOCK_SAMPLES)
        val idealBlock = DoubleArray(BLOCK_SAMPLES)
        var sumOfSquares = 0.0
        var maxError = 0.0
        while (true) {
            val n = pcm.read(pcmBlock)
            if (n < 0) break
            ideal.fill(idealBlock, 0, n)
            for (j in 0 until n) {
                val error = abs(pcmBlock[j] / Pcm16.FULL_SCALE.toDouble() - idealBlock[j])
                sumOfSquares += error * error
                maxError = maxOf(maxError, error)
            }
        }
        val rms = if (sampleCount == 0L) 0.0 else sqrt(sumOfSquares / sampleCount)
        return Fidelity(rms, maxError, "PCM16 at $sampleRate Hz, $model envelope, $mode carrier, $sampleCount samples")
    }

    private companion object {
        const val BLOCK_SAMPLES = 4096
    }
}
