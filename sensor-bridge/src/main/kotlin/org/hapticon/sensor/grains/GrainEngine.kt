package org.hapticon.sensor.grains

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.live.FrameListener
import org.hapticon.sensor.live.LiveFrame
import org.hapticon.sensor.live.StreamInfo
import org.hapticon.sensor.protocol.framed.ChannelUnit

/**
 * Where the grain engine's bursts go: the phone's vibrator in the app, a recorder in tests. Called on
 * the sensor's reading thread, at most once per grain; must not block.
 */
public fun interface GrainSink {
    /**
     * Plays [waveform] (an [LraGrain] burst) once.
     * @throws RuntimeException (e.g. a safety limit) when it refuses; the engine then turns the mode off.
     */
    public fun play(waveform: VibrationWaveform)
}

/** How a channel's value becomes a force in newtons. */
public enum class ForceInput(public val label: String) {
    /** ADC counts of an Interlink 402 divider (FSR to the supply, 10 kΩ to ground, 5 V). */
    FSR_ADC("FSR, ADC counts"),

    /** The same divider's output in millivolts. */
    FSR_MILLIVOLTS("FSR, millivolts"),

    /** Already newtons. */
    NEWTONS("Newtons"),

    /** Grams (a calibrated load cell or FSR). */
    GRAMS("Grams"),

    /** Millinewtons. */
    MILLINEWTONS("Millinewtons"),
    ;

    public companion object {
        /** What a framed channel of [unit] carries; null if not a force. */
        public fun forUnit(unit: ChannelUnit): ForceInput? = when (unit) {
            ChannelUnit.RAW -> FSR_ADC
            ChannelUnit.MILLIVOLT -> FSR_MILLIVOLTS
            ChannelUnit.GRAM -> GRAMS
            ChannelUnit.MILLINEWTON -> MILLINEWTONS
            ChannelUnit.CENTIDEGREE, ChannelUnit.UNKNOWN -> null
        }
    }
}

/**
 * The FSR grain mode: which [channel] is the force, how it reads ([input]; null takes it from a
 * framed channel's unit and otherwise assumes FSR ADC counts; [adcBits] for counts),
 * the grain [settings], the burst [amplitude] and the sample rate to assume when the board does not
 * announce one ([fallbackSampleRateHz]; framed boards announce theirs).
 */
public data class GrainConfig(
    val channel: Int,
    val input: ForceInput? = null,
    val adcBits: Int = 10,
    val settings: GrainSettings = GrainSettings(),
    val amplitude: Int = 255,
    val fallbackSampleRateHz: Double = 100.0,
) {
    init {
        require(channel >= 0) { "channel must be >= 0, was $channel" }
        require(adcBits in 8..16) { "adcBits must be in 8..16, was $adcBits" }
        require(fallbackSampleRateHz > 0 && fallbackSampleRateHz.isFinite()) { "sample rate must be > 0" }
    }

    /** The burst played per grain; its constructor checks the safety limits. */
    public val grain: LraGrain get() = LraGrain(settings.grainSeconds, amplitude)
}

/** What the grain mode is doing, for the UI. */
public data class GrainStatus(
    val enabled: Boolean = false,
    val grainsPlayed: Long = 0,
    /** The sample rate the decider runs at, once a frame arrived. */
    val sampleRateHz: Double? = null,
    /** Why it stopped, if a safety limit or bad setting stopped it. */
    val error: String? = null,
)

/**
 * Compliance grains from a force channel ([GrainConfig]): each frame's force goes through
 * sensor-bridge's [GrainDecider] (low-pass, bins, at most one grain at a time: a grain lasts
 * round(grainSeconds·fs) samples and no other starts meanwhile), and each grain is played once as an
 * [LraGrain] burst on [output] (the app's vibrator). Runs on the sensor's reading thread and allocates nothing per sample
 * (the burst's waveform is rendered once per configuration).
 */
public class GrainEngine(private val output: GrainSink) : FrameListener {
    private val lock = Any()
    private val fsr = FsrForceConverter()
    private val mutableStatus = MutableStateFlow(GrainStatus())

    private var config: GrainConfig? = null
    private var decider: GrainDecider? = null
    private var waveform: VibrationWaveform? = null
    private var deciderRate = 0.0
    private var played = 0L

    /** What the grain mode is doing. [GrainStatus.grainsPlayed] is updated at most per grain. */
    public val status: StateFlow<GrainStatus> = mutableStatus.asStateFlow()

    /** The configuration in force, or null while the mode is off (the recorder reads its calibrated force range). */
    public val currentConfig: GrainConfig? get() = synchronized(lock) { config }

    /** Grains played since the mode was last configured; cheap to poll. */
    public val grainsPlayed: Long get() = synchronized(lock) { played }

    /** Turns the mode on with [newConfig], or off with null. A new configuration starts afresh. */
    public fun configure(newConfig: GrainConfig?) {
        synchronized(lock) {
            if (newConfig == config) return
            config = newConfig
            decider = null
            played = 0
            waveform = try {
                newConfig?.grain?.waveform()
            } catch (e: IllegalArgumentException) {
                config = null
                mutableStatus.value = GrainStatus(enabled = false, error = e.message)
                return
            }
            mutableStatus.value = GrainStatus(enabled = newConfig != null)
        }
    }

    override fun onFrame(frame: LiveFrame, info: StreamInfo) {
        synchronized(lock) {
            val cfg = config ?: return
            if (cfg.channel >= frame.channelCount) return
            val rate = info.sampleRateHz?.toDouble() ?: cfg.fallbackSampleRateHz
            var current = decider
            if (current == null || rate != deciderRate) {
                current = GrainDecider(cfg.settings, rate)
                decider = current
                deciderRate = rate
                mutableStatus.value = mutableStatus.value.copy(sampleRateHz = rate)
            }
            val bits = info.adcBits ?: cfg.adcBits
            val unit = info.channelUnits?.getOrNull(cfg.channel)
            val input = cfg.input ?: if (unit == null) ForceInput.FSR_ADC else ForceInput.forUnit(unit)
            val newtons = if (input == null) Double.NaN else newtonsOf(frame[cfg.channel], input, bits)
            if (current.offer(newtons)) {
                try {
                    output.play(waveform ?: return)
                } catch (e: RuntimeException) {
                    // A refused effect (safety limit) turns the mode off; the stream goes on.
                    config = null
                    decider = null
                    mutableStatus.value = GrainStatus(enabled = false, grainsPlayed = played, error = e.message ?: e.javaClass.simpleName)
                    return
                }
                played++
                mutableStatus.value = mutableStatus.value.copy(grainsPlayed = played)
            }
        }
    }

    private fun newtonsOf(value: Double, input: ForceInput, adcBits: Int): Double = when (input) {
        ForceInput.NEWTONS -> value
        ForceInput.GRAMS -> value * NEWTONS_PER_GRAM
        ForceInput.MILLINEWTONS -> value / 1000.0
        ForceInput.FSR_MILLIVOLTS -> fsrNewtons(value / 1000.0)
        ForceInput.FSR_ADC -> {
            val full = ((1 shl adcBits) - 1).toDouble()
            if (value < 0 || value > full) Double.NaN else fsrNewtons(value / full * fsr.supplyVolts)
        }
    }

    // A fault is NaN: skipped and counted by the decider.
    private fun fsrNewtons(volts: Double): Double = fsr.newtonsOrNaN(volts)

    private companion object {
        const val NEWTONS_PER_GRAM = 0.00980665
    }
}
