package org.hapticon.study.analysis

import org.hapticon.study.compliance.ComplianceAnalysis
import org.hapticon.study.compliance.ComplianceSimulation
import org.hapticon.study.compliance.MagnitudeEstimation
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.SplittableRandom
import kotlin.math.abs

/**
 * [AlignedRankTransform] equals a reproduction of ARTool's procedure in base R (`art_reference.R`: alignment, `rank`,
 * `aov(… + Error(subject))`, and ART-C contrasts from `lm` and `vcov` with `ptukey`), run live: on Shaping Compliance's
 * three analyses of simulated answers (whole-number ratings, so the aligned ranks tie), on a 3-factor design and on one
 * with unequal level counts.
 */
class AlignedRankTransformOracleTest {
    @get:Rule
    val folder = TemporaryFolder()

    private fun assertClose(what: String, expected: Double, actual: Double, relative: Double = 1e-9, absolute: Double = 1e-12) {
        val ok = abs(expected - actual) <= absolute || abs(expected - actual) <= relative * abs(expected)
        if (!ok) assertEquals(what, expected, actual, 0.0)
    }

    private fun csv(factors: List<String>, rows: List<ArtObservation>): File {
        val file = folder.newFile()
        file.writeText(buildString {
            append("subject,${factors.joinToString(",")},value\n")
            for (o in rows) append("${o.subject},${o.levels.joinToString(",")},${"%.17g".format(java.util.Locale.ROOT, o.value)}\n")
        })
        return file
    }

    /** Runs both on [rows] and compares every ANOVA row and every contrast of [contrastFactors]. */
    private fun compare(factors: List<String>, rows: List<ArtObservation>, contrastFactors: List<String>) {
        val data = csv(factors, rows)
        val reference = RScript.run(folder.root, "art_reference.R", data.path, factors.joinToString(","), contrastFactors.joinToString(","))
        val art = AlignedRankTransform(factors, rows)
        val anova = art.anova()
        val rAnova = reference.filter { it.startsWith("ANOVA,") }.map { it.split(',') }
        assertEquals(reference.joinToString("\n"), anova.map { it.effect }, rAnova.map { it[1] })
        for ((ours, r) in anova.zip(rAnova)) {
            assertClose("${ours.effect} F", r[2].toDouble(), ours.f)
            assertEquals("${ours.effect} df", r[3].toInt(), ours.dfEffect)
            assertEquals("${ours.effect} error df", r[4].toInt(), ours.dfError)
            assertClose("${ours.effect} p", r[5].toDouble(), ours.p, absolute = 1e-300)
        }
        val contrasts = contrastFactors.flatMap { art.contrasts(it) }
        val rContrasts = reference.filter { it.startsWith("CONTRAST,") }.map { it.split(',') }
        assertEquals(rContrasts.map { it.subList(1, 4) }, contrasts.map { listOf(it.factor, it.first, it.second) })
        for ((ours, r) in contrasts.zip(rContrasts)) {
            val name = "${ours.first} - ${ours.second}"
            assertClose("$name estimate", r[4].toDouble(), ours.estimate, absolute = 1e-9)
            assertClose("$name SE", r[5].toDouble(), ours.standardError)
            assertEquals("$name df", r[6].toInt(), ours.df)
            assertClose("$name t", r[7].toDouble(), ours.t, absolute = 1e-9)
            // R's ptukey is accurate to about 1e-8 absolute (and gives 0 far out in the tail): compare there.
            assertClose("$name p (Tukey)", r[8].toDouble(), ours.p, relative = 1e-5, absolute = 2e-8)
        }
    }

    @Test
    fun complianceAnalyses_onSimulatedAnswers_equalTheBaseRReference() {
        val scores = MagnitudeEstimation.standardize(ComplianceSimulation.answers(participants = 12, seed = 7))
        compare(listOf(ComplianceAnalysis.GRAINS, ComplianceAnalysis.ELECTRODE), ComplianceAnalysis.grainsByShapeData(scores), listOf(ComplianceAnalysis.GRAINS, ComplianceAnalysis.ELECTRODE))
        compare(listOf(ComplianceAnalysis.ELECTRODES), ComplianceAnalysis.electrodeCountData(scores), listOf(ComplianceAnalysis.ELECTRODES))
        compare(listOf(ComplianceAnalysis.ORIENTATION), ComplianceAnalysis.orientationData(scores), listOf(ComplianceAnalysis.ORIENTATION))
    }

    @Test
    fun weakEffects_pValuesAcrossTheRange_equalTheBaseRReference() {
        // Small effects and few people: p-values from near 0 to near 1, where Tukey's tail is most sensitive.
        for (seed in 1L..3L) {
            val scores = MagnitudeEstimation.standardize(ComplianceSimulation.answers(participants = 4, seed = seed, grainWeight = 0.05, electrodeWeight = 0.02, noise = 1.0))
            compare(listOf(ComplianceAnalysis.GRAINS, ComplianceAnalysis.ELECTRODE), ComplianceAnalysis.grainsByShapeData(scores), listOf(ComplianceAnalysis.GRAINS))
        }
    }

    @Test
    fun threeFactors_withTies_equalTheBaseRReference() {
        val random = SplittableRandom(3)
        val rows = (1..5).flatMap { s ->
            listOf("a1", "a2").flatMap { a ->
                listOf("b1", "b2", "b3").flatMap { b ->
                    listOf("c1", "c2").flatMap { c ->
                        List(2) { ArtObservation("s$s", listOf(a, b, c), (random.nextInt(7) + (if (a == "a2") 2 else 0) + s).toDouble()) }
                    }
                }
            }
        }
        compare(listOf("A", "B", "C"), rows, listOf("B"))
    }
}
