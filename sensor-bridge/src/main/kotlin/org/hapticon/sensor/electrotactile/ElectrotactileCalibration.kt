package org.hapticon.sensor.electrotactile

import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.sensor.safety.SafetyLimits
import kotlin.math.ceil

/**
 * The stimulator's amplitude resolution: [STEPS] steps over 0–2.7 mA (Shaping Compliance's circuit: "0–2.7 mA,
 * controllable with 200 discrete steps", 003_8ca1dc8f53472543.txt:123), step k = k·2.7/200 mA = k·13.5 µA. Step 200 is the hard cap [SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS];
 * nothing maps above it.
 */
public object AmplitudeSteps {
    /** Steps over the full range. */
    public const val STEPS: Int = 200

    /** One step in milliamperes: 0.0135 mA. */
    public const val MILLIAMPS_PER_STEP: Double = SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS / STEPS

    /**
     * The current of [step] in milliamperes.
     * @throws org.hapticon.sensor.safety.SafetyLimitException when [step] is outside 0..[STEPS].
     */
    public fun milliampsOf(step: Int): Double {
        requireStep(step)
        // Step 200 is exactly the cap, not 200 × 0.0135 rounded.
        return if (step == STEPS) SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS else step * MILLIAMPS_PER_STEP
    }

    /**
     * The lowest step whose current is at least [milliamps]: how a requested current reaches the hardware without
     * ever rounding above what was asked for by more than one step, and never above the cap.
     * @throws org.hapticon.sensor.safety.SafetyLimitException when [milliamps] is negative, above 2.7 mA or not finite.
     */
    public fun stepAtLeast(milliamps: Double): Int {
        if (!(milliamps >= 0.0 && milliamps <= SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS)) {
            throw SafetyLimitException(
                "electrotactileCurrent",
                "electrotactile current must be in [0, ${SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS}] mA, was $milliamps",
            )
        }
        // The small tolerance keeps exact multiples (0.81 mA = step 60) on their own step despite binary rounding.
        return minOf(STEPS, ceil(milliamps / MILLIAMPS_PER_STEP - 1e-9).toInt())
    }

    /**
     * Returns [step] when it is in 0..[STEPS].
     * @throws org.hapticon.sensor.safety.SafetyLimitException otherwise.
     */
    public fun requireStep(step: Int): Int {
        if (step !in 0..STEPS) {
            throw SafetyLimitException("electrotactileCurrent", "amplitude step must be in 0..$STEPS, was $step")
        }
        return step
    }
}

/** One calibration stimulus: [electrodes] driven at [step] for [durationMillis] with the grain's pulses. */
public data class CalibrationStimulus(
    /** The electrodes driven (one while calibrating an electrode, all nine in the whole-array check). */
    val electrodes: ElectrodePattern,
    /** The amplitude step of each driven electrode, in [electrodes]' scan order. */
    val steps: List<Int>,
    /** How long the stimulus lasts. */
    val durationMillis: Int,
    /** Grains over a full press in the whole-array check, else 0 (a plain 200 ms stimulus). */
    val grains: Int,
)

/**
 * Shaping Compliance's per-person calibration (003_8ca1dc8f53472543.txt:152), as a state machine the app or a CLI
 * drives:
 *
 * 1. Each electrode of the 3×3 array in order (0..8, row by row; "each of the 9 channels ... separately in order"): a
 *    [STIMULUS_MILLIS] ms stimulus starting at the first step at or above [START_MILLIAMPS] (step 60, 0.81 mA);
 *    [notYet] raises it one hardware step (13.5 µA) for the next stimulus until the person calls it clear and
 *    pain-free ([clearAndPainFree]); [tooStrong] lowers it one step. Raising stops at step 200 (2.7 mA): the cap is
 *    absolute. The step size is paper silent ("gradually increased"): ours is the hardware's smallest.
 * 2. The whole-array check: all nine electrodes at their levels while the person presses, with [CHECK_GRAINS]
 *    grains over the press ("39 grains, all electrodes"), adjusted until the sensation is "pain-free and uniform ...
 *    on the whole stimulated area": [weaker] or [stronger] moves the one electrode the person feels stand out by a
 *    step, [tooStrong] lowers every electrode a step, and [wholeArrayOk] finishes.
 *
 * The study redoes this before each repetition (:152, "before starting each repetition"); the compliance protocol
 * says when. [stimulus] is what to play next. Not thread-safe.
 */
public class ElectrotactileCalibration {
    private val levels = IntArray(ELECTRODES) { START_STEP }
    private var electrode = 0

    /** The electrode being calibrated (0..8), or null in the whole-array check and after it. */
    public val currentElectrode: Int? get() = electrode.takeIf { it < ELECTRODES }

    /** Whether the person is in the whole-array check. */
    public val isCheckingWholeArray: Boolean get() = electrode == ELECTRODES && !isDone

    /** Whether calibration has finished. */
    public var isDone: Boolean = false
        private set

    /** The step of each electrode so far (its calibrated step once passed). */
    public fun steps(): List<Int> = levels.toList()

    /** The next stimulus to play, or null once done. */
    public fun stimulus(): CalibrationStimulus? = when {
        isDone -> null
        electrode < ELECTRODES -> CalibrationStimulus(ElectrodePattern(1 shl electrode), listOf(levels[electrode]), STIMULUS_MILLIS, 0)
        else -> CalibrationStimulus(ElectrodePattern.ALL, levels.toList(), 0, CHECK_GRAINS)
    }

    /** Not clear yet: the current electrode's next stimulus is one step stronger (never past step 200). */
    public fun notYet() {
        val e = requireCalibratingElectrode("notYet")
        levels[e] = minOf(AmplitudeSteps.STEPS, levels[e] + 1)
    }

    /** Clear and pain-free: the current electrode keeps its step; on to the next electrode or the whole-array check. */
    public fun clearAndPainFree() {
        requireCalibratingElectrode("clearAndPainFree")
        electrode++
    }

    /** Too strong: one step weaker (the current electrode, or every electrode in the whole-array check). */
    public fun tooStrong() {
        check(!isDone) { "calibration is done" }
        if (electrode < ELECTRODES) {
            levels[electrode] = maxOf(0, levels[electrode] - 1)
        } else {
            for (i in levels.indices) levels[i] = maxOf(0, levels[i] - 1)
        }
    }

    /**
     * Whole-array check: [electrode] (0..8) stands out as stronger than the rest, so it alone goes one step weaker
     * (not below 0).
     * @throws IllegalStateException outside the whole-array check; IllegalArgumentException for an electrode outside 0..8.
     */
    public fun weaker(electrode: Int) {
        levels[requireCheckElectrode(electrode, "weaker")] = maxOf(0, levels[electrode] - 1)
    }

    /**
     * Whole-array check: [electrode] (0..8) is felt less than the rest, so it alone goes one step stronger (never past
     * step 200, 2.7 mA).
     * @throws IllegalStateException outside the whole-array check; IllegalArgumentException for an electrode outside 0..8.
     */
    public fun stronger(electrode: Int) {
        levels[requireCheckElectrode(electrode, "stronger")] = minOf(AmplitudeSteps.STEPS, levels[electrode] + 1)
    }

    private fun requireCheckElectrode(electrode: Int, action: String): Int {
        check(isCheckingWholeArray) { "$action only in the whole-array check" }
        require(electrode in 0 until ELECTRODES) { "electrode must be in 0..8, was $electrode" }
        return electrode
    }

    /** The whole-array check passed: calibration is done. */
    public fun wholeArrayOk() {
        check(isCheckingWholeArray) { "wholeArrayOk only in the whole-array check" }
        isDone = true
    }

    /**
     * The result: each electrode's current and the person's limit (the highest of them).
     * @throws IllegalStateException before [isDone].
     */
    public fun result(): ElectrotactileCalibrationResult {
        check(isDone) { "calibration is not finished" }
        return ElectrotactileCalibrationResult(levels.toList())
    }

    private fun requireCalibratingElectrode(action: String): Int {
        check(electrode < ELECTRODES) { "$action only while calibrating an electrode" }
        return electrode
    }

    public companion object {
        /** Electrodes on the array. */
        public const val ELECTRODES: Int = ElectrodePattern.SIZE * ElectrodePattern.SIZE

        /** Where each electrode's stimulus starts: 0.8 mA (003_8ca1dc8f53472543.txt:152). */
        public const val START_MILLIAMPS: Double = 0.8

        /** The first step at or above [START_MILLIAMPS]: 60 (0.81 mA). */
        public val START_STEP: Int = AmplitudeSteps.stepAtLeast(START_MILLIAMPS)

        /** One calibration stimulus lasts 200 ms (003_8ca1dc8f53472543.txt:152). */
        public const val STIMULUS_MILLIS: Int = 200

        /** Grains over a press in the whole-array check: 39 on all electrodes, the most stimulating condition (003_8ca1dc8f53472543.txt:152). */
        public const val CHECK_GRAINS: Int = 39
    }
}

/** A finished calibration: the amplitude [steps] of electrodes 0..8. */
public data class ElectrotactileCalibrationResult(val steps: List<Int>) {
    init {
        require(steps.size == ElectrotactileCalibration.ELECTRODES) { "need ${ElectrotactileCalibration.ELECTRODES} steps, got ${steps.size}" }
        steps.forEach { AmplitudeSteps.requireStep(it) }
    }

    /** Each electrode's current in milliamperes. */
    public val milliamps: List<Double> get() = steps.map { AmplitudeSteps.milliampsOf(it) }

    /**
     * The person's limit: the highest calibrated current (at most 2.7 mA).
     * @throws org.hapticon.sensor.safety.SafetyLimitException when every electrode was lowered to 0.
     */
    public fun userLimit(): ElectrotactileUserLimit = ElectrotactileUserLimit(milliamps.max())
}
