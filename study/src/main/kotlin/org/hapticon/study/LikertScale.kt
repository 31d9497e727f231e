package org.hapticon.study

import org.hapticon.study.schema.ProtocolException
/**
 * A rating scale of [points] answers, 1..[points]. [labels] are either empty, the two end anchors, or one label
 * per point, lowest first (for example "strongly disagree" .. "strongly agree").
 *
 * Throws [ProtocolException] (path `scale.points` or `scale.labels`) when [points] is outside 2..[MAX_POINTS]
 * or the labels do not fit.
 */
public data class LikertScale(val points: Int, val labels: List<String> = emptyList()) {
    init {
        if (points !in 2..MAX_POINTS) throw ProtocolException("scale.points", "must be in 2..$MAX_POINTS, was $points")
        if (labels.size != 0 && labels.size != 2 && labels.size != points) {
            throw ProtocolException("scale.labels", "expected none, 2 anchors or $points labels, got ${labels.size}")
        }
        labels.forEachIndexed { i, label ->
            if (label.isBlank()) throw ProtocolException("scale.labels[$i]", "must not be blank")
        }
    }

    /** True when [value] is an answer on this scale, 1..[points]. */
    public fun accepts(value: Int): Boolean = value in 1..points

    public companion object {
        /** Largest number of points; beyond it a rating is a slider, not a Likert item. */
        public const val MAX_POINTS: Int = 11

        /** The originating study's 5-point agreement scale. */
        public val AGREEMENT_5: LikertScale = LikertScale(
            5, listOf("strongly disagree", "disagree", "neither agree nor disagree", "agree", "strongly agree"),
        )
    }
}
