package org.hapticon.app.gesture

import android.os.SystemClock
import android.view.MotionEvent
import java.util.concurrent.ConcurrentLinkedQueue
import java.util.concurrent.Executors
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.TimeUnit

/**
 * The phone's touchscreen as a gesture sensor: the touch pad feeds it every [MotionEvent] ([onMotionEvent],
 * main thread) and it delivers [sampleRate] frames per second of [CHANNELS] — pressure (0..1, as the
 * screen reports it), contact size (0..1, [MotionEvent.getSize]) and finger velocity in px/s — by
 * zero-order hold, all 0 while no finger is down. Historical (batched) samples of a move count, so
 * fast strokes keep their shape.
 *
 * Events are queued and replayed on a ticker thread every [tickMillis] ms; the ticker stays [LAG_NANOS]
 * behind the clock so an event that is delivered a little after its time stamp still lands in the right
 * frame. With [autoTick] false nothing ticks and the owner calls [pump] (tests).
 */
class TouchGestureSource(
    override val sampleRate: Double = DEFAULT_RATE_HZ,
    private val clockNanos: () -> Long = { SystemClock.uptimeMillis() * 1_000_000L },
    private val tickMillis: Long = 20,
    private val autoTick: Boolean = true,
) : GestureSource {
    private class Reading(val timeNanos: Long, val values: DoubleArray)

    private val queue = ConcurrentLinkedQueue<Reading>()
    private val lock = Any()
    private var hold: ZeroOrderHold? = null
    private var ticker: ScheduledExecutorService? = null

    // The previous position of the finger, for its velocity; touched on the main thread only.
    private var lastX = 0f
    private var lastY = 0f
    private var lastNanos = 0L
    private var lastVx = 0.0
    private var lastVy = 0.0

    override val label: String get() = "Touchscreen"
    override val channels: List<GestureChannel> get() = CHANNELS

    @Volatile override var running: Boolean = false
        private set

    override fun start(sink: GestureSink) {
        synchronized(lock) {
            check(!running) { "the touchscreen is already recording" }
            queue.clear()
            hold = ZeroOrderHold(sampleRate, CHANNELS.size, sink).also { it.start(clockNanos() - LAG_NANOS) }
            running = true
        }
        if (autoTick) {
            ticker = Executors.newSingleThreadScheduledExecutor { Thread(it, "hapticon-touch").apply { isDaemon = true } }.also {
                it.scheduleWithFixedDelay({ pump(clockNanos() - LAG_NANOS) }, tickMillis, tickMillis, TimeUnit.MILLISECONDS)
            }
        }
    }

    override fun stop() {
        ticker?.let {
            it.shutdown()
            it.awaitTermination(1, TimeUnit.SECONDS)
        }
        ticker = null
        synchronized(lock) {
            running = false
            hold = null
        }
    }

    /** Takes one touch event (any thread, normally main); ignored while not running. */
    fun onMotionEvent(event: MotionEvent) {
        if (!running) return
        when (event.actionMasked) {
            MotionEvent.ACTION_DOWN -> {
                lastX = event.x
                lastY = event.y
                lastNanos = event.eventTime * 1_000_000L
                lastVx = 0.0
                lastVy = 0.0
                queue += Reading(lastNanos, doubleArrayOf(event.pressure.toDouble(), event.size.toDouble(), 0.0, 0.0))
            }
            MotionEvent.ACTION_MOVE -> {
                for (h in 0 until event.historySize) {
                    reading(event.getHistoricalEventTime(h), event.getHistoricalX(h), event.getHistoricalY(h), event.getHistoricalPressure(h), event.getHistoricalSize(h))
                }
                reading(event.eventTime, event.x, event.y, event.pressure, event.size)
            }
            MotionEvent.ACTION_UP, MotionEvent.ACTION_CANCEL -> queue += Reading(event.eventTime * 1_000_000L, DoubleArray(CHANNELS.size))
        }
    }

    private fun reading(timeMillis: Long, x: Float, y: Float, pressure: Float, size: Float) {
        val nanos = timeMillis * 1_000_000L
        // Two samples with one time stamp (possible in a batch) keep the previous velocity instead of dividing by 0.
        if (nanos > lastNanos) {
            val seconds = (nanos - lastNanos) / 1e9
            lastVx = (x - lastX) / seconds
            lastVy = (y - lastY) / seconds
        }
        lastX = x
        lastY = y
        lastNanos = nanos
        queue += Reading(nanos, doubleArrayOf(pressure.toDouble(), size.toDouble(), lastVx, lastVy))
    }

    /** Replays the queued events and emits every frame before [untilNanos] (the ticker's work; public for tests). */
    fun pump(untilNanos: Long) {
        synchronized(lock) {
            val target = hold ?: return
            while (true) {
                val next = queue.poll() ?: break
                target.update(next.timeNanos, next.values)
            }
            target.advanceTo(untilNanos)
        }
    }

    companion object {
        /** 200 Hz: finer than any touchscreen's report rate (60–240 Hz), coarse enough for a 60 s recording. */
        const val DEFAULT_RATE_HZ: Double = 200.0

        /** How far the ticker stays behind the clock: longer than touch events take to reach the app. */
        const val LAG_NANOS: Long = 50_000_000L

        /** The channels delivered, in order. */
        val CHANNELS: List<GestureChannel> = listOf(
            // Pressure and size are normalised by Android (nominally 0..1); a velocity has no full scale.
            GestureChannel("pressure"), GestureChannel("size"), GestureChannel("velocity_x", fullScale = null), GestureChannel("velocity_y", fullScale = null),
        )
    }
}
