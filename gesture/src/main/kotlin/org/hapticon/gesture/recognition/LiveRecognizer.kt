package org.hapticon.gesture.recognition

import kotlin.math.roundToLong

/**
 * A recognised gesture: [label] with vote share [probability], decided when frame [decisionFrame] (0-based,
 * counted from the first frame pushed) arrived. [firstVoteFrame] is when the first of the agreeing decisions
 * was made; the gesture began before it, so `decisionFrame − onset` is the decision latency in frames for a
 * caller that knows the onset (the benchmark does).
 */
public class GestureEvent(
    public val label: GestureLabel,
    public val probability: Double,
    public val decisionFrame: Long,
    public val firstVoteFrame: Long,
) {
    override fun toString(): String = "GestureEvent($label, p=$probability, frame $decisionFrame, first vote $firstVoteFrame)"
}

/**
 * Recognises gestures live from frames pushed one at a time (one value per model channel, in model order):
 * every hop it classifies the last window and reports a gesture only once it is stable — the same label
 * won [stableDecisions] decisions in a row, or a single decision gave it a vote share of at least
 * [probabilityThreshold]. After an event it stays silent until a [GestureLabel.NONE] decision has been seen
 * and [refractorySeconds] have passed, so one squeeze sends one icon however long it lasts.
 *
 * Holds the last window in a ring buffer and allocates nothing per frame; not thread-safe.
 */
public class LiveRecognizer(
    public val model: GestureModel,
    public val stableDecisions: Int = DEFAULT_STABLE_DECISIONS,
    public val probabilityThreshold: Double = DEFAULT_PROBABILITY_THRESHOLD,
    public val refractorySeconds: Double = DEFAULT_REFRACTORY_SECONDS,
) {
    init {
        require(stableDecisions >= 1) { "stableDecisions must be >= 1, was $stableDecisions" }
        require(probabilityThreshold > 0.0 && probabilityThreshold <= 1.0) { "probabilityThreshold must be in (0, 1], was $probabilityThreshold" }
        require(refractorySeconds.isFinite() && refractorySeconds >= 0.0) { "refractorySeconds must be finite and >= 0, was $refractorySeconds" }
    }

    private val classifier = model.classifier()
    private val window = model.windowFrames
    private val hop = model.hopFrames
    private val refractoryFrames = (refractorySeconds * model.sampleRate).roundToLong()

    // Each sample is written twice, W apart, so the last W samples are always contiguous.
    private val buffers = List(model.channels.size) { DoubleArray(2 * window) }

    private var frames = 0L
    private var runLabel: GestureLabel? = null
    private var runLength = 0
    private var runStart = 0L
    private var lastEvent = Long.MIN_VALUE / 2
    private var sawNoneSinceEvent = true

    /** Frames pushed so far. */
    public val framesSeen: Long get() = frames

    /** The label of the most recent decision, or null before the first full window. */
    public var lastDecision: GestureLabel? = null
        private set

    /** The vote share of [lastDecision] (0 before the first decision). */
    public var lastProbability: Double = 0.0
        private set

    /** Decisions made so far (one per hop once the first window is full). */
    public var decisionCount: Long = 0
        private set

    /** Adds one frame ([frame] has one value per model channel; non-finite values are held, see [WindowFeatures]) and returns the event it completes, if any. */
    public fun push(frame: DoubleArray): GestureEvent? {
        require(frame.size == buffers.size) { "expected ${buffers.size} values per frame (${model.channels}), got ${frame.size}" }
        val slot = (frames % window).toInt()
        for (c in buffers.indices) {
            buffers[c][slot] = frame[c]
            buffers[c][slot + window] = frame[c]
        }
        val now = frames++
        if (frames < window || (frames - window) % hop != 0L) return null
        return decide(classifier.classify(buffers, slot + 1), now)
    }

    private fun decide(label: GestureLabel, now: Long): GestureEvent? {
        lastDecision = label
        decisionCount++
        val probability = classifier.probabilities[model.labels.indexOf(label)]
        lastProbability = probability
        if (label == runLabel) {
            runLength++
        } else {
            runLabel = label
            runLength = 1
            runStart = now
        }
        if (label.isNone) {
            sawNoneSinceEvent = true
            return null
        }
        val armed = sawNoneSinceEvent && now - lastEvent >= refractoryFrames
        if (!armed || (runLength < stableDecisions && probability < probabilityThreshold)) return null
        lastEvent = now
        sawNoneSinceEvent = false
        return GestureEvent(label, probability, now, runStart)
    }

    /** Forgets all frames and decisions, as if newly made. */
    public fun reset() {
        frames = 0
        runLabel = null
        runLength = 0
        lastDecision = null
        lastProbability = 0.0
        decisionCount = 0
        lastEvent = Long.MIN_VALUE / 2
        sawNoneSinceEvent = true
    }

    public companion object {
        /** Decisions in a row that make a label stable. */
        public const val DEFAULT_STABLE_DECISIONS: Int = 3

        /** A single decision with at least this vote share is stable at once. */
        public const val DEFAULT_PROBABILITY_THRESHOLD: Double = 0.8

        /** Minimum time between two events. */
        public const val DEFAULT_REFRACTORY_SECONDS: Double = 1.0
    }
}
