package org.hapticon.study.analysis

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.exp
import kotlin.math.ln
import kotlin.math.sqrt

/**
 * The studentized range distribution, for Tukey-adjusted pairwise comparisons: the upper tail P(Q > q) of the range
 * of k independent standard normals divided by an independent √(χ²_ν/ν) (what R's `ptukey(q, k, ν, lower.tail =
 * FALSE)` gives, and what emmeans' `adjust = "tukey"` applies to √2·|t|).
 *
 * Hand-written because no Maven Central library we use has it (Apache Commons Math has no studentized range); it is
 * the textbook double integral, evaluated by composite Gauss–Legendre quadrature:
 * P(R > w) = k ∫ φ(z) [Q(z)^(k−1) − (Q(z) − Q(z + w))^(k−1)] dz (Q the normal upper tail, the difference of powers
 * expanded so nothing cancels), and P(Q > q) = ∫ f_S(s) P(R > q·s) ds with S = √(χ²_ν/ν), over every ν (R's ptukey
 * takes S = 1 past 25 000 df, an error of order 1/ν). Checked against R's `ptukey` and an arbitrary-precision integral
 * (StudentizedRangeTest, and the ART-C oracle test).
 */
internal object StudentizedRange {
    /** P(Q > [q]) for [means] ≥ 2 means and [df] > 0 degrees of freedom; 1 for q ≤ 0. */
    fun upperTail(q: Double, means: Int, df: Double): Double {
        require(means >= 2) { "the studentized range needs at least 2 means, got $means" }
        require(df > 0.0 && !df.isNaN()) { "degrees of freedom must be > 0, got $df" }
        require(!q.isNaN()) { "q is NaN" }
        if (q <= 0.0) return 1.0
        if (q.isInfinite()) return 0.0
        val tails = ZNodes.upperTails
        val sd = 1.0 / sqrt(2.0 * df)
        val mode = sqrt((df - 1.0).coerceAtLeast(0.0) / df)
        val (low, high) = if (df >= 20.0) (mode - 14 * sd).coerceAtLeast(0.0) to mode + 14 * sd else 0.0 to 9.0
        val logC = ln(2.0) + df / 2 * ln(df / 2) - SpecialFunctions.lnGamma(df / 2)
        return integrate(low, high, S_PANELS) { s ->
            if (s <= 0.0) 0.0 else exp(logC + (df - 1) * ln(s) - df * s * s / 2) * rangeUpper(q * s, means, tails)
        }.coerceIn(0.0, 1.0)
    }

    /** P(R > [w]): the range of [means] standard normals exceeds w. */
    private fun rangeUpper(w: Double, means: Int, tails: DoubleArray): Double {
        val m = means - 1
        var sum = 0.0
        for (i in Z.indices) {
            val a = tails[i]
            val d = normalUpper(Z[i] + w)
            val b = a - d
            // a^m − b^m = d · Σ a^j b^(m−1−j): no cancellation when d is tiny.
            var series = 0.0
            var aj = 1.0
            for (j in 0 until m) {
                series += aj * pow(b, m - 1 - j)
                aj *= a
            }
            sum += ZW[i] * PHI[i] * d * series
        }
        return (means * sum).coerceIn(0.0, 1.0)
    }

    private fun pow(x: Double, n: Int): Double {
        var r = 1.0
        repeat(n) { r *= x }
        return r
    }

    /** Q(z) = P(Z > z), from the normal two-sided tail without cancellation on either side. */
    private fun normalUpper(z: Double): Double {
        val two = SpecialFunctions.normalTwoSided(z)
        return if (z >= 0.0) two / 2 else 1.0 - two / 2
    }

    private fun integrate(low: Double, high: Double, panels: Int, f: (Double) -> Double): Double {
        val width = (high - low) / panels
        var sum = 0.0
        for (p in 0 until panels) {
            val mid = low + (p + 0.5) * width
            for (k in GL_X.indices) sum += GL_W[k] * f(mid + GL_X[k] * width / 2)
        }
        return sum * width / 2
    }

    /** Gauss–Legendre nodes and weights on [−1, 1] by Newton's method on P_n (n = [GL_POINTS]). */
    private val GL: Pair<DoubleArray, DoubleArray> = run {
        val n = GL_POINTS
        val x = DoubleArray(n)
        val w = DoubleArray(n)
        for (i in 0 until n) {
            var root = cos(PI * (i + 0.75) / (n + 0.5))
            var derivative = 0.0
            var iterations = 0
            do {
                var p0 = 1.0
                var p1 = root
                for (k in 2..n) {
                    val p2 = ((2 * k - 1) * root * p1 - (k - 1) * p0) / k
                    p0 = p1
                    p1 = p2
                }
                derivative = n * (root * p1 - p0) / (root * root - 1)
                val step = p1 / derivative
                root -= step
            } while (kotlin.math.abs(step) > 1e-15 && ++iterations < 100)
            x[i] = root
            w[i] = 2 / ((1 - root * root) * derivative * derivative)
        }
        x to w
    }
    private val GL_X get() = GL.first
    private val GL_W get() = GL.second

    /** The z nodes of the inner integral over [−Z_LIMIT, Z_LIMIT], their weights and φ(z). */
    private val Z: DoubleArray
    private val ZW: DoubleArray
    private val PHI: DoubleArray

    init {
        val width = 2 * Z_LIMIT / Z_PANELS
        val nodes = ArrayList<Double>()
        val weights = ArrayList<Double>()
        for (p in 0 until Z_PANELS) {
            val mid = -Z_LIMIT + (p + 0.5) * width
            for (k in GL_X.indices) {
                nodes += mid + GL_X[k] * width / 2
                weights += GL_W[k] * width / 2
            }
        }
        Z = nodes.toDoubleArray()
        ZW = weights.toDoubleArray()
        PHI = DoubleArray(Z.size) { exp(-Z[it] * Z[it] / 2) / sqrt(2 * PI) }
    }

    /** Q(z) at the inner nodes, which do not depend on w: computed once. */
    private object ZNodes {
        val upperTails: DoubleArray = DoubleArray(Z.size) { normalUpper(Z[it]) }
    }

    private const val GL_POINTS = 20
    private const val Z_LIMIT = 10.0
    private const val Z_PANELS = 32
    private const val S_PANELS = 48
}
