package org.hapticon.core.io

/**
 * Audio read by [WavReader]: [frames] frames of [channels] samples each at [sampleRate], in [-1, 1]
 * for PCM16 (float files are returned as stored).
 */
public class WavAudio internal constructor(
    /** Frames per second. */
    public val sampleRate: Int,
    /** 1 (mono) or 2 (stereo). */
    public val channels: Int,
    /** How the file stored its samples. */
    public val encoding: WavEncoding,
    private val interleaved: FloatArray,
) {
    /** Number of frames (samples per channel). */
    public val frames: Int get() = interleaved.size / channels

    /** Duration in seconds. */
    public val durationSeconds: Double get() = frames.toDouble() / sampleRate

    /** A fresh copy of all samples, channels interleaved (left, right, left, … for stereo). */
    public fun samples(): FloatArray = interleaved.copyOf()

    /** A fresh copy of the samples of channel [index]; throws [IndexOutOfBoundsException] unless 0 <= [index] < [channels]. */
    public fun channel(index: Int): FloatArray {
        if (index !in 0 until channels) throw IndexOutOfBoundsException("channel $index of $channels")
        return FloatArray(frames) { interleaved[it * channels + index] }
    }

    /** A debug representation with the format and length. */
    override fun toString(): String = "WavAudio($encoding, $channels channel(s), $sampleRate Hz, $frames frames)"
}
