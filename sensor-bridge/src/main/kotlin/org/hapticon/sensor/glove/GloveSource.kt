package org.hapticon.sensor.glove

import java.io.Closeable
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.map
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.lucid.LucidForceFeedback

/** Hears the glove's thumb and middle flex sensors, on the sensor's reading thread. */
public fun interface GloveListener {
    /**
     * One sample: each finger's divider output in volts (see [FlexDivider]), or NaN when the sample
     * carried no valid value for it (an ADC count out of range, a missing channel).
     */
    public fun onGloveSample(thumbVolts: Double, middleVolts: Double, receivedNanos: Long)
}

/** A flex-sensor glove's thumb and middle finger, whatever board and protocol carry them. */
public interface GloveSource {
    /** Whether a glove stream is running. */
    public val connected: Flow<Boolean>

    /** The voltage divider the flex sensors sit in. */
    public val divider: FlexDivider

    /** Calls [listener] with every sample from now on; close the handle to stop. */
    public fun addListener(listener: GloveListener): Closeable

    /** Whether the glove on the line takes force-feedback commands (a LucidGloves stream does). */
    public val acceptsForceFeedback: Flow<Boolean>

    /**
     * Where force-feedback servo values go: it sends them to the glove and answers true, or answers
     * false when the glove on the line takes none. Callable from the reading thread; never blocks.
     */
    public val forceFeedback: ForceFeedbackSink
}

/**
 * Which channels carry the glove's thumb and middle finger, and the ADC resolution of counts. Null
 * means the protocol's default: LucidGloves thumb A, middle C, 12 bit (ESP32); CSV and framed
 * channels 0 and 1, 10 bit (framed boards announce their resolution).
 */
public data class GloveChannels(val thumb: Int? = null, val middle: Int? = null, val adcBits: Int? = null) {
    public fun thumbFor(@Suppress("UNUSED_PARAMETER") protocol: SensorProtocol): Int = thumb ?: 0
    public fun middleFor(protocol: SensorProtocol): Int = middle ?: if (protocol == SensorProtocol.LUCID_GLOVES) 2 else 1
    public fun adcBitsFor(info: StreamInfo): Int = adcBits ?: info.adcBits ?: info.protocol.assumedAdcBits
}

/**
 * The glove as the [SensorSession]'s stream carries it: the chosen channels' ADC counts (or millivolts,
 * for framed channels in mV) become divider voltages. Channels that already hold angles (framed
 * centidegrees) are not flex-sensor voltages and read as NaN here.
 *
 * Force feedback goes back over the same line as LucidGloves commands (`A<n>B<n>C<n>D<n>E<n>`), and
 * only while a LucidGloves stream runs: CSV and framed boards do not speak that encoding.
 */
public class SessionGloveSource(
    private val session: SensorSession,
    override val divider: FlexDivider = FlexDivider(),
) : GloveSource, FrameListener {
    private val listeners = CopyOnWriteArrayList<GloveListener>()
    private val mutableChannels = MutableStateFlow(GloveChannels())
    private val lastError = MutableStateFlow<String?>(null)
    private var scaleBits = 0
    private var scale: AdcScale? = null

    init {
        session.addFrameListener(this)
    }

    override val connected: Flow<Boolean> = session.state.map { it is SessionState.Streaming }

    override val acceptsForceFeedback: Flow<Boolean> = session.state.map(::takesForceFeedback)

    override val forceFeedback: ForceFeedbackSink = ForceFeedbackSink { servoValues ->
        takesForceFeedback(session.state.value) && session.send(LucidForceFeedback.encode(servoValues))
    }

    /** Why a glove listener was dropped, if one failed. */
    public val listenerError: StateFlow<String?> = lastError.asStateFlow()

    /** The channel choice; see [GloveChannels]. */
    public val channels: StateFlow<GloveChannels> = mutableChannels.asStateFlow()

    public fun setChannels(channels: GloveChannels) {
        mutableChannels.value = channels
    }

    override fun addListener(listener: GloveListener): Closeable {
        listeners += listener
        return Closeable { listeners -= listener }
    }

    override fun onFrame(frame: LiveFrame, info: StreamInfo) {
        if (listeners.isEmpty()) return
        val choice = mutableChannels.value
        val bits = choice.adcBitsFor(info)
        if (bits != scaleBits) {
            scale = AdcScale(bits.coerceIn(AdcScale.MIN_BITS, AdcScale.MAX_BITS), divider.supplyVolts)
            scaleBits = bits
        }
        val thumb = volts(frame, info, choice.thumbFor(info.protocol))
        val middle = volts(frame, info, choice.middleFor(info.protocol))
        for (listener in listeners) {
            try {
                listener.onGloveSample(thumb, middle, frame.receivedNanos)
            } catch (e: RuntimeException) {
                // One failing screen must not take the glove away from the others.
                listeners -= listener
                lastError.value = e.message ?: e.javaClass.simpleName
            }
        }
    }

    private fun volts(frame: LiveFrame, info: StreamInfo, channel: Int): Double {
        if (channel !in 0 until frame.channelCount) return Double.NaN
        val value = frame[channel]
        return when (info.channelUnits?.getOrNull(channel)) {
            ChannelUnit.MILLIVOLT -> value / 1000.0
            ChannelUnit.CENTIDEGREE, ChannelUnit.GRAM, ChannelUnit.MILLINEWTON, ChannelUnit.UNKNOWN -> Double.NaN
            ChannelUnit.RAW, null -> {
                val adc = scale ?: return Double.NaN
                val counts = value.toInt()
                if (counts.toDouble() != value || !adc.isValid(counts)) Double.NaN else adc.voltsOf(counts)
            }
        }
    }
}

private fun takesForceFeedback(state: SessionState): Boolean =
    state is SessionState.Streaming && state.protocol == SensorProtocol.LUCID_GLOVES
