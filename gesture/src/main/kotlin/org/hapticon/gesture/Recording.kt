package org.hapticon.gesture

/**
 * A touch-gesture recording: equally long channels sampled together at [sampleRate] Hz. Everything the
 * gesture module reads — a vibration-sensor WAV, an FSR or glove stream, the touchscreen and the
 * accelerometer — becomes one of these. Samples are copied in and never change.
 */
public class Recording(
    /** Samples per second of every channel; finite and positive. */
    public val sampleRate: Double,
    /** The channels, at least one, all of the same length. */
    public val channels: List<Channel>,
) {
    init {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(channels.isNotEmpty()) { "a recording needs at least one channel" }
        val length = channels.first().size
        require(channels.all { it.size == length }) {
            "channels must be equally long, were ${channels.joinToString { "${it.name}=${it.size}" }}"
        }
        require(channels.map { it.name }.toSet().size == channels.size) { "channel names must be unique" }
    }

    /** Samples per channel. */
    public val frameCount: Int get() = channels.first().size

    /** Length in seconds. */
    public val durationSeconds: Double get() = frameCount / sampleRate

    /** The channel called [name], or null. */
    public fun channel(name: String): Channel? = channels.firstOrNull { it.name == name }

    /**
     * The channel called [name], or the first channel when [name] is null; throws [IllegalArgumentException]
     * naming the channels there are when there is no such channel.
     */
    public fun requireChannel(name: String?): Channel =
        if (name == null) channels.first() else channel(name)
            ?: throw IllegalArgumentException("no channel '$name'; the recording has ${channels.joinToString { it.name }}")

    /** The frames `[from, to)` as a new recording (trimming). */
    public fun slice(from: Int, to: Int): Recording {
        require(from in 0..to && to <= frameCount) { "slice [$from, $to) is outside 0..$frameCount" }
        return Recording(sampleRate, channels.map { it.slice(from, to) })
    }

    override fun toString(): String =
        "Recording(${channels.size} channels × $frameCount frames at $sampleRate Hz)"
}

/**
 * One named series of a [Recording]. [unit] says what the numbers are ("N", "V", "deg", "g", "px", or
 * "" for a normalised signal). Non-finite samples are allowed here — a CSV may hold a gap — and each
 * consumer says how it treats them.
 *
 * [fullScale] is the largest value the input can hold, in [unit]: 1.0 for a normalised channel (a float WAV's
 * 1.0; a PCM16 WAV's 32767, which is read as 1.0), a sensor's calibrated maximum when its source knows it, null
 * when unknown (a CSV in physical units). A fitted icon's level is measured against it by default.
 */
public class Channel(
    public val name: String,
    public val unit: String,
    samples: DoubleArray,
    public val fullScale: Double? = if (unit.isEmpty()) 1.0 else null,
) {
    private val values: DoubleArray = samples.copyOf()

    init {
        require(name.isNotBlank()) { "a channel needs a name" }
        require(fullScale == null || (fullScale.isFinite() && fullScale > 0.0)) { "full scale must be finite and > 0, was $fullScale" }
    }

    /** Number of samples. */
    public val size: Int get() = values.size

    /** Sample [index]. */
    public operator fun get(index: Int): Double = values[index]

    /** A copy of the samples. */
    public fun toDoubleArray(): DoubleArray = values.copyOf()

    /** Samples `[from, to)` as a new channel. */
    public fun slice(from: Int, to: Int): Channel = Channel(name, unit, values.copyOfRange(from, to), fullScale)

    override fun toString(): String = "Channel($name, $size samples${if (unit.isEmpty()) "" else " in $unit"})"
}
