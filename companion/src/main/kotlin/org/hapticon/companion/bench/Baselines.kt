package org.hapticon.companion.bench

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin

/**
 * The bench's two independent baselines, each the shortest honest loop for the same number of samples
 * of a bare carrier (no envelope, so they do less work than the renderer), read into the same reused
 * block. [PlainSineLoop] is what EXACT is compared with (one `Math.sin` per sample); [SinglePhasorLoop]
 * is what FAST is compared with (one rotating phasor, the textbook fast oscillator).
 */
sealed class BaselineLoop(val sampleCount: Long) {
    protected var position: Long = 0L

    /** Fills [block] with the next samples and returns how many, or -1 at the end, like a SampleStream. */
    fun read(block: FloatArray): Int {
        if (position >= sampleCount) return -1
        val count = minOf(block.size.toLong(), sampleCount - position).toInt()
        fill(block, count)
        position += count
        return count
    }

    protected abstract fun fill(block: FloatArray, count: Int)
}

/** block[j] = sin(2π·f·i / fs) for sample i: a plain `Math.sin` loop. */
class PlainSineLoop(frequency: Double, sampleRate: Int, sampleCount: Long) : BaselineLoop(sampleCount) {
    private val radiansPerSample = 2.0 * PI * frequency / sampleRate

    override fun fill(block: FloatArray, count: Int) {
        for (j in 0 until count) block[j] = sin(radiansPerSample * (position + j)).toFloat()
    }
}

/** block[j] = sin of one phasor rotated by 2π·f/fs per sample, from phase 0: a single rotating phasor. */
class SinglePhasorLoop(frequency: Double, sampleRate: Int, sampleCount: Long) : BaselineLoop(sampleCount) {
    private val rotationCos = cos(2.0 * PI * frequency / sampleRate)
    private val rotationSin = sin(2.0 * PI * frequency / sampleRate)
    private var c = 1.0
    private var s = 0.0

    override fun fill(block: FloatArray, count: Int) {
        var c = c
        var s = s
        for (j in 0 until count) {
            block[j] = s.toFloat()
            val next = c * rotationCos - s * rotationSin
            s = s * rotationCos + c * rotationSin
            c = next
        }
        this.c = c
        this.s = s
    }
}
