package org.hapticon.sensor.glove

/**
 * When a held pose counts as settled: the last [windowSamples] valid readings span at most
 * [maxRelativeSpread] of their mean, (max − min)/mean ≤ spread. The captured value is that window's mean.
 *
 * The defaults (25 samples, 2 %) suit a glove streaming at 50–100 Hz: a quarter to half a second of
 * steady hand. 2 % of R is about 1.1° at the study's α ≈ 0.018/° (Δθ ≈ ΔR/R/α).
 */
public data class SettleCriterion(
    val windowSamples: Int = DEFAULT_WINDOW_SAMPLES,
    val maxRelativeSpread: Double = DEFAULT_MAX_RELATIVE_SPREAD,
) {
    init {
        require(windowSamples in 2..MAX_WINDOW_SAMPLES) { "windowSamples must be in 2..$MAX_WINDOW_SAMPLES, was $windowSamples" }
        require(maxRelativeSpread > 0.0 && maxRelativeSpread < 1.0) { "maxRelativeSpread must be in (0, 1), was $maxRelativeSpread" }
    }

    public companion object {
        /** Default window length in samples. */
        public const val DEFAULT_WINDOW_SAMPLES: Int = 25

        /** Default largest spread of a settled window, relative to its mean. */
        public const val DEFAULT_MAX_RELATIVE_SPREAD: Double = 0.02

        /** Longest window accepted. */
        public const val MAX_WINDOW_SAMPLES: Int = 10_000
    }
}

/** Where a [FlexCalibrationFlow] is. Every state is an immutable snapshot. */
public sealed interface CalibrationState {
    /**
     * Waiting for the person to hold pose [poseIndex] at [targetDegrees] and confirm with `beginPose()`, in round
     * [take] (1-based; each pose is taken [FlexCalibrationFlow.takesPerPose] times).
     */
    public data class WaitingForPose(val poseIndex: Int, val targetDegrees: Double, val take: Int = 1) : CalibrationState

    /**
     * Collecting readings for pose [poseIndex]. [windowFill] valid readings are in the window so far;
     * [relativeSpread] is the current window's (max − min)/mean once it is full, else null; it stays above
     * the criterion while the reading is still moving. [faults] counts fault readings in this pose (each
     * one empties the window). [take] is the round, as in [WaitingForPose].
     */
    public data class Settling(
        val poseIndex: Int,
        val targetDegrees: Double,
        val windowFill: Int,
        val relativeSpread: Double?,
        val faults: Int,
        val take: Int = 1,
    ) : CalibrationState

    /** Every pose was captured and fitted. */
    public data class Calibrated(val fit: FlexFit) : CalibrationState

    /** Every pose was captured but the fit was rejected: [reason]; `restart()` to try again. */
    public data class Failed(val reason: String) : CalibrationState
}

/**
 * The calibration procedure for one finger, as a state machine the app drives (one instance per finger):
 * for each pose in [posesDegrees] (default 0°, 30°, 50°, 70°, 90°, the tele-handshake paper's,
 * 002_12aacdd60a14fec1.txt:77) the app shows "hold θ", calls [beginPose] once the person holds it, then feeds every
 * reading to [offer]. Readings are collected until the window is settled ([criterion]; the paper read a goniometer,
 * :71, :76, and is silent on how long a pose is held); the window's mean is that take of the pose and the flow moves
 * on. The poses are walked [takesPerPose] times: the paper repeated the whole procedure twice per participant
 * (:79) and used "the average of two trials" (:83). Round 1 through every pose, then round 2, so the hand leaves
 * each pose before it is taken again (the paper's order is thumb, middle finger, then both again, :76-79; ours
 * completes one finger's two rounds before the other's, one flow per finger). A pose's
 * [CalibrationPoint] is the mean resistance of its takes. After the last take of the last pose it fits
 * ([FlexCalibration.fit]) and ends in [CalibrationState.Calibrated] or [CalibrationState.Failed].
 *
 * [beginPose] is explicit because a reading that is settled at the previous pose would otherwise be
 * captured again before the person has moved. Not thread-safe: drive it from one thread.
 */
public class FlexCalibrationFlow(
    /** The finger being calibrated. */
    public val finger: GloveFinger,
    /** The angles to hold, in order; at least 2 distinct, all finite. */
    public val posesDegrees: List<Double> = DEFAULT_POSES_DEGREES,
    /** When a held reading counts as settled. */
    public val criterion: SettleCriterion = SettleCriterion(),
    /** How many times each pose is taken and averaged: 2, as the tele-handshake paper did (002_12aacdd60a14fec1.txt:79, :83). */
    public val takesPerPose: Int = DEFAULT_TAKES_PER_POSE,
) {
    init {
        require(takesPerPose in 1..MAX_TAKES_PER_POSE) { "takesPerPose must be in 1..$MAX_TAKES_PER_POSE, was $takesPerPose" }
        require(posesDegrees.all { it.isFinite() }) { "posesDegrees must be finite, were $posesDegrees" }
        require(posesDegrees.distinct().size >= 2) { "posesDegrees needs at least 2 distinct angles, were $posesDegrees" }
    }

    private val window = DoubleArray(criterion.windowSamples)
    private var windowFill = 0
    private var windowNext = 0
    private var faults = 0
    private val captured = ArrayList<CalibrationPoint>()

    /** The current state. */
    public var state: CalibrationState = CalibrationState.WaitingForPose(0, posesDegrees[0])
        private set

    /** Every take captured so far, in the order taken (round 1's poses, then round 2's). */
    public val takes: List<CalibrationPoint> get() = captured.toList()

    /** Each pose taken so far, its resistance the mean of its takes, in pose order. */
    public val points: List<CalibrationPoint> get() = posesDegrees.indices.mapNotNull { pose ->
        val of = captured.indices.filter { it % posesDegrees.size == pose }.map { captured[it].kiloohms }
        if (of.isEmpty()) null else CalibrationPoint(posesDegrees[pose], of.average())
    }

    /** Takes captured so far, 0..[totalTakes]. */
    public val capturedTakes: Int get() = captured.size

    /** Takes in the whole procedure: poses × [takesPerPose]. */
    public val totalTakes: Int get() = posesDegrees.size * takesPerPose

    /**
     * Starts collecting for the pose the flow is waiting for and returns the new state; in any other state
     * it changes nothing and returns the current state.
     */
    public fun beginPose(): CalibrationState {
        val waiting = state as? CalibrationState.WaitingForPose ?: return state
        clearWindow()
        faults = 0
        state = CalibrationState.Settling(waiting.poseIndex, waiting.targetDegrees, 0, null, 0, waiting.take)
        return state
    }

    /**
     * Feeds one reading while settling and returns the new state. A fault empties the window (the pose
     * must be held steady again); other states ignore readings.
     */
    public fun offer(reading: DividerReading): CalibrationState {
        val settling = state as? CalibrationState.Settling ?: return state
        when (reading) {
            is DividerReading.Fault -> {
                faults++
                clearWindow()
                state = settling.copy(windowFill = 0, relativeSpread = null, faults = faults)
            }
            is DividerReading.Resistance -> accept(settling, reading.kiloohms)
        }
        return state
    }

    /** Drops every captured point and starts again at the first pose. */
    public fun restart(): CalibrationState {
        captured.clear()
        clearWindow()
        faults = 0
        state = CalibrationState.WaitingForPose(0, posesDegrees[0])
        return state
    }

    private fun accept(settling: CalibrationState.Settling, kiloohms: Double) {
        window[windowNext] = kiloohms
        windowNext = (windowNext + 1) % window.size
        if (windowFill < window.size) windowFill++
        if (windowFill < window.size) {
            state = settling.copy(windowFill = windowFill, relativeSpread = null)
            return
        }
        var min = Double.POSITIVE_INFINITY
        var max = Double.NEGATIVE_INFINITY
        var sum = 0.0
        for (value in window) {
            if (value < min) min = value
            if (value > max) max = value
            sum += value
        }
        val mean = sum / window.size
        val spread = (max - min) / mean
        if (spread > criterion.maxRelativeSpread) {
            state = settling.copy(windowFill = windowFill, relativeSpread = spread)
            return
        }
        captured += CalibrationPoint(settling.targetDegrees, mean)
        val next = captured.size
        state = if (next < totalTakes) {
            val pose = next % posesDegrees.size
            CalibrationState.WaitingForPose(pose, posesDegrees[pose], next / posesDegrees.size + 1)
        } else {
            when (val result = FlexCalibration.fit(points)) {
                is FitResult.Fitted -> CalibrationState.Calibrated(result.fit)
                is FitResult.Rejected -> CalibrationState.Failed(result.reason)
            }
        }
    }

    private fun clearWindow() {
        windowFill = 0
        windowNext = 0
    }

    public companion object {
        /** The study's calibration poses: 0°, 30°, 50°, 70°, 90°. */
        public val DEFAULT_POSES_DEGREES: List<Double> = listOf(0.0, 30.0, 50.0, 70.0, 90.0)

        /** Each pose taken twice and averaged, as in the tele-handshake paper. */
        public const val DEFAULT_TAKES_PER_POSE: Int = 2

        /** Most takes per pose accepted. */
        public const val MAX_TAKES_PER_POSE: Int = 10
    }
}
