package org.hapticon.study.analysis

import kotlin.math.abs
import kotlin.math.exp
import kotlin.math.ln
import kotlin.math.ln1p
import kotlin.math.max
import kotlin.math.min

/**
 * The special functions behind the tests' p-values, after Numerical Recipes (3rd ed.): ln Γ by Lanczos,
 * the regularized incomplete beta by its continued fraction (modified Lentz), the regularized incomplete
 * gamma for the normal tail. Measured against mpmath, the two-sided t tail is within 1e-11 relative for
 * df ≤ 10⁴ and t in [0.01, 30]; near the fraction's switch-over point it degrades to 3e-10 at df = 10⁵ and
 * 3e-9 at df = 10⁸ (the Lentz stopping test fires early there), far beyond any study's size.
 */
internal object SpecialFunctions {
    /** ln Γ([x]) for x > 0 (Lanczos, g = 671/128, 14 terms: NR3 `gammln`). */
    fun lnGamma(x: Double): Double {
        require(x > 0.0 && x.isFinite()) { "lnGamma needs a finite x > 0, got $x" }
        var y = x
        var tmp = x + 671.0 / 128.0
        tmp = (x + 0.5) * ln(tmp) - tmp
        var series = 0.999999999999997092
        for (c in LANCZOS) series += c / ++y
        return tmp + ln(2.5066282746310005 * series / x)
    }

    /**
     * ln B([a], [b]) = ln Γ(a) + ln Γ(b) − ln Γ(a + b). For a large argument the three ln Γ are huge and
     * nearly cancel, so (as R's `lbeta`) Stirling's formula is expanded by hand and only the small
     * corrections [stirlingCorrection] are added.
     */
    fun lnBeta(a: Double, b: Double): Double {
        val p = min(a, b)
        val q = max(a, b)
        val sum = p + q
        return when {
            p >= STIRLING_FROM -> {
                val correction = stirlingCorrection(p) + stirlingCorrection(q) - stirlingCorrection(sum)
                -0.5 * ln(q) + LN_SQRT_2PI + correction + (p - 0.5) * ln(p / sum) + q * ln1p(-p / sum)
            }
            q >= STIRLING_FROM -> {
                val correction = stirlingCorrection(q) - stirlingCorrection(sum)
                lnGamma(p) + correction + p - p * ln(sum) + (q - 0.5) * ln1p(-p / sum)
            }
            else -> lnGamma(p) + lnGamma(q) - lnGamma(sum)
        }
    }

    /**
     * ln Γ([x]) − ((x − ½) ln x − x + ln √(2π)) for x ≥ 10, by the Stirling series to x⁻¹¹ (the next term,
     * 1/(156 x¹³), is below 1e-15 there).
     */
    private fun stirlingCorrection(x: Double): Double {
        val inv2 = 1.0 / (x * x)
        return (1.0 / 12 - inv2 * (1.0 / 360 - inv2 * (1.0 / 1260 - inv2 * (1.0 / 1680 - inv2 * (1.0 / 1188 - inv2 * 691.0 / 360360))))) / x
    }

    /**
     * The regularized incomplete beta I_x([a], [b]). [complement] is 1 − [x], passed separately so callers
     * that know it exactly (the t distribution's t²/(ν+t²)) lose nothing to cancellation.
     */
    fun incompleteBeta(a: Double, b: Double, x: Double, complement: Double = 1.0 - x): Double {
        require(a > 0.0 && b > 0.0) { "incompleteBeta needs a, b > 0, got a=$a b=$b" }
        require(x in 0.0..1.0) { "incompleteBeta needs x in [0, 1], got $x" }
        if (x == 0.0 || complement == 0.0) return if (x == 0.0) 0.0 else 1.0
        // ln of whichever of x, 1 − x is near 1 via ln1p of the other: with a = ν/2 in the millions, a·ln x must not
        // carry x's rounding error.
        val lnX = if (x > 0.5) ln1p(-complement) else ln(x)
        val lnComplement = if (complement > 0.5) ln1p(-x) else ln(complement)
        val front = exp(a * lnX + b * lnComplement - lnBeta(a, b))
        // The fraction converges fast only left of the mean; use the symmetry I_x(a,b) = 1 − I_{1−x}(b,a) right of it.
        return if (x < (a + 1.0) / (a + b + 2.0)) {
            front * betaContinuedFraction(a, b, x) / a
        } else {
            1.0 - front * betaContinuedFraction(b, a, complement) / b
        }
    }

    /** Two-sided tail P(|T| ≥ |[t]|) of Student's t with [df] degrees of freedom. */
    fun studentTTwoSided(t: Double, df: Double): Double {
        require(df > 0.0) { "degrees of freedom must be > 0, got $df" }
        require(!t.isNaN()) { "t is NaN" }
        if (t.isInfinite()) return 0.0
        val t2 = t * t
        return incompleteBeta(df / 2.0, 0.5, df / (df + t2), t2 / (df + t2))
    }

    /** The CDF P(T ≤ [t]) of Student's t with [df] degrees of freedom. */
    fun studentTCdf(t: Double, df: Double): Double {
        val tail = studentTTwoSided(t, df) / 2.0
        return if (t > 0.0) 1.0 - tail else tail
    }

    /** Two-sided tail P(|Z| ≥ |[z]|) of the standard normal: erfc(|z|/√2) = Q(1/2, z²/2). */
    fun normalTwoSided(z: Double): Double {
        require(!z.isNaN()) { "z is NaN" }
        if (z.isInfinite()) return 0.0
        return upperIncompleteGammaHalf(z * z / 2.0)
    }

    /** Q(1/2, [x]), the upper regularized incomplete gamma at a = 1/2 (NR3 `gser`/`gcf`). */
    private fun upperIncompleteGammaHalf(x: Double): Double {
        val a = 0.5
        if (x == 0.0) return 1.0
        val logFront = -x + a * ln(x) - LN_SQRT_PI
        if (x < a + 1.0) {
            // Series for P, then Q = 1 − P (P is small here, so no precision is lost).
            var ap = a
            var del = 1.0 / a
            var sum = del
            repeat(MAX_ITERATIONS) {
                ap += 1.0
                del *= x / ap
                sum += del
                if (abs(del) < abs(sum) * EPSILON) return 1.0 - sum * exp(logFront)
            }
            error("incomplete gamma series did not converge for x=$x")
        }
        // Continued fraction for Q (modified Lentz).
        var b = x + 1.0 - a
        var c = 1.0 / FPMIN
        var d = 1.0 / b
        var h = d
        for (i in 1..MAX_ITERATIONS) {
            val an = -i * (i - a)
            b += 2.0
            d = an * d + b
            if (abs(d) < FPMIN) d = FPMIN
            c = b + an / c
            if (abs(c) < FPMIN) c = FPMIN
            d = 1.0 / d
            val del = d * c
            h *= del
            if (abs(del - 1.0) <= EPSILON) return exp(logFront) * h
        }
        error("incomplete gamma fraction did not converge for x=$x")
    }

    /** The continued fraction of the incomplete beta, by the modified Lentz method (NR3 `betacf`). */
    private fun betaContinuedFraction(a: Double, b: Double, x: Double): Double {
        val qab = a + b
        val qap = a + 1.0
        val qam = a - 1.0
        var c = 1.0
        var d = 1.0 - qab * x / qap
        if (abs(d) < FPMIN) d = FPMIN
        d = 1.0 / d
        var h = d
        for (m in 1..MAX_ITERATIONS) {
            val m2 = 2 * m
            var aa = m * (b - m) * x / ((qam + m2) * (a + m2))
            d = 1.0 + aa * d
            if (abs(d) < FPMIN) d = FPMIN
            c = 1.0 + aa / c
            if (abs(c) < FPMIN) c = FPMIN
            d = 1.0 / d
            h *= d * c
            aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
            d = 1.0 + aa * d
            if (abs(d) < FPMIN) d = FPMIN
            c = 1.0 + aa / c
            if (abs(c) < FPMIN) c = FPMIN
            d = 1.0 / d
            val del = d * c
            h *= del
            if (abs(del - 1.0) <= EPSILON) return h
        }
        error("incomplete beta fraction did not converge for a=$a b=$b x=$x")
    }

    private val LANCZOS = doubleArrayOf(
        57.1562356658629235, -59.5979603554754912, 14.1360979747417471, -0.491913816097620199,
        .339946499848118887e-4, .465236289270485756e-4, -.983744753048795646e-4, .158088703224912494e-3,
        -.210264441724104883e-3, .217439618115212643e-3, -.164318106536763890e-3, .844182239838527433e-4,
        -.261908384015814087e-4, .368991826595316234e-5,
    )

    /** ln √(2π). */
    private val LN_SQRT_2PI = 0.5 * ln(2 * Math.PI)
    private const val STIRLING_FROM = 10.0

    /** ln √π = ln Γ(1/2). */
    private val LN_SQRT_PI = 0.5 * ln(Math.PI)
    private const val EPSILON = 1e-16
    private const val FPMIN = 1e-300
    // The fractions need O(√max(a, b)) steps: enough for t-tests on 10⁸ pairs and more.
    private const val MAX_ITERATIONS = 1_000_000
}
