package org.hapticon.study.analysis

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import kotlin.math.abs
import kotlin.math.sqrt

class StudentizedRangeTest {
    @get:Rule
    val folder = TemporaryFolder()

    @Test
    fun twoMeans_isTheTwoSidedStudentT() {
        // The range of two normals is |Z1 − Z2| = √2·|Z|, so P(Q > q) for k = 2 is P(|T| > q/√2): no R needed.
        for (df in listOf(3.0, 12.0, 61.0, 500.0, 1e5)) for (q in listOf(0.3, 1.0, 2.5, 4.0, 7.0)) {
            val expected = SpecialFunctions.studentTTwoSided(q / sqrt(2.0), df)
            val actual = StudentizedRange.upperTail(q, 2, df)
            assertEquals("q=$q df=$df", 0.0, abs(actual - expected) / expected, 1e-8)
        }
    }

    @Test
    fun smallDf_matchesAnArbitraryPrecisionIntegral() {
        // mpmath (30 digits, adaptive quadrature of the same double integral): R's ptukey gives 0.14521026 here (1e-5 off).
        assertEquals(0.0, abs(StudentizedRange.upperTail(5.5, 4, 2.0) / 0.14520875632946472 - 1), 1e-8)
    }

    @Test
    fun edges() {
        assertEquals(1.0, StudentizedRange.upperTail(0.0, 4, 10.0), 0.0)
        assertEquals(0.0, StudentizedRange.upperTail(Double.POSITIVE_INFINITY, 4, 10.0), 0.0)
        assertThrows(IllegalArgumentException::class.java) { StudentizedRange.upperTail(1.0, 1, 10.0) }
        assertThrows(IllegalArgumentException::class.java) { StudentizedRange.upperTail(1.0, 3, 0.0) }
    }

    @Test
    fun upperTail_equalsRsPtukey() {
        val qs = listOf(0.5, 1.5, 2.8, 3.5, 4.2, 5.5, 7.0)
        val ks = listOf(3, 4, 5, 9)
        val dfs = listOf(5.0, 20.0, 61.0, 400.0, 3000.0)
        val script = folder.newFile("ptukey.R")
        script.writeText(
            "for (q in c(${qs.joinToString()})) for (k in c(${ks.joinToString()})) for (df in c(${dfs.joinToString()})) " +
                "cat(sprintf('%.17g,%d,%.17g,%.17g\\n', q, k, df, ptukey(q, k, df, lower.tail = FALSE)))\n",
        )
        val lines = RScript.runFile(script)
        assertEquals(qs.size * ks.size * dfs.size, lines.size)
        for (line in lines) {
            val (q, k, df, p) = line.split(',')
            val ours = StudentizedRange.upperTail(q.toDouble(), k.toInt(), df.toDouble())
            val r = p.toDouble()
            assertEquals(line, true, abs(ours - r) <= 2e-8 || abs(ours - r) <= 1e-5 * r)
        }
    }
}
