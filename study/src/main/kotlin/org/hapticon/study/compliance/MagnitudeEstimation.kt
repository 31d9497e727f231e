package org.hapticon.study.compliance

import kotlin.math.exp
import kotlin.math.ln

/** One magnitude estimate: [participant] answered [value] for [conditionId]. */
public data class MagnitudeEstimate(val participant: String, val conditionId: String, val value: Double) {
    init {
        MagnitudeEstimation.requireEstimate(value)
    }
}

/**
 * Free-modulus magnitude estimation: each participant answers with any positive numbers in proportion to what
 * they feel. Because every participant picks their own modulus, the answers are made comparable by dividing each
 * participant's answers by that participant's geometric mean and multiplying by the grand geometric mean of all
 * answers (the usual normalisation for free-modulus data, e.g. Zwislocki & Goodman 1980). This is the standard
 * method, not one restated from Shaping Compliance.
 */
public object MagnitudeEstimation {
    /**
     * Returns [value] when it is a usable estimate: finite and > 0 (zero has no logarithm).
     * @throws IllegalArgumentException otherwise, with a one-line message for the participant's screen.
     */
    public fun requireEstimate(value: Double): Double {
        require(value > 0.0 && value.isFinite()) { "an estimate must be a positive number, was $value" }
        return value
    }

    /** The answers rescaled as described on the type, in the same order. Empty in, empty out. */
    public fun normalize(estimates: List<MagnitudeEstimate>): List<MagnitudeEstimate> {
        if (estimates.isEmpty()) return emptyList()
        val grand = geometricMean(estimates.map { it.value })
        val perParticipant = estimates.groupBy { it.participant }.mapValues { (_, list) -> geometricMean(list.map { it.value }) }
        return estimates.map { it.copy(value = it.value / perParticipant.getValue(it.participant) * grand) }
    }

    /** The geometric mean of each condition's normalised estimates, by condition id, in first-seen order. */
    public fun conditionMeans(estimates: List<MagnitudeEstimate>): Map<String, Double> =
        normalize(estimates).groupBy { it.conditionId }.mapValues { (_, list) -> geometricMean(list.map { it.value }) }

    private fun geometricMean(values: List<Double>): Double = exp(values.sumOf { ln(it) } / values.size)
}
