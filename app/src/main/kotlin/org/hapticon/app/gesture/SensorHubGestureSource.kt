package org.hapticon.app.gesture

import java.io.Closeable
import org.hapticon.sensor.live.ConnectionState
import org.hapticon.sensor.live.FrameListener
import org.hapticon.sensor.live.SensorSession

/**
 * The sensor board stream the Sensors tab connected (FSR, glove) as a gesture source: every decoded frame
 * is passed on unchanged, on the hub's reading thread. The channels are the stream's (names made safe
 * for CSV headers) and the rate is the board's declared rate, else the rate measured over the last
 * second — both fixed when recording starts, so connect and let it stream for a second first.
 */
class SensorHubGestureSource(private val hub: SensorSession) : GestureSource {
    // Held while a frame is delivered and while stopping, so no frame arrives after stop() returns.
    private val lock = Any()
    private var subscription: Closeable? = null
    private var format: Pair<List<GestureChannel>, Double>? = null

    override val label: String get() = "Sensor board"
    override val channels: List<GestureChannel> get() = format?.first ?: currentFormat()?.first.orEmpty()
    override val sampleRate: Double get() = format?.second ?: currentFormat()?.second ?: 0.0

    @Volatile override var running: Boolean = false
        private set

    /** The stream's channels and rate now, or null while nothing is streaming or the rate is not known yet. */
    private fun currentFormat(): Pair<List<GestureChannel>, Double>? {
        if (hub.state.value !is ConnectionState.Streaming) return null
        val snapshot = hub.snapshot()
        val info = snapshot.info ?: return null
        if (info.channelCount == 0) return null
        val rate = info.sampleRateHz?.toDouble() ?: snapshot.measuredRateHz ?: return null
        // The board's values are raw (ADC counts, newtons): their full scale is not known here.
        return safeNames(info.channelNames).map { GestureChannel(it, fullScale = null) } to rate
    }

    override fun start(sink: GestureSink) {
        check(!running) { "the sensor board is already recording" }
        val (names, rate) = currentFormat()
            ?: throw IllegalStateException("No sensor board is streaming: connect one in the Sensors tab and let it run for a second")
        format = names to rate
        val values = DoubleArray(names.size)
        running = true
        subscription = hub.addFrameListener(
            FrameListener { frame, _ ->
                synchronized(lock) {
                    if (!running) return@FrameListener
                    // A frame with fewer channels than the header (a short CSV line) leaves the rest at 0.
                    val n = minOf(frame.channelCount, values.size)
                    for (i in 0 until n) values[i] = frame.values[i]
                    for (i in n until values.size) values[i] = 0.0
                    sink.onFrame(values)
                }
            },
        )
    }

    override fun stop() {
        synchronized(lock) { running = false }
        subscription?.close()
        subscription = null
        format = null
    }

    companion object {
        /** [names] with anything but letters, digits and `_` replaced by `_`, blank ones numbered and duplicates suffixed: valid, unique CSV columns. */
        fun safeNames(names: List<String>): List<String> {
            val used = HashSet<String>()
            return names.mapIndexed { i, raw ->
                val base = raw.trim().replace(Regex("[^A-Za-z0-9_]"), "_").ifEmpty { "ch$i" }
                var name = base
                var k = 2
                while (!used.add(name)) name = "${base}_${k++}"
                name
            }
        }
    }
}
