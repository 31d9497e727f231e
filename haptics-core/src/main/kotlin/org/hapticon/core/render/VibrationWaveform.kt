package org.hapticon.core.render

import org.hapticon.core.HapticIcon

/**
 * A vibration for Android's `VibrationEffect.createWaveform(timings(), amplitudes(), -1)`: entry i holds the
 * vibrator at amplitude `amplitudes()[i]` (0 = off, 1..255 = on) for `timings()[i]` milliseconds.
 *
 * Every instance satisfies the safety limits, checked when it is built: at least one entry, every timing
 * > 0 ms, every amplitude in 0..255, consecutive entries differ, and the total is at most
 * [HapticIcon.MAX_DURATION_SECONDS].
 *
 * [amplitudeSteps] computes it from an envelope as follows, so the result is easy to predict:
 * 1. The length is the duration rounded to whole milliseconds, T (ties up).
 * 2. Time is cut into steps of [stepMillis]: [0, s), [s, 2s), …; the last step ends at T and may be shorter.
 * 3. The envelope is sampled at the centres of 0.1 ms cells. A step is off (amplitude 0) when every cell in
 *    it is below half an amplitude step (0.5/255); otherwise its amplitude is the mean of its cells × 255,
 *    rounded (ties up) and clamped to 1..255, so that a short pulse never disappears.
 * 4. Consecutive steps of equal amplitude are merged into one entry.
 * 5. If that leaves more than `maxEntries` entries, the step is doubled and the computation repeated.
 *
 * For example knock (0.005/0.01/0.5/0.005 s, period 0.27 s, ×3) at 10 ms steps: each pulse covers two steps
 * whose mean envelope is 0.375, giving timings [20, 250, 20, 250, 20] and amplitudes [96, 0, 96, 0, 96].
 *
 * [fidelity] compares the step function (amplitude / 255) with the ideal envelope on the 0.1 ms cells.
 */
public class VibrationWaveform private constructor(
    private val timingMillis: LongArray,
    private val amplitudeValues: IntArray,
    /** The step length actually used, in milliseconds; larger than requested when entries had to be reduced. */
    public val stepMillis: Int,
    /** How closely the steps follow the ideal envelope. */
    public val fidelity: Fidelity,
) {
    init {
        // The app passes these arrays straight to the vibrator: enforce the limits here, not only in the algorithm.
        check(timingMillis.isNotEmpty() && timingMillis.size == amplitudeValues.size) { "timings and amplitudes must pair up" }
        check(timingMillis.all { it > 0 }) { "every timing must be > 0 ms" }
        check(amplitudeValues.all { it in 0..MAX_AMPLITUDE }) { "every amplitude must be in 0..$MAX_AMPLITUDE" }
        check((1 until amplitudeValues.size).all { amplitudeValues[it] != amplitudeValues[it - 1] }) { "entries must be merged" }
        check(timingMillis.sum() <= HapticIcon.MAX_DURATION_SECONDS * 1000) { "total exceeds the safety cap" }
    }

    /** Number of entries. */
    public val size: Int get() = timingMillis.size

    /** Sum of the timings: the duration rounded to whole milliseconds. */
    public val totalMillis: Long get() = timingMillis.sum()

    /** A fresh copy of the entry durations in milliseconds, each > 0. */
    public fun timings(): LongArray = timingMillis.copyOf()

    /** A fresh copy of the entry amplitudes, each in 0..255 (0 = off). */
    public fun amplitudes(): IntArray = amplitudeValues.copyOf()

    /** A debug representation listing timings, amplitudes and the fidelity. */
    override fun toString(): String =
        "VibrationWaveform(timings=${timingMillis.contentToString()}, amplitudes=${amplitudeValues.contentToString()}, " +
            "stepMillis=$stepMillis, fidelity=$fidelity)"

    public companion object {
        /** Largest amplitude Android accepts. */
        public const val MAX_AMPLITUDE: Int = 255

        /** Default step: Android vibrators update their amplitude every few milliseconds at best. */
        public const val DEFAULT_STEP_MILLIS: Int = 10

        /** Default cap on entries; a 30 s icon at 10 ms steps has at most 3000, so the default never coarsens. */
        public const val DEFAULT_MAX_ENTRIES: Int = 3000

        /**
         * [icon]'s ideal envelope under [model] ([idealEnvelope]) as amplitude steps, by the algorithm described on
         * [VibrationWaveform]; the total equals [HapticIcon.duration] rounded to whole milliseconds.
         *
         * Throws [IllegalArgumentException] when the duration rounds to 0 ms, when [stepMillis] < 1 or when
         * [maxEntries] < 1.
         */
        public fun amplitudeSteps(
            icon: HapticIcon,
            model: EnvelopeModel = EnvelopeModel.DEFAULT,
            stepMillis: Int = DEFAULT_STEP_MILLIS,
            maxEntries: Int = DEFAULT_MAX_ENTRIES,
        ): VibrationWaveform = amplitudeSteps(icon.idealEnvelope(model), icon.duration, stepMillis, maxEntries)

        /**
         * [onOff] for [icon]'s ideal envelope under [model]: full strength where the envelope is at least
         * [threshold] × its peak, off elsewhere.
         *
         * Throws [IllegalArgumentException] as the icon [amplitudeSteps] does, and when [threshold] is not in (0, 1].
         */
        public fun onOff(
            icon: HapticIcon,
            model: EnvelopeModel = EnvelopeModel.DEFAULT,
            threshold: Double = 0.5,
            stepMillis: Int = DEFAULT_STEP_MILLIS,
            maxEntries: Int = DEFAULT_MAX_ENTRIES,
        ): VibrationWaveform = onOff(icon.idealEnvelope(model), icon.duration, threshold, stepMillis, maxEntries)

        /**
         * [envelope] (amplitude in [0, 1] at a time in seconds; values outside are clamped, NaN reads as 0) over
         * [durationSeconds] as amplitude steps, by the algorithm described on [VibrationWaveform].
         *
         * Throws [IllegalArgumentException] when the duration is not finite, rounds to 0 ms or exceeds
         * [HapticIcon.MAX_DURATION_SECONDS], when [stepMillis] < 1 or when [maxEntries] < 1.
         */
        public fun amplitudeSteps(
            envelope: (Double) -> Double,
            durationSeconds: Double,
            stepMillis: Int = DEFAULT_STEP_MILLIS,
            maxEntries: Int = DEFAULT_MAX_ENTRIES,
        ): VibrationWaveform {
            val steps = StepGrid(envelope, durationSeconds, stepMillis, maxEntries)
            return steps.build("amplitude steps") { from, to -> steps.amplitudeOf(from, to) }
        }

        /**
         * Renders [envelope] for a vibrator without amplitude control: full strength (255) during the steps
         * whose mean envelope is at least [threshold] × the envelope's peak, off elsewhere. The threshold is
         * relative to the peak so that a quiet icon still plays (an absolute one would silence it).
         * Steps, merging and the entry cap work as in [amplitudeSteps].
         *
         * Throws [IllegalArgumentException] as [amplitudeSteps] does, and when [threshold] is not in (0, 1].
         */
        public fun onOff(
            envelope: (Double) -> Double,
            durationSeconds: Double,
            threshold: Double = 0.5,
            stepMillis: Int = DEFAULT_STEP_MILLIS,
            maxEntries: Int = DEFAULT_MAX_ENTRIES,
        ): VibrationWaveform {
            require(threshold > 0.0 && threshold <= 1.0) { "threshold must be in (0, 1], was $threshold" }
            val steps = StepGrid(envelope, durationSeconds, stepMillis, maxEntries)
            val onFrom = threshold * steps.peak
            val description = "on/off steps (on at ≥ $threshold of the peak)"
            return steps.build(description) { from, to ->
                // The tolerance keeps a mean that equals the threshold in exact arithmetic from flipping off.
                if (steps.peak > 0.0 && steps.meanOf(from, to) >= onFrom - 1e-12) MAX_AMPLITUDE else 0
            }
        }
    }

    /** The sampled envelope and step bookkeeping shared by [amplitudeSteps] and [onOff]. */
    private class StepGrid(
        envelope: (Double) -> Double,
        durationSeconds: Double,
        private val requestedStepMillis: Int,
        private val maxEntries: Int,
    ) {
        private val ideal: EnvelopeCells
        val totalMillis: Int
        val cells: DoubleArray

        init {
            // The duration is checked first, then the step and the cap: each error names the first bad argument.
            totalMillis = totalMillisOf(durationSeconds)
            require(requestedStepMillis >= 1) { "stepMillis must be >= 1, was $requestedStepMillis" }
            require(maxEntries >= 1) { "maxEntries must be >= 1, was $maxEntries" }
            ideal = EnvelopeCells(envelope, durationSeconds, totalMillis)
            cells = ideal.cells
        }

        val peak: Double = cells.maxOrNull() ?: 0.0

        /** Mean of the cells in [fromMillis, toMillis). */
        fun meanOf(fromMillis: Int, toMillis: Int): Double {
            var sum = 0.0
            for (cell in fromMillis * CELLS_PER_MILLI until toMillis * CELLS_PER_MILLI) sum += cells[cell]
            return sum / ((toMillis - fromMillis) * CELLS_PER_MILLI)
        }

        fun amplitudeOf(fromMillis: Int, toMillis: Int): Int {
            var anyOn = false
            for (cell in fromMillis * CELLS_PER_MILLI until toMillis * CELLS_PER_MILLI) {
                if (cells[cell] >= OFF_BELOW) anyOn = true
            }
            if (!anyOn) return 0
            return roundHalfUp(meanOf(fromMillis, toMillis) * MAX_AMPLITUDE).toInt().coerceIn(1, MAX_AMPLITUDE)
        }

        /** Steps of growing length until the merged entries fit [maxEntries]; 1 entry always fits eventually. */
        inline fun build(kind: String, amplitudeOf: (fromMillis: Int, toMillis: Int) -> Int): VibrationWaveform {
            var step = requestedStepMillis
            while (true) {
                val timings = ArrayList<Long>()
                val amplitudes = ArrayList<Int>()
                var from = 0
                while (from < totalMillis) {
                    val to = minOf(from.toLong() + step, totalMillis.toLong()).toInt()
                    val amplitude = amplitudeOf(from, to)
                    if (amplitudes.isNotEmpty() && amplitudes.last() == amplitude) {
                        timings[timings.size - 1] = timings.last() + (to - from)
                    } else {
                        timings.add((to - from).toLong())
                        amplitudes.add(amplitude)
                    }
                    from = to
                }
                if (timings.size <= maxEntries) return finish(kind, step, timings.toLongArray(), amplitudes.toIntArray())
                step = if (step > totalMillis / 2) totalMillis else step * 2
            }
        }

        private fun finish(kind: String, step: Int, timings: LongArray, amplitudes: IntArray): VibrationWaveform {
            val stepEnds = LongArray(timings.size)
            var end = 0L
            for (i in timings.indices) {
                end += timings[i]
                stepEnds[i] = end * CELLS_PER_MILLI
            }
            var entry = 0
            val errors = ideal.errorsOf { cell ->
                while (entry < stepEnds.size && cell >= stepEnds[entry]) entry++
                if (entry < amplitudes.size) amplitudes[entry].toDouble() / MAX_AMPLITUDE else 0.0
            }
            val fidelity = Fidelity(errors.rms, errors.max, "$kind of $step ms, ${timings.size} entries; ${errors.summary()}")
            return VibrationWaveform(timings, amplitudes, step, fidelity)
        }
    }
}
