package org.hapticon.core.render

import kotlin.math.abs
import kotlin.math.floor

/**
 * Conversion of samples in [-1, 1] to signed 16-bit PCM: x · 32767 rounded half away from zero,
 * clipped to ±32767 (so −1.0 → −32767; −32768 is never produced, keeping the scale symmetric).
 * NaN becomes 0 (silence), because a non-number must never drive the actuator.
 */
public object Pcm16 {
    /** The PCM value of full scale 1.0. */
    public const val FULL_SCALE: Int = 32767

    /** [value] as PCM16: value · 32767 rounded half away from zero, clipped to ±32767, NaN → 0. */
    public fun fromSample(value: Double): Short {
        if (value.isNaN()) return 0
        val scaled = value * FULL_SCALE
        if (scaled >= FULL_SCALE) return FULL_SCALE.toShort()
        if (scaled <= -FULL_SCALE) return (-FULL_SCALE).toShort()
        val magnitude = abs(scaled)
        val whole = floor(magnitude)
        // Compare the exact remainder with one half; floor(magnitude + 0.5) would round
        // 0.49999999999999994 up because the addition itself rounds.
        val rounded = if (magnitude - whole >= 0.5) whole + 1.0 else whole
        return (if (scaled < 0.0) -rounded else rounded).toInt().toShort()
    }

    /** [value] as PCM16, by the same rule as the Double overload (the float is widened exactly first). */
    public fun fromSample(value: Float): Short = fromSample(value.toDouble())

    /**
     * Converts [length] samples of [source] from [sourceOffset] into [destination] from [destinationOffset].
     *
     * @throws IndexOutOfBoundsException if either range falls outside its array.
     */
    public fun convert(
        source: FloatArray, destination: ShortArray, sourceOffset: Int = 0, destinationOffset: Int = 0,
        length: Int = source.size - sourceOffset,
    ): Unit = convert(source.size, destination, sourceOffset, destinationOffset, length) { source[it].toDouble() }

    /** [convert] for Double samples: the same ranges, checks and rounding. */
    public fun convert(
        source: DoubleArray, destination: ShortArray, sourceOffset: Int = 0, destinationOffset: Int = 0,
        length: Int = source.size - sourceOffset,
    ): Unit = convert(source.size, destination, sourceOffset, destinationOffset, length) { source[it] }

    // One loop for both array types; inline, so reading a sample stays a plain array access.
    private inline fun convert(
        sourceSize: Int, destination: ShortArray, sourceOffset: Int, destinationOffset: Int, length: Int,
        sample: (Int) -> Double,
    ) {
        checkRange(sourceSize, sourceOffset, length)
        checkRange(destination.size, destinationOffset, length)
        for (j in 0 until length) destination[destinationOffset + j] = fromSample(sample(sourceOffset + j))
    }
}
