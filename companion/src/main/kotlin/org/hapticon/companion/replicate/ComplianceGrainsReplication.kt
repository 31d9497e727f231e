package org.hapticon.companion.replicate

import org.hapticon.companion.study.printTask1
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.electrotactile.PulseTrain
import org.hapticon.sensor.electrotactile.TimeDivisionScan
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.grains.GrainDecider
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.study.compliance.ComplianceAnalysis
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceSimulation
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.ShapeDrawings
import java.io.PrintStream
import java.util.Locale

/**
 * Shaping Compliance (CHI 2024; the seed text `003_8ca1dc8f53472543.txt`): every published rule the
 * project implements, the paper's value with its line beside ours, then the paper's results beside nothing of ours (no
 * study of our own was run) and, in a table of their own, the analysis run on simulated people.
 */
object ComplianceGrainsReplication : Replication {
    override val id: String = "003"
    override val names: List<String> = listOf("shaping-compliance")
    override val title: String = "Shaping Compliance: electrotactile grains, electrodes, protocol and analysis"

    private const val SEED = "003_8ca1dc8f53472543.txt"

    /** Grains [GrainDecider] fires over a 20 s linear press across the default 0–10 N range at 1 kHz with [grains] requested. */
    fun grainsPerSlowPress(grains: Int): Int {
        val decider = GrainDecider(GrainSettings(grainCount = grains), 1000.0)
        return (0 until 21_000).count { decider.offer(minOf(10.0, it / 2000.0)) }
    }

    /** Distinct bins a force sweep of the default 0–10 N range in 10 000 steps passes through, with [grains] requested. */
    fun binsSwept(grains: Int): Int {
        val bins = GrainSettings(grainCount = grains).bins
        return (0..10_000).map { bins.binOf(it / 1000.0) }.distinct().size
    }

    /**
     * The spacing in ms of the grains the board's decision (grains.cpp's Kotlin twin, [FirmwareGrainParams.deciderSettings])
     * fires at 1 kHz on [mask] when the force rises four bins per sample, so only the dead time holds grains back.
     */
    fun rapidPressSpacingMillis(mask: ElectrodeMask): Int {
        val params = FirmwareGrainParams.of(99, BinDistribution.LINEAR, FirmwareForceRange(0, 1000), mask.pattern, List(9) { 60 })
        val decider = GrainDecider(params.deciderSettings().copy(cutoffHz = 499.0), 1000.0)
        val onsets = (0 until 30).filter { k -> decider.offer(k * 40.0) }
        return onsets[2] - onsets[1]
    }

    override fun run(out: PrintStream) {
        out.println("source: \"Shaping Compliance: Inducing Haptic Illusion of Compliance in Different Shapes with Electrotactile Grains\", CHI 2024; full text $SEED")
        out.println("cited as :LINE below ($SEED:LINE)")

        out.println()
        out.println("grains over a full press (bins swept by a 0-10 N sweep; grains GrainDecider fires over a 20 s linear press at 1 kHz):")
        out.println("  paper: (number of grains) = (number of bins) - 1, 9-39 grains = 10-40 bins, linear (:95, :97)")
        out.println("  requested  bins swept  grains fired")
        for (g in ComplianceStudy.GRAINS) {
            out.println(String.format(Locale.ROOT, "  %9d  %10d  %12d", g, binsSwept(g), grainsPerSlowPress(g)))
        }

        out.println()
        out.println("dead time: paper \"did not trigger a new grain while a previous one was still being delivered\" (:97); no duration printed.")
        out.println("  a grain's delivery from the published pulses (2 at 125 Hz, :99) and scan (250 us per electrode, :105, :123):")
        out.println("  shape            electrodes  delivery   board dead time   grains 1 kHz apart on a rapid press")
        for (mask in ComplianceStudy.DRAWN_SHAPES) {
            val delivery = TimeDivisionScan.deliveryMicros(mask.pattern)
            val params = FirmwareGrainParams.of(19, BinDistribution.LINEAR, FirmwareForceRange(0, 1023), mask.pattern, List(9) { 60 })
            out.println(
                String.format(
                    Locale.ROOT, "  %-15s  %10d  %6.2f ms  %12.2f ms  %15d ms",
                    ComplianceCondition.shapeName(mask), mask.pattern.activeCount, delivery / 1000.0, params.grainMicros / 1000.0, rapidPressSpacingMillis(mask),
                ),
            )
        }

        out.println()
        out.println("electrode conditions on the 3x3 array (1.5 mm electrodes, 3 mm apart, centre over the FSR: :115, :117):")
        out.println("  shape            " + "paper (text)".padEnd(50) + "ours         members (0-8 row by row)")
        val paper = mapOf(
            ElectrodeMask.LARGE_SQUARE to "3x3, 9 electrodes (:144, :107)",
            ElectrodeMask.SMALL_SQUARE to "2x2, 4 (:144, :107); corner: Figure 5 only",
            ElectrodeMask.VERTICAL_LINE to "2x3 cols x rows, 6 (:144); side: Figure 5 only",
            ElectrodeMask.HORIZONTAL_LINE to "3x2, 6 (:144); side: Figure 5 only",
            ElectrodeMask.TRIANGLE to "6, \"diagonal\" (:107, :171); cells: Figure 5 only",
        )
        for ((mask, text) in paper) {
            out.println(String.format(Locale.ROOT, "  %-15s  %-48s  %-11s  %s", ComplianceCondition.shapeName(mask), text, mask.pattern, mask.pattern.electrodes().joinToString(",")))
        }
        out.println("  fewer than 4 electrodes: too weak in the paper's pilot (:107); ours refused for grains (ElectrodePattern.isStrongEnoughForCompliance)")

        out.println()
        out.println("calibration, pulses and circuit:")
        row(out, "", "paper", "ours")
        val stimulus = FirmwareStimulus(0, ElectrotactileCalibration.START_STEP)
        row(out, "per electrode", "each of 9 in order, 200 ms (:152)", "electrodes 1-9 in order, ${stimulus.durationMillis} ms (STIMULATE, ${stimulus.pulseCount} pulses)")
        row(out, "starting current", "0.8 mA, raised gradually (:152)", String.format(Locale.ROOT, "%.2f mA (step %d), +1 step (%.4f mA)", AmplitudeSteps.milliampsOf(ElectrotactileCalibration.START_STEP), ElectrotactileCalibration.START_STEP, AmplitudeSteps.MILLIAMPS_PER_STEP))
        row(out, "whole-array check", "39 grains, all; uniform, pain-free (:152)", "${ElectrotactileCalibration.CHECK_GRAINS} grains on all 9; one electrode or all a step")
        row(out, "when", "before each repetition (:152)", "Task 1 as published: before each of its ${ComplianceStudy.PROTOCOL.repetitions} blocks")
        row(out, "mean amplitude", "1.59 mA (SD 0.27); Task 2 1.70 (0.28) (:152, :175)", "per person (a result, not a setting); cap 2.70 mA")
        row(out, "amplitude range", "0-2.7 mA in 200 steps (:123)", String.format(Locale.ROOT, "%d steps of %.4f mA, cap %.2f", AmplitudeSteps.STEPS, AmplitudeSteps.MILLIAMPS_PER_STEP, AmplitudeSteps.milliampsOf(AmplitudeSteps.STEPS)))
        val grain = PulseTrain.GRAIN
        row(out, "pulses per grain", "2 anodic, 200 us, 125 Hz (:99)", "${grain.pulseCount} ${grain.polarity.name.lowercase()}, ${grain.pulseWidthMicros.toInt()} us, ${grain.frequencyHz.toInt()} Hz")
        row(out, "scan", "50 us after each 200 us pulse, 4 kHz (:105, :123)", "${TimeDivisionScan.PULSE_MICROS} us + ${TimeDivisionScan.GAP_MICROS} us (${TimeDivisionScan.SCAN_HZ.toInt()} Hz)")
        row(out, "force filter", "low-pass, cutoff not given (:123)", "paper silent; ours ${GrainSettings.DEFAULT_CUTOFF_HZ.toInt()} Hz first order")
        row(out, "sensor to stimulus", "< 25 ms, stand-alone (:125)", "firmware: first pulse at the crossing sample (grains_test)")

        out.println()
        out.println("protocol:")
        row(out, "", "paper", "ours (default = as published)")
        val task1 = ComplianceStudy.PROTOCOL
        val first = task1.trials(0)
        row(out, "Task 1 trials", "3 grains x 4 shapes x 3 reps = 36 (:144, :150)", "${task1.conditions.size} x ${task1.repetitions} = ${first.size} (${task1.id})")
        row(out, "order", "counterbalanced per repetition (:150)", "${first.count { it.breakBefore } + 1} blocks, Williams rows; paper silent on the scheme")
        row(out, "breaks, calibration", "break after each rep.; recalibrated (:150, :152)", "break before ${first.count { it.breakBefore }} blocks, calibration before ${first.count { it.calibrateBefore }}")
        row(out, "rating", "compliance vs desk = 0, signed, any numbers (:148)", "signed finite number; \"compliance\", not \"soft\"")
        row(out, "normalisation", "raw / SD per participant x repetition (:154)", "MagnitudeEstimation.standardize (sample SD: paper silent)")
        row(out, "analysis", "ART ANOVA RM + ART-C, reference rows 0 (:161)", "AlignedRankTransform = base-R reference (oracle test)")
        val task2 = ComplianceStudy.SHAPES_PROTOCOL
        row(out, "Task 2 trials", "5 shapes x 39 grains x 3 = 15, random (:171, :175)", "${task2.conditions.size} x ${task2.repetitions} = ${task2.trials(0).size}, one shuffled list (${task2.id})")
        row(out, "Task 2 answer", "more compliant? then draw contour(s) (:175)", "yes/no, then contours drawn on the phone")
        row(out, "Task 2 heatmaps", "340x340, 256 levels, shown from 128 (:177, :159)", "${ShapeDrawings.SIZE}x${ShapeDrawings.SIZE}, 256 levels, shown from ${ShapeDrawings.THRESHOLD}")
        row(out, "ours, a variant", "-", "${ComplianceStudy.EXTENDED.id}: 0/9/19/39 x 5 shapes x 3 = ${ComplianceStudy.EXTENDED.trialCount}, one list, calibrated once")

        out.println()
        out.println("the paper's results (12 participants, :131); no study of ours has been run, so nothing of ours stands beside them:")
        out.println("  grains x electrode: grains p < .001, electrode p < .001, interaction p < .001; every grain pair p < .01 (:163)")
        out.println("  number of electrodes (0/4/6/9): p < .001; every pair p < .001 (:165)")
        out.println("  horizontal vs vertical line: p = .67 (:165)")
        out.println("  Task 2: drawn contours roughly match the active electrodes; larger vertical offsets (:179)")

        out.println()
        out.println("simulated, not comparable: the analysis run end to end on 12 simulated people (ComplianceSimulation, seed 1)")
        printTask1(ComplianceAnalysis.run(ComplianceSimulation.answers(participants = 12, seed = 1)), out)
    }

    private fun row(out: PrintStream, what: String, paper: String, ours: String) {
        out.println(String.format(Locale.ROOT, "  %-20s  %-50s  %s", what, paper, ours))
    }
}
