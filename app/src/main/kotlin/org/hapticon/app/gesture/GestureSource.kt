package org.hapticon.app.gesture

/** One channel a [GestureSource] delivers: [name] as written in recordings and model files, [unit] as in the gesture module ("" when none). */
/**
 * One channel a [GestureSource] delivers: its [name], [unit] ("" for a normalised value) and [fullScale], the
 * largest value the source can deliver (1.0 for a normalised value; null when the source cannot say, such as raw
 * sensor-board values or a velocity): a fitted icon's level is measured against it when known.
 */
data class GestureChannel(val name: String, val unit: String = "", val fullScale: Double? = if (unit.isEmpty()) 1.0 else null)

/** Receives frames from a [GestureSource] on the source's background thread. */
fun interface GestureSink {
    /**
     * One frame: one value per [GestureSource.channels] entry, in that order. The array is reused by the
     * source: copy what you keep.
     */
    fun onFrame(values: DoubleArray)
}

/**
 * Something a gesture can be recorded from: the sensor board stream, the touchscreen, the accelerometer.
 * [start] begins delivering frames at [sampleRate] Hz to a sink on a background thread (never the main
 * thread, so recording and recognition cannot stall the UI); [stop] ends it, after which no frame arrives.
 * [channels] and [sampleRate] are fixed while running; a source whose format is only known once it runs
 * (the sensor board) fixes them in [start].
 */
interface GestureSource {
    /** What the UI calls this source. */
    val label: String

    /** The channels of every frame, in order. */
    val channels: List<GestureChannel>

    /** Frames per second. */
    val sampleRate: Double

    /** Whether frames are being delivered. */
    val running: Boolean

    /** Starts delivering frames to [sink]; [IllegalStateException] with a message for the user when it cannot. */
    fun start(sink: GestureSink)

    /** Stops delivering; no frame arrives after this returns. Stopping a stopped source does nothing. */
    fun stop()
}

/**
 * Turns irregular, time-stamped readings (touch events, sensor events) into frames at a fixed
 * [sampleRate] by zero-order hold: frame k is at `start + k / sampleRate` and holds the newest reading at
 * or before it. [update] and [advanceTo] emit every frame strictly before the given time to [sink];
 * times only move forward (a reading older than the frames already emitted counts as arriving now).
 * Not thread-safe: one thread drives it.
 */
class ZeroOrderHold(val sampleRate: Double, channelCount: Int, private val sink: GestureSink) {
    init {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(channelCount >= 1) { "need at least one channel, was $channelCount" }
    }

    private val held = DoubleArray(channelCount)
    private val out = DoubleArray(channelCount)
    private val stepNanos = 1e9 / sampleRate
    private var startNanos = 0L
    private var frame = 0L
    private var started = false

    /** Frames emitted since [start]. */
    val framesEmitted: Long get() = frame

    /** Begins the frame grid at [timeNanos] holding [initial] (zeros by default); forgets anything before. */
    fun start(timeNanos: Long, initial: DoubleArray? = null) {
        startNanos = timeNanos
        frame = 0
        started = true
        if (initial == null) held.fill(0.0) else initial.copyInto(held, 0, 0, held.size)
    }

    /** The reading [values] taken at [timeNanos]: frames before it get the previous reading, frames from it on this one. Starts the grid at the first reading. */
    fun update(timeNanos: Long, values: DoubleArray) {
        require(values.size == held.size) { "expected ${held.size} values, got ${values.size}" }
        if (!started) start(timeNanos, values) else advanceTo(timeNanos)
        values.copyInto(held)
    }

    /** Emits every frame strictly before [timeNanos] with the held reading (nothing before [start] or the first [update]). */
    fun advanceTo(timeNanos: Long) {
        if (!started) return
        while (true) {
            val at = startNanos + (frame * stepNanos).toLong()
            if (at >= timeNanos) return
            held.copyInto(out)
            sink.onFrame(out)
            frame++
        }
    }
}
