package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.study.analysis.AlignedRankTransform
import org.hapticon.study.analysis.ArtContrast
import org.hapticon.study.analysis.ArtEffect
import org.hapticon.study.analysis.ArtObservation
import org.hapticon.study.analysis.Descriptives

/** One cell of Figure 4a: the standardized scores of [grains] grains on [shape] (0 grains: the added reference). */
public data class ComplianceCell(val grains: Int, val shape: ElectrodeMask, val n: Int, val median: Double)

/**
 * Shaping Compliance's Task 1 analysis (003_8ca1dc8f53472543.txt:154–:165) on one study's answers:
 * - [grainsByShape]: ART ANOVA over grains (0, 9, 19, 39) × electrode condition, the 0-grain reference added as
 *   score 0 (Figure 4a; the paper found both factors and their interaction at p < .001, :163), with [grainContrasts],
 *   the ART-C post-hoc over the grain levels (all pairs p < .01, :163);
 * - [electrodeCount]: ART ANOVA over the number of active electrodes (0, 4, 6, 9; Figure 4b; p < .001, :165) with
 *   [electrodeContrasts] (all pairs p < .001);
 * - [orientation]: ART ANOVA of horizontal against vertical line (Figure 4c; p = .67, :165);
 * - [cells]: each condition's median standardized score (Figure 4 shows medians and 95 % CIs; the CI's method is paper
 *   silent, so it is not computed here).
 * [leftOut] counts answers to conditions outside Task 1's twelve (our extended variant's 0-grain and triangle trials).
 */
public data class ComplianceAnalysisResult(
    val participants: Int,
    val cells: List<ComplianceCell>,
    val grainsByShape: List<ArtEffect>,
    val grainContrasts: List<ArtContrast>,
    val electrodeCount: ArtEffect,
    val electrodeContrasts: List<ArtContrast>,
    val orientation: ArtEffect,
    val leftOut: Int,
)

/**
 * Builds the paper's three analyses from raw Task 1 answers: each participant's answers standardized per repetition
 * ([MagnitudeEstimation.standardize], :154), then the reference rows added ("We manually added reference conditions
 * (= no stimuli, score = 0) to the raw data in the analysis", :161) and an [AlignedRankTransform] with the participant
 * as the repeated-measures error term ("ART ANOVA for repeated measures", :161).
 *
 * How many reference rows is paper silent. Ours keep each analysis a complete design: for grains × electrode one 0-grain
 * row per participant, repetition and electrode condition (the 0 level then has as many rows as 9, 19 or 39); for the
 * number of electrodes one 0-electrode row per participant, repetition and grain level (as many as one shape, e.g. the
 * 4-electrode small square; the two 6-electrode lines together have twice that). Whether the orientation comparison also
 * had grains as a factor is paper silent: ours compares the two lines alone, every grain level pooled, as Figure 4c shows them.
 */
public object ComplianceAnalysis {
    /** The grain-level factor of Figure 4a's data: levels `0`, `9`, `19`, `39`. */
    public const val GRAINS: String = "grains"

    /** The electrode-condition factor of Figure 4a's data: the shapes' names. */
    public const val ELECTRODE: String = "electrode"

    /** The number-of-electrodes factor of Figure 4b's data: `0`, `4`, `6`, `9`. */
    public const val ELECTRODES: String = "electrodes"

    /** The line-orientation factor of Figure 4c's data: `horizontal-line`, `vertical-line`. */
    public const val ORIENTATION: String = "orientation"

    /**
     * The analysis of [estimates] (raw answers).
     * @throws IllegalArgumentException when a repetition cannot be standardized (all answers equal) or the design is not
     *   complete (a participant missing a condition, or answering one more often than another participant).
     */
    public fun run(estimates: List<MagnitudeEstimate>): ComplianceAnalysisResult {
        val task1 = estimates.filter { it.condition in ComplianceStudy.CONDITIONS }
        val scores = MagnitudeEstimation.standardize(task1)
        val twoFactor = AlignedRankTransform(listOf(GRAINS, ELECTRODE), grainsByShapeData(scores))
        val count = AlignedRankTransform(listOf(ELECTRODES), electrodeCountData(scores))
        val lines = AlignedRankTransform(listOf(ORIENTATION), orientationData(scores))
        val cells = (listOf(0) + ComplianceStudy.GRAINS).flatMap { g ->
            ComplianceStudy.SHAPES.mapNotNull { shape ->
                val values = if (g == 0) {
                    scores.filter { it.condition.mask == shape }.map { 0.0 }
                } else {
                    scores.filter { it.condition == ComplianceCondition(g, shape) }.map { it.value }
                }
                if (values.isEmpty()) null else ComplianceCell(g, shape, values.size, Descriptives.of(values).median)
            }
        }
        return ComplianceAnalysisResult(
            participants = scores.map { it.participant }.distinct().size,
            cells = cells,
            grainsByShape = twoFactor.anova(),
            grainContrasts = twoFactor.contrasts(GRAINS),
            electrodeCount = count.anova().single(),
            electrodeContrasts = count.contrasts(ELECTRODES),
            orientation = lines.anova().single(),
            leftOut = estimates.size - task1.size,
        )
    }

    /** Grains × electrode condition with the 0-grain reference rows (Figure 4a's data). */
    public fun grainsByShapeData(scores: List<MagnitudeEstimate>): List<ArtObservation> {
        val references = scores.map { Triple(it.participant, it.repetition, it.condition.mask) }.distinct()
            .map { (p, _, shape) -> ArtObservation(p, listOf("0", ComplianceCondition.shapeName(shape)), 0.0) }
        // Levels in the paper's order (0, 9, 19, 39; its shapes' order): they are first seen in this order.
        return references.sortedBy { ComplianceStudy.SHAPES.indexOf(shapeOf(it)) } +
            scores.sortedWith(compareBy({ it.condition.grains }, { ComplianceStudy.SHAPES.indexOf(it.condition.mask) }))
                .map { ArtObservation(it.participant, listOf(it.condition.grains.toString(), ComplianceCondition.shapeName(it.condition.mask)), it.value) }
    }

    /** The number of active electrodes with the 0-electrode reference rows (Figure 4b's data). */
    public fun electrodeCountData(scores: List<MagnitudeEstimate>): List<ArtObservation> {
        val references = scores.map { Triple(it.participant, it.repetition, it.condition.grains) }.distinct()
            .map { (p, _, _) -> ArtObservation(p, listOf("0"), 0.0) }
        return references + scores.sortedBy { it.condition.mask.pattern.activeCount }
            .map { ArtObservation(it.participant, listOf(it.condition.mask.pattern.activeCount.toString()), it.value) }
    }

    /** Horizontal against vertical line (Figure 4c's data). */
    public fun orientationData(scores: List<MagnitudeEstimate>): List<ArtObservation> =
        scores.filter { it.condition.mask == ElectrodeMask.HORIZONTAL_LINE || it.condition.mask == ElectrodeMask.VERTICAL_LINE }
            .map { ArtObservation(it.participant, listOf(ComplianceCondition.shapeName(it.condition.mask)), it.value) }

    private fun shapeOf(o: ArtObservation): ElectrodeMask = ElectrodeMask.entries.first { ComplianceCondition.shapeName(it) == o.levels[1] }
}
