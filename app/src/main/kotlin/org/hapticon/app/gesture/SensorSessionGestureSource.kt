package org.hapticon.app.gesture

import org.hapticon.sensor.grains.FsrForceConverter
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.grains.GrainConfig
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.framed.ChannelUnit
import java.io.Closeable
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.sensor.live.SensorSession

/**
 * The sensor board stream the Sensors tab connected (FSR, glove) as a gesture source: every decoded frame
 * is passed on unchanged, on the session's reading thread. The channels are the stream's (names made safe
 * for CSV headers) and the rate is the board's declared rate, else the rate measured over the last
 * second — both fixed when recording starts, so connect and let it stream for a second first.
 *
 * Each channel's full scale ([GestureChannel.fullScale], what a fitted icon's level is measured against) is the
 * sensor's calibrated maximum where it is known ([calibratedMaximum]): the force range the Sensors tab's grain
 * mode is calibrated to ([grains], for its force channel), else a framed board's ADC range for raw channels.
 * Elsewhere it is unknown and the recorder falls back to the gesture's own peak, saying so.
 */
class SensorSessionGestureSource(private val session: SensorSession, private val grains: () -> GrainConfig? = { null }) : GestureSource {
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
        if (session.state.value !is SessionState.Streaming) return null
        val snapshot = session.snapshot()
        val info = snapshot.info ?: return null
        if (info.channelCount == 0) return null
        val rate = info.sampleRateHz?.toDouble() ?: snapshot.measuredRateHz ?: return null
        val grain = grains()
        return safeNames(info.channelNames).mapIndexed { i, name -> GestureChannel(name, fullScale = calibratedMaximum(info, i, grain)) } to rate
    }

    override fun start(sink: GestureSink) {
        check(!running) { "the sensor board is already recording" }
        val (names, rate) = currentFormat()
            ?: throw IllegalStateException("No sensor board is streaming: connect one in the Sensors tab and let it run for a second")
        format = names to rate
        val values = DoubleArray(names.size)
        running = true
        subscription = session.addFrameListener(
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
        private const val GRAMS_PER_NEWTON = 1.0 / 0.00980665

        /**
         * The largest value channel [channel] of a stream described by [info] can hold, in the channel's own unit,
         * or null when nothing states it:
         * - the grain mode's force channel ([grain] on this channel): its calibrated force range's maximum,
         *   [org.hapticon.sensor.grains.GrainSettings.maxNewtons], in the channel's unit (N, g, mN); for an FSR read
         *   as ADC counts or millivolts, the divider's full scale (2^bits − 1 counts, the supply in mV);
         * - a framed board's raw channel: its ADC's 2^adcBits − 1 counts (device info);
         * - anything else (CSV and LucidGloves streams, calibrated framed units without a grain range): null.
         */
        fun calibratedMaximum(info: StreamInfo, channel: Int, grain: GrainConfig?): Double? {
            val unit = info.channelUnits?.getOrNull(channel)
            val bits = info.adcBits
            if (grain != null && grain.channel == channel) {
                val maxNewtons = grain.settings.maxNewtons
                return when (grain.input ?: unit?.let { ForceInput.forUnit(it) } ?: ForceInput.FSR_ADC) {
                    ForceInput.NEWTONS -> maxNewtons
                    ForceInput.GRAMS -> maxNewtons * GRAMS_PER_NEWTON
                    ForceInput.MILLINEWTONS -> maxNewtons * 1000.0
                    ForceInput.FSR_ADC -> ((1 shl (bits ?: grain.adcBits)) - 1).toDouble()
                    ForceInput.FSR_MILLIVOLTS -> FsrForceConverter.DEFAULT_SUPPLY_VOLTS * 1000.0
                }.takeIf { it.isFinite() && it > 0.0 }
            }
            return if (unit == ChannelUnit.RAW && bits != null) ((1 shl bits) - 1).toDouble() else null
        }

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
