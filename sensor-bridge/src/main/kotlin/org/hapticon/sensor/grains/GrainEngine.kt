package org.hapticon.sensor.grains

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.framed.ChannelUnit
import java.util.concurrent.atomic.AtomicReference

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

/** What the grain mode is doing, for the UI; changes only when the mode is configured, stops or changes rate. */
public data class GrainStatus(
    val enabled: Boolean = false,
    /**
     * The sample rate the decider runs at: the stream's announced rate if one was seen when the mode was
     * configured, else the fallback; updated if a frame later announces another.
     */
    val sampleRateHz: Double? = null,
    /** Why it stopped, if a safety limit or bad setting stopped it. */
    val error: String? = null,
)

/**
 * Compliance grains from a force channel ([GrainConfig]): each frame's force goes through
 * sensor-bridge's [GrainDecider] (low-pass, bins, at most one grain at a time: a grain lasts
 * round(grainSeconds·fs) samples and no other starts meanwhile), and each grain is played once as an
 * [LraGrain] burst on [output] (the app's vibrator).
 *
 * Runs on the sensor's reading thread with no lock and no allocation per frame or per grain: [configure]
 * (any thread) builds the whole run — decider, rendered burst — and publishes it through one atomic
 * reference; the reading thread is the only writer of the decider and of the grain count, which the UI
 * samples ([grainsPlayed], a volatile read) instead of being woken per grain. [status] changes only on a
 * configuration, a stop or a rate change (so the grain path's worst case is bounded by its own work).
 */
public class GrainEngine(private val output: GrainSink) : FrameListener {
    /** One configuration's state. Only the reading thread offers to [decider] and writes [played]. */
    private class Run(
        val config: GrainConfig?,
        val waveform: VibrationWaveform?,
        val decider: GrainDecider?,
        val rateHz: Double,
        played: Long = 0,
    ) {
        @Volatile var played: Long = played
    }

    private val fsr = FsrForceConverter()
    private val run = AtomicReference(Run(null, null, null, 0.0))
    private val mutableStatus = MutableStateFlow(GrainStatus())

    // Serialises status publication between configure and the reading thread's rare stops and rate changes.
    private val statusLock = Any()

    /** The rate the stream last announced (0 when none), written by the reading thread only when it changes. */
    @Volatile private var announcedRateHz = 0.0

    /** What the grain mode is doing; the grain count is [grainsPlayed], sampled rather than pushed. */
    public val status: StateFlow<GrainStatus> = mutableStatus.asStateFlow()

    /** The configuration in force, or null while the mode is off (the recorder reads its calibrated force range). */
    public val currentConfig: GrainConfig? get() = run.get().config

    /** Grains played since the mode was last configured (kept after a stop); a volatile read, cheap to poll. */
    public val grainsPlayed: Long get() = run.get().played

    /** Turns the mode on with [newConfig], or off with null. A new configuration starts afresh. */
    public fun configure(newConfig: GrainConfig?) {
        synchronized(statusLock) {
            if (newConfig == run.get().config) return
            if (newConfig == null) {
                run.set(Run(null, null, null, 0.0))
                mutableStatus.value = GrainStatus(enabled = false)
                return
            }
            val waveform = try {
                newConfig.grain.waveform()
            } catch (e: IllegalArgumentException) {
                run.set(Run(null, null, null, 0.0))
                mutableStatus.value = GrainStatus(enabled = false, error = e.message)
                return
            }
            // The decider is built here, off the reading thread, at the rate the stream announced if any.
            val rate = announcedRateHz.takeIf { it > 0 } ?: newConfig.fallbackSampleRateHz
            run.set(Run(newConfig, waveform, GrainDecider(newConfig.settings, rate), rate))
            mutableStatus.value = GrainStatus(enabled = true, sampleRateHz = rate)
        }
    }

    override fun onFrame(frame: LiveFrame, info: StreamInfo) {
        val announced = info.sampleRateHz?.toDouble() ?: 0.0
        if (announced != announcedRateHz) announcedRateHz = announced
        var current = run.get()
        val cfg = current.config ?: return
        if (cfg.channel >= frame.channelCount) return
        val rate = if (announced > 0) announced else cfg.fallbackSampleRateHz
        // Cold, once per stream at most: the board announced another rate than the decider was built for.
        if (rate != current.rateHz) current = replace(current, Run(cfg, current.waveform, GrainDecider(cfg.settings, rate), rate, current.played)) ?: return
        val bits = info.adcBits ?: cfg.adcBits
        val unit = info.channelUnits?.getOrNull(cfg.channel)
        val input = cfg.input ?: if (unit == null) ForceInput.FSR_ADC else ForceInput.forUnit(unit)
        val newtons = if (input == null) Double.NaN else newtonsOf(frame[cfg.channel], input, bits)
        if (current.decider!!.offer(newtons)) {
            try {
                output.play(current.waveform!!)
            } catch (e: RuntimeException) {
                // A refused effect (safety limit) turns the mode off; the stream goes on.
                replace(current, Run(null, null, null, 0.0, current.played), e.message ?: e.javaClass.simpleName)
                return
            }
            current.played = current.played + 1
        }
    }

    /**
     * Publishes [next] in place of [current] unless [configure] replaced it meanwhile (then null: the new
     * configuration wins), with its status ([error] set: stopped).
     */
    private fun replace(current: Run, next: Run, error: String? = null): Run? {
        if (!run.compareAndSet(current, next)) return null
        synchronized(statusLock) {
            if (run.get() === next) {
                mutableStatus.value = if (error != null) GrainStatus(enabled = false, error = error) else GrainStatus(enabled = true, sampleRateHz = next.rateHz)
            }
        }
        return next
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
