package org.hapticon.gesture.extraction

import org.hapticon.core.HapticIcon
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import java.util.Locale
import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.log10
import kotlin.math.roundToInt
import kotlin.math.sqrt

/**
 * What the [level][HapticIcon.level] of a fitted icon is relative to. The originating study's levels (stroke
 * 0.3, hit 1.0) say how strong each gesture was, so a fitted level must be measured against a stated
 * reference, not against the gesture's own peak (which makes every icon full strength).
 */
public sealed class LevelReference {
    /**
     * The input's full scale ([Channel.fullScale]): 1.0 for a float WAV, 32767 for PCM16 (both read as 1.0),
     * the sensor's calibrated maximum when the source knows it. The default. Fitting a channel with no known
     * full scale throws, asking for a [Value] or [Strongest].
     */
    public object FullScale : LevelReference() {
        override fun toString(): String = "full scale"
    }

    /** A given amplitude [value] in the channel's units counts as level 1; [label] names it in the fit report. */
    public data class Value(val value: Double, val label: String = "the given reference") : LevelReference() {
        init {
            require(value.isFinite() && value > 0.0) { "reference must be finite and > 0, was $value" }
        }

        override fun toString(): String = "value $value"
    }

    /**
     * The gesture's own envelope peak: level says how the sustain compares with the strongest moment of this
     * recording. A batch uses it through [IconFitter.fitBatch], scaled so the strongest gesture of the batch is 1.
     */
    public object GesturePeak : LevelReference() {
        override fun toString(): String = "gesture peak"
    }
}

/**
 * Settings of [IconFitter.fit]; the defaults suit a vibration WAV or an FSR stream.
 */
public class FitOptions(
    /** Envelope detector; low-pass measured the more accurate (docs/gesture-extraction.md). */
    public val envelope: EnvelopeMethod = EnvelopeMethod.LOWPASS,
    /** Low-pass cutoff in Hz; null picks half the carrier frequency (vibration) or [FORCE_CUTOFF_HZ] (force). */
    public val cutoffHz: Double? = null,
    /** RMS window in seconds; null picks one carrier period (vibration) or [FORCE_RMS_WINDOW_S] (force). */
    public val rmsWindowSeconds: Double? = null,
    /** An onset is a rise through this fraction of the envelope peak... */
    public val onThreshold: Double = 0.5,
    /** ...after the envelope fell below this fraction (hysteresis). */
    public val offThreshold: Double = 0.25,
    /** Onsets closer than this to the previous one are the same repetition. */
    public val minGapSeconds: Double = 0.05,
    /** What the fitted level is relative to. */
    public val levelReference: LevelReference = LevelReference.FullScale,
    /** Name of the fitted icon (1..64 characters). */
    public val name: String = "gesture",
) {
    init {
        require(cutoffHz == null || (cutoffHz.isFinite() && cutoffHz > 0.0)) { "cutoff must be finite and > 0 Hz, was $cutoffHz" }
        require(rmsWindowSeconds == null || (rmsWindowSeconds.isFinite() && rmsWindowSeconds > 0.0)) {
            "RMS window must be finite and > 0 s, was $rmsWindowSeconds"
        }
        require(offThreshold > 0.0 && offThreshold < onThreshold && onThreshold < 1.0) {
            "thresholds must satisfy 0 < off < on < 1, were off=$offThreshold on=$onThreshold"
        }
        require(minGapSeconds.isFinite() && minGapSeconds >= 0.0) { "minimum gap must be finite and >= 0 s, was $minGapSeconds" }
        require(name.isNotBlank() && name.length <= HapticIcon.MAX_NAME_LENGTH) { "icon name must be 1..${HapticIcon.MAX_NAME_LENGTH} characters, was '$name'" }
    }

    /** These options with [reference] as the level reference. */
    public fun withReference(reference: LevelReference): FitOptions =
        FitOptions(envelope, cutoffHz, rmsWindowSeconds, onThreshold, offThreshold, minGapSeconds, reference, name)

    public companion object {
        /** Default low-pass cutoff for a force signal: keeps a 20 ms tap's ramps, drops tremor and mains hum. */
        public const val FORCE_CUTOFF_HZ: Double = 20.0
        /** Default RMS window for a force signal. */
        public const val FORCE_RMS_WINDOW_S: Double = 0.025
    }
}

/**
 * Extracts a [HapticIcon] from a gesture recording:
 * 1. the dominant frequency (Hann-windowed FFT) decides vibration carrier or force signal and gives the note;
 * 2. the envelope ([EnvelopeMethod]) with its noise floor removed;
 * 3. onsets by hysteresis thresholds relative to the envelope peak → count and period (median spacing);
 * 4. the repetitions aligned on their onsets and averaged, and a [Trapezoid] fitted to the average →
 *    attack, sustain, level, release.
 */
public object IconFitter {
    /** Below this dominant frequency a channel has no carrier and counts as [SignalKind.FORCE]. */
    public const val CARRIER_MIN_HZ: Double = 20.0
    /** Fewest samples a recording needs. */
    public const val MIN_SAMPLES: Int = 16
    /** Reported SNR cap: a noise-free synthetic signal would otherwise be infinite. */
    public const val MAX_SNR_DB: Double = 120.0
    /** Longest span the FFT looks at, around the strongest part (2^20 samples, 24 s at 44.1 kHz). */
    public const val MAX_FFT_SPAN: Int = 1 shl 20

    /**
     * Fits the channel [channelName] of [recording] (default: the first). Throws [NoGestureException] when
     * it is too short, silent or constant, [IllegalArgumentException] when the channel is missing or holds a
     * non-finite sample.
     */
    public fun fit(recording: Recording, channelName: String? = null, options: FitOptions = FitOptions()): IconFit {
        return fit(recording.requireChannel(channelName), recording.sampleRate, options)
    }

    /**
     * Fits a batch of [recordings] of one sensor so that their levels compare: each gesture's envelope peak
     * ([FitReport.envelopePeak], in the channel's units) is measured first, and the largest — the strongest
     * gesture of the batch — is the reference every level is relative to (its icon's peak is level 1, a gesture
     * half as strong fits about half its level). [FitOptions.levelReference] is ignored. Throws as [fit] does,
     * and [IllegalArgumentException] for an empty batch.
     */
    public fun fitBatch(recordings: List<Recording>, channelName: String? = null, options: FitOptions = FitOptions()): List<IconFit> {
        require(recordings.isNotEmpty()) { "a batch needs at least one recording" }
        val peaks = recordings.map { fit(it, channelName, options.withReference(LevelReference.GesturePeak)).report.envelopePeak }
        val strongest = LevelReference.Value(peaks.max(), "the strongest gesture of the batch of ${recordings.size}")
        return recordings.map { fit(it, channelName, options.withReference(strongest)) }
    }

    /**
     * The envelope [fit] works on for [samples] at [sampleRate]: the [FitOptions.envelope] detector, scaled to
     * amplitude (a sine of amplitude A gives A), noise floor removed (vibration) or rest value subtracted
     * (force). Throws as [fit] does.
     */
    public fun envelope(samples: DoubleArray, sampleRate: Double, options: FitOptions = FitOptions(), name: String = "samples"): DoubleArray {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        val frequency = checkGesture(samples, sampleRate, name)
        return envelope(samples, sampleRate, kindOf(frequency), frequency, options).first
    }

    /** Throws unless [x] can hold a gesture; returns its dominant frequency. */
    private fun checkGesture(x: DoubleArray, rate: Double, name: String): Double {
        val n = x.size
        if (n < MIN_SAMPLES) throw NoGestureException("the recording has $n sample(s), too short to hold one (need at least $MIN_SAMPLES)")
        val bad = x.indexOfFirst { !it.isFinite() }
        require(bad < 0) { "channel $name has a non-finite sample (${x[bad]}) at index $bad (${format(bad / rate)} s)" }
        var min = x[0]
        var max = x[0]
        for (v in x) { if (v < min) min = v; if (v > max) max = v }
        if (max - min <= 1e-9 * maxOf(1.0, abs(max), abs(min))) {
            throw NoGestureException(if (max == 0.0 && min == 0.0) "channel $name is all zeros" else "channel $name is constant at ${format(min)}")
        }
        val (from, to) = fftSpan(x)
        return Spectrum.dominantFrequency(x, rate, from, to)
    }

    private fun kindOf(frequency: Double) = if (frequency >= CARRIER_MIN_HZ) SignalKind.VIBRATION else SignalKind.FORCE

    private fun fit(channel: Channel, rate: Double, options: FitOptions): IconFit {
        val x = channel.toDoubleArray()
        val frequency = checkGesture(x, rate, channel.name)
        val kind = kindOf(frequency)
        val warnings = ArrayList<String>()
        val (envelope, setting) = envelope(x, rate, kind, frequency, options)

        var peak = 0.0
        for (v in envelope) if (v > peak) peak = v
        if (!(peak > 0.0)) throw NoGestureException("channel ${channel.name} has no envelope above its noise floor")

        val anchors = onsetCrossings(envelope, peak, options, rate)
        if (anchors.isEmpty()) throw NoGestureException("channel ${channel.name} never rises above ${options.onThreshold} of its peak")
        val window = RepetitionWindow.of(envelope, anchors, peak)
        val average = window.average(envelope, anchors)
        val trapezoid = PiecewiseLinearFit.fit(average)
        val onsets = anchors.map { (it - window.before + trapezoid.start) / rate }

        val attack = (trapezoid.attackEnd - trapezoid.start) / rate
        val sustain = (trapezoid.sustainEnd - trapezoid.attackEnd) / rate
        val release = (trapezoid.releaseEnd - trapezoid.sustainEnd) / rate
        val period = if (anchors.size > 1) median(anchors.zipWithNext { a, b -> (b - a).toDouble() }) / rate else 0.0
        val gesturePeak = robustPeak(average, trapezoid)
        val (reference, referenceHow) = when (val chosen = options.levelReference) {
            is LevelReference.GesturePeak -> gesturePeak to "the gesture's envelope peak ${format(gesturePeak)}"
            is LevelReference.Value -> chosen.value to "${chosen.label} ${format(chosen.value)}${unitSuffix(channel.unit)}"
            is LevelReference.FullScale -> {
                val fullScale = channel.fullScale ?: throw IllegalArgumentException(
                    "channel ${channel.name} is in ${channel.unit.ifEmpty { "unknown units" }} with no known full scale: " +
                        "give a reference (--reference VALUE, e.g. the sensor's calibrated maximum, or --reference strongest)",
                )
                fullScale to "the input's full scale ${format(fullScale)}${unitSuffix(channel.unit)}"
            }
        }
        val level = trapezoid.level / reference
        val note: Int
        val noteHow: String
        if (kind == SignalKind.VIBRATION) {
            note = Spectrum.noteOf(frequency, rate)
            noteHow = "carrier ${format(frequency)} Hz (Hann FFT, parabolic peak) → round(69 + 12·log2(f/440))"
        } else {
            val firmness = ForceNote.firmnessOf(gesturePeak, channel.unit) ?: 0.5.also {
                warnings += "force scale of unit '${channel.unit}' unknown: firmness taken as 0.5 for the note"
            }
            note = ForceNote.note(firmness, attack + sustain + release)
            noteHow = "force mapping: firmness ${format(firmness)}, contact ${format(attack + sustain + release)} s (no carrier: dominant ${format(frequency)} Hz < $CARRIER_MIN_HZ Hz)"
        }
        clipping(x, channel.unit, warnings)

        val measured = Measured(attack, sustain, level, release, note, period, anchors.size)
        val (icon, parameters) = SafeIcon.build(measured, options.name, warnings, how(setting, options, anchors.size, noteHow, referenceHow))
        val report = FitReport(
            channel = channel.name,
            sampleRate = rate,
            kind = kind,
            dominantFrequencyHz = frequency,
            envelopeMethod = options.envelope,
            envelopeSetting = setting,
            envelopePeak = gesturePeak,
            levelReference = referenceHow,
            levelReferenceValue = reference,
            parameters = parameters,
            onsets = onsets,
            fitRmsError = trapezoid.rmsError / gesturePeak,
            rSquared = trapezoid.rSquared,
            snrDb = snr(x, kind, envelope, peak, onsets, attack + sustain + release, rate),
            warnings = warnings,
        )
        return IconFit(icon, report)
    }

    private fun unitSuffix(unit: String) = if (unit.isEmpty()) "" else " $unit"

    private fun how(setting: String, options: FitOptions, count: Int, noteHow: String, referenceHow: String): Map<String, String> = mapOf(
        "attack" to "trapezoid fit (segmented least squares) of the ${if (count > 1) "average of $count aligned repetitions" else "one repetition"}; $setting",
        "sustain" to "trapezoid fit: attack end to sustain end",
        "level" to "trapezoid sustain amplitude relative to $referenceHow",
        "release" to "trapezoid fit: sustain end to release end",
        "note" to noteHow,
        "period" to if (count > 1) "median onset-to-onset time" else "one repetition: 0",
        "count" to "onsets (rise through ${options.onThreshold} of peak after falling below ${options.offThreshold}, ≥ ${options.minGapSeconds} s apart)",
    )

    /**
     * The gesture's peak: the [PEAK_PERCENTILE] of the averaged repetition over the fitted span, at least the
     * fitted level. A plain maximum would be the largest noise excursion; this keeps any peak lasting 1 % of
     * the repetition (a tap's impact before a hold) and reads a flat noisy sustain only ~2σ high.
     */
    private fun robustPeak(average: DoubleArray, trapezoid: Trapezoid): Double {
        val from = trapezoid.start
        val to = maxOf(trapezoid.releaseEnd, from + 1).coerceAtMost(average.size)
        val span = average.copyOfRange(minOf(from, to - 1), to)
        return maxOf(trapezoid.level, percentile(span, PEAK_PERCENTILE))
    }

    private const val PEAK_PERCENTILE = 0.99

    /** The span the FFT reads: the whole channel, or [MAX_FFT_SPAN] samples centred on the largest deviation from the first sample. */
    private fun fftSpan(x: DoubleArray): Pair<Int, Int> {
        if (x.size <= MAX_FFT_SPAN) return 0 to x.size
        var at = 0
        for (i in x.indices) if (abs(x[i] - x[0]) > abs(x[at] - x[0])) at = i
        val from = (at - MAX_FFT_SPAN / 2).coerceIn(0, x.size - MAX_FFT_SPAN)
        return from to from + MAX_FFT_SPAN
    }

    private fun envelope(x: DoubleArray, rate: Double, kind: SignalKind, frequency: Double, options: FitOptions): Pair<DoubleArray, String> {
        val vibration = kind == SignalKind.VIBRATION
        val envelope: DoubleArray
        val setting: String
        when (options.envelope) {
            EnvelopeMethod.LOWPASS -> {
                // Half the carrier: the rectified ripple at 2f is then 4 octaves up, −48 dB after both passes.
                val cutoff = minOf(options.cutoffHz ?: if (vibration) frequency / 2.0 else FitOptions.FORCE_CUTOFF_HZ, 0.45 * rate)
                envelope = Envelopes.lowpass(x, rate, cutoff, rectify = vibration)
                if (vibration) for (i in envelope.indices) envelope[i] *= PI / 2.0
                setting = "full-wave rectified, 2nd-order Butterworth low-pass at ${format(cutoff)} Hz, forward-backward".let {
                    if (vibration) it else "2nd-order Butterworth low-pass at ${format(cutoff)} Hz, forward-backward (no rectification: force)"
                }
            }
            EnvelopeMethod.RMS -> {
                // One carrier period holds two whole ripple cycles of x², so the moving mean cancels them.
                val seconds = options.rmsWindowSeconds ?: if (vibration) 1.0 / frequency else FitOptions.FORCE_RMS_WINDOW_S
                val samples = (seconds * rate).roundToInt().coerceIn(1, x.size)
                envelope = if (vibration) Envelopes.rms(x, samples) else Envelopes.rms(x.copyOf().also { centre(it, rate) }, samples)
                if (vibration) for (i in envelope.indices) envelope[i] *= sqrt(2.0)
                setting = "moving RMS over $samples samples (${format(samples / rate)} s)"
            }
        }
        val floor = quietest(envelope, rate)
        if (vibration) {
            // Noise adds power: take the quiet floor's power off every sample (never below 0).
            for (i in envelope.indices) envelope[i] = sqrt(maxOf(0.0, envelope[i] * envelope[i] - floor * floor))
        } else {
            for (i in envelope.indices) envelope[i] = maxOf(0.0, envelope[i] - floor)
        }
        return envelope to setting
    }

    // A force RMS around the rest value, not around zero: a resting FSR reads a small offset.
    private fun centre(x: DoubleArray, rate: Double) {
        val rest = quietest(x, rate)
        for (i in x.indices) x[i] = maxOf(0.0, x[i] - rest)
    }

    /**
     * The noise floor (vibration) or rest value (force): the lowest mean over [QUIET_BLOCK_S] blocks. Any one
     * quiet moment of the recording is enough, however short the silence is relative to the gesture; a
     * recording with none gets its gesture's lowest level, which is then treated as rest.
     */
    private fun quietest(values: DoubleArray, rate: Double): Double {
        val block = (QUIET_BLOCK_S * rate).roundToInt().coerceIn(1, maxOf(1, values.size / 8))
        var lowest = Double.MAX_VALUE
        var from = 0
        while (from + block <= values.size) {
            var sum = 0.0
            for (i in from until from + block) sum += values[i]
            lowest = minOf(lowest, sum / block)
            from += block
        }
        return lowest
    }

    /** Block length of [quietest]. */
    private const val QUIET_BLOCK_S = 0.02

    /** Envelope indices where a repetition rises through the on-threshold after falling below the off-threshold. */
    private fun onsetCrossings(envelope: DoubleArray, peak: Double, options: FitOptions, rate: Double): List<Int> {
        val on = options.onThreshold * peak
        val off = options.offThreshold * peak
        val minGap = (options.minGapSeconds * rate).roundToInt()
        val anchors = ArrayList<Int>()
        var armed = true
        for (i in envelope.indices) {
            val v = envelope[i]
            if (armed && v >= on) {
                if (anchors.isEmpty() || i - anchors.last() >= minGap) anchors += i
                armed = false
            } else if (!armed && v < off) {
                armed = true
            }
        }
        return anchors
    }

    private fun snr(x: DoubleArray, kind: SignalKind, envelope: DoubleArray, peak: Double, onsets: List<Double>, length: Double, rate: Double): Double? {
        val offset = if (kind == SignalKind.VIBRATION) x.average() else quietest(x, rate)
        var quietPower = 0.0
        var quiet = 0L
        val active = BooleanArray(x.size)
        for (onset in onsets) {
            val from = (onset * rate).roundToInt().coerceIn(0, x.size)
            val to = ((onset + length) * rate).roundToInt().coerceIn(from, x.size)
            for (i in from until to) active[i] = true
        }
        var activePower = 0.0
        var activeCount = 0L
        for (i in x.indices) {
            val d = x[i] - offset
            if (active[i]) {
                activePower += d * d
                activeCount++
            } else if (envelope[i] <= QUIET_FRACTION * peak) {
                quietPower += d * d
                quiet++
            }
        }
        if (quiet == 0L || activeCount == 0L) return null
        val noise = quietPower / quiet
        val signal = activePower / activeCount - noise
        if (noise <= 0.0) return MAX_SNR_DB
        if (signal <= 0.0) return -MAX_SNR_DB
        return minOf(MAX_SNR_DB, 10.0 * log10(signal / noise))
    }

    /** Envelope below this fraction of the peak is quiet (noise only) for the SNR estimate. */
    private const val QUIET_FRACTION = 0.02

    /**
     * A clipped signal sits on full scale for runs of equal samples; a full-scale sine only touches it, so
     * count samples at |x| >= [CLIP_LEVEL] equal to their predecessor.
     */
    private fun clipping(x: DoubleArray, unit: String, warnings: MutableList<String>) {
        if (unit.isNotEmpty()) return
        var clipped = 0
        for (i in 1 until x.size) if (abs(x[i]) >= CLIP_LEVEL && x[i] == x[i - 1]) clipped++
        if (clipped >= maxOf(10, x.size / 1000)) {
            warnings += "saturated: $clipped samples held at full scale (|x| >= $CLIP_LEVEL); level and shape are underestimated"
        }
    }

    private const val CLIP_LEVEL = 0.999
}

/** The seven measured parameters before clamping. */
internal class Measured(
    val attack: Double, val sustain: Double, val level: Double, val release: Double,
    val note: Int, val period: Double, val count: Int,
)

/** The icon from measured values, clamped into [HapticIcon]'s safe ranges with one warning per clamp. */
internal object SafeIcon {
    fun build(m: Measured, name: String, warnings: MutableList<String>, how: Map<String, String>): Pair<HapticIcon, List<ParameterFit>> {
        val level = m.level.coerceIn(0.0, 1.0)
        // A level a hair above 1 is filter ripple on a full-scale sustain, not worth a warning.
        if (abs(level - m.level) > LEVEL_ROUNDING) warnings += "level ${format(m.level)} clamped to ${format(level)}"
        var count = minOf(m.count, HapticIcon.MAX_COUNT)
        if (count != m.count) warnings += "count ${m.count} clamped to ${HapticIcon.MAX_COUNT}"
        var attack = m.attack
        var sustain = m.sustain
        var release = m.release
        val cap = HapticIcon.MAX_DURATION_SECONDS
        if (count > 1 && (count - 1) * m.period + attack + sustain + release > cap) {
            val fits = ((cap - (attack + sustain + release)) / m.period).toInt() + 1
            val reduced = fits.coerceIn(1, count)
            warnings += "count $count clamped to $reduced to stay within the $cap s duration cap"
            count = reduced
        }
        if (attack + sustain + release > cap) {
            // Shorten the sustain first: it is the part a long hold stretches.
            sustain = maxOf(0.0, cap - attack - release)
            if (attack + sustain + release > cap) {
                val scale = cap / (attack + release)
                attack *= scale
                release *= scale
            }
            warnings += "envelope ${format(m.attack + m.sustain + m.release)} s clamped to the $cap s duration cap"
        }
        val period = if (count > 1) m.period else 0.0
        val icon = HapticIcon(name, attack, sustain, level, release, m.note.toDouble(), period, count)
        val parameters = listOf(
            ParameterFit("attack", attack, m.attack, how.getValue("attack")),
            ParameterFit("sustain", sustain, m.sustain, how.getValue("sustain")),
            ParameterFit("level", level, m.level, how.getValue("level")),
            ParameterFit("release", release, m.release, how.getValue("release")),
            ParameterFit("note", m.note.toDouble(), m.note.toDouble(), how.getValue("note")),
            ParameterFit("period", period, m.period, how.getValue("period")),
            ParameterFit("count", count.toDouble(), m.count.toDouble(), how.getValue("count")),
        )
        return icon to parameters
    }

    private const val LEVEL_ROUNDING = 0.005
}

/**
 * Where the repetitions are cut out for averaging: from [before] samples before each onset crossing, each
 * up to the next repetition's window (the last one up to the end of the recording), [length] samples at most.
 * [cleanFrom] is, per repetition, the window index from which it is its own (0, or later when it starts
 * inside the previous one's release).
 */
internal class RepetitionWindow(val before: Int, val length: Int, private val cleanFrom: IntArray) {
    /**
     * The mean over the repetitions of [envelope] at each window index. Repetitions that overlap (combined by
     * maximum) are their own only between the trough before them and the next one's window, so each adds just
     * that part: a release longer than the period comes from the last repetition alone, an attack hidden under
     * the previous release from the first.
     */
    fun average(envelope: DoubleArray, anchors: List<Int>): DoubleArray {
        val sum = DoubleArray(length)
        val count = IntArray(length)
        for ((k, anchor) in anchors.withIndex()) {
            val from = anchor - before
            val until = if (k + 1 < anchors.size) anchors[k + 1] - before else envelope.size
            for (j in cleanFrom[k] until minOf(length, until - from)) {
                val i = from + j
                if (i < 0) continue
                sum[j] += envelope[i]
                count[j]++
            }
        }
        for (j in 0 until length) sum[j] = if (count[j] > 0) sum[j] / count[j] else 0.0
        return sum
    }

    companion object {
        /**
         * Reaches back from each crossing while the envelope keeps falling, to where it leaves [START_FRACTION]
         * of the peak (plus 40 % and a margin, for the attack's foot) or to the trough where it starts
         * rising again into the previous repetition's release. The window runs to the end of the recording from
         * the last repetition's start.
         */
        fun of(envelope: DoubleArray, anchors: List<Int>, peak: Double): RepetitionWindow {
            val start = START_FRACTION * peak
            val rise = TROUGH_RISE * peak
            var before = 0
            val troughs = IntArray(anchors.size) { -1 }
            for ((k, anchor) in anchors.withIndex()) {
                var i = anchor
                var lowestAt = anchor
                while (i > 0 && envelope[i - 1] > start && envelope[i - 1] <= envelope[lowestAt] + rise) {
                    i--
                    if (envelope[i] < envelope[lowestAt]) lowestAt = i
                }
                if (i > 0 && envelope[i - 1] > start) troughs[k] = lowestAt else before = maxOf(before, anchor - i)
            }
            // Every walk ended in a trough (a recording that starts mid-release): reach back to the nearest.
            if (troughs.all { it >= 0 }) {
                before = anchors.indices.minOf { anchors[it] - troughs[it] }
                troughs.fill(-1)
            }
            val spacing = anchors.zipWithNext { a, b -> b - a }.minOrNull()
            // The walk stops at 10 % of the peak (lower, noise can end it early on the ramp), not at the
            // attack's start: the foot below is a quarter of the walk on a 50 % crossing, so reach 40 % further.
            before = minOf(before + before * 2 / 5 + MARGIN_SAMPLES, anchors.first(), spacing?.let { it / 2 } ?: Int.MAX_VALUE)
            val cleanFrom = IntArray(anchors.size) { k -> if (troughs[k] < 0) 0 else maxOf(0, troughs[k] - (anchors[k] - before)) }
            val length = maxOf(spacing ?: 0, envelope.size - anchors.last() + before)
            return RepetitionWindow(before, maxOf(2, length), cleanFrom)
        }

        private const val START_FRACTION = 0.1
        /**
         * A backward walk that climbs this fraction of the peak above its lowest point has passed a trough:
         * well above the envelope's noise at 10 dB SNR (~4 % RMS), well below the rise into an overlapping
         * release (stroke's trough is at 20 % of its level).
         */
        private const val TROUGH_RISE = 0.15
        private const val MARGIN_SAMPLES = 16
    }
}

internal fun median(values: List<Double>): Double {
    val sorted = values.sorted()
    val mid = sorted.size / 2
    return if (sorted.size % 2 == 1) sorted[mid] else (sorted[mid - 1] + sorted[mid]) / 2.0
}

/** The [fraction] percentile of [values], from a strided sample of at most 1 Mi values so huge inputs stay cheap. */
internal fun percentile(values: DoubleArray, fraction: Double): Double {
    val stride = maxOf(1, values.size / (1 shl 20))
    val sample = DoubleArray((values.size + stride - 1) / stride) { values[it * stride] }
    sample.sort()
    return sample[((sample.size - 1) * fraction).roundToInt()]
}

internal fun format(value: Double): String = String.format(Locale.ROOT, "%.4g", value)
