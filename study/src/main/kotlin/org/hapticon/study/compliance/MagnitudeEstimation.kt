package org.hapticon.study.compliance

import kotlin.math.sqrt

/**
 * One answer of Task 1: [participant] rated [condition] in repetition [repetition] (0-based) with [value], the
 * compliance felt against the bare desk (0): positive more compliant, negative less, 0 the same.
 */
public data class MagnitudeEstimate(val participant: String, val repetition: Int, val condition: ComplianceCondition, val value: Double) {
    init {
        MagnitudeEstimation.requireEstimate(value)
        require(repetition >= 0) { "repetition must be >= 0, was $repetition" }
    }
}

/**
 * Shaping Compliance's relative magnitude estimation (003_8ca1dc8f53472543.txt:142, :148): the bare desk is the
 * reference, rated 0; a stimulus is rated with any number, positive when more compliant than the desk, negative when
 * less, 0 when the same, in a range and kind of number the participant chooses (whole or decimal), with one scale per
 * repetition (:150).
 *
 * [standardize] is the paper's normalisation: "Raw scores were first standardized by dividing by the standard deviation
 * for each participant and each repetition" (:154). Which standard deviation is paper silent: ours is the sample one
 * (n − 1, R's `sd`). Not centred: the desk stays at 0, as the paper's added reference rows need (:161).
 */
public object MagnitudeEstimation {
    /**
     * Returns [value] when it is a usable rating: any finite number (0 and negatives included).
     * @throws IllegalArgumentException otherwise, with a one-line message.
     */
    public fun requireEstimate(value: Double): Double {
        require(value.isFinite()) { "a rating must be a finite number, was $value" }
        return value
    }

    /**
     * The rating typed as [text]: a decimal number with an optional sign, `.` or `,` as the decimal mark (a phone's
     * keyboard in many locales gives `,`), or null when it is not one.
     */
    public fun parse(text: String): Double? {
        val t = text.trim().replace(',', '.')
        if (!NUMBER.matches(t)) return null
        return t.toDouble().takeIf { it.isFinite() }
    }

    /**
     * Every estimate divided by the sample standard deviation of its participant's answers in its repetition, in the
     * same order. Empty in, empty out.
     * @throws IllegalArgumentException when a participant's repetition has fewer than 2 answers or all of them equal (its
     *   SD is 0 or undefined, so it has no scale to divide by), naming the participant and repetition.
     */
    public fun standardize(estimates: List<MagnitudeEstimate>): List<MagnitudeEstimate> {
        val sd = estimates.groupBy { it.participant to it.repetition }.mapValues { (key, group) ->
            val values = group.map { it.value }
            require(values.size >= 2) { "${key.first}, repetition ${key.second + 1}: one answer has no standard deviation" }
            val mean = values.average()
            val s = sqrt(values.sumOf { (it - mean) * (it - mean) } / (values.size - 1))
            require(s > 0.0) { "${key.first}, repetition ${key.second + 1}: every answer is ${values.first()}, so there is no scale to divide by" }
            s
        }
        return estimates.map { it.copy(value = it.value / sd.getValue(it.participant to it.repetition)) }
    }

    private val NUMBER = Regex("[+-]?([0-9]+([.][0-9]*)?|[.][0-9]+)([eE][+-]?[0-9]+)?")
}
