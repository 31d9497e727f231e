package org.hapticon.companion.replicate

import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.electrotactile.PulseTrain
import org.hapticon.sensor.electrotactile.TimeDivisionScan
import org.hapticon.sensor.grains.GrainDecider
import org.hapticon.sensor.grains.GrainSettings
import java.io.PrintStream
import java.util.Locale

/**
 * 001: Shaping Compliance's published rules (the electrotactile compliance illusion, CHI 2024) against ours: grains
 * per full press (grains = bins − 1), the electrode conditions, calibration and the pulses.
 */
object ComplianceGrainsReplication : Replication {
    override val id: String = "001"
    override val title: String = "Shaping Compliance: electrotactile grains, electrodes and calibration"

    /** Grains a 20 s linear press over the default 0–10 N range at 1 kHz fires with [grains] requested. */
    fun grainsPerSlowPress(grains: Int): Int {
        val decider = GrainDecider(GrainSettings(grainCount = grains), 1000.0)
        return (0 until 21_000).count { decider.offer(minOf(10.0, it / 2000.0)) }
    }

    override fun run(out: PrintStream) {
        out.println()
        out.println("grains per slow full press (20 s, 0-10 N, 1 kHz):")
        out.println("  requested  paper bins  our bins  paper grains  our grains")
        for (g in listOf(0, 9, 19, 39)) {
            out.println(String.format(Locale.ROOT, "  %9d  %10d  %8d  %12d  %10d", g, g + 1, GrainSettings(grainCount = g).binCount, g, grainsPerSlowPress(g)))
        }
        out.println()
        out.println("electrode conditions (3x3 array):")
        val paper = mapOf(ElectrodeMask.LARGE_SQUARE to 9, ElectrodeMask.VERTICAL_LINE to 6, ElectrodeMask.HORIZONTAL_LINE to 6, ElectrodeMask.SMALL_SQUARE to 4, ElectrodeMask.TRIANGLE to 6)
        out.println("  shape            paper  ours  rows")
        for ((mask, n) in paper) {
            out.println(String.format(Locale.ROOT, "  %-15s  %5d  %4d  %s", mask.name.lowercase(), n, mask.pattern.activeCount, mask.pattern))
        }
        out.println("  fewer than 4 electrodes: paper too weak in the pilot; ours refused for grains (ElectrodePattern.isStrongEnoughForCompliance)")
        out.println()
        out.println("calibration and pulses:      paper                      ours")
        row(out, "stimulus per electrode", "200 ms", "${ElectrotactileCalibration.STIMULUS_MILLIS} ms")
        row(out, "starting current", "0.8 mA", String.format(Locale.ROOT, "%.2f mA (step %d)", AmplitudeSteps.milliampsOf(ElectrotactileCalibration.START_STEP), ElectrotactileCalibration.START_STEP))
        row(out, "amplitude resolution", "200 steps, 0-2.7 mA", String.format(Locale.ROOT, "%d steps of %.4f mA", AmplitudeSteps.STEPS, AmplitudeSteps.MILLIAMPS_PER_STEP))
        row(out, "whole-array check", "39 grains, all", "${ElectrotactileCalibration.CHECK_GRAINS} grains, all 9")
        val grain = PulseTrain.GRAIN
        row(out, "pulses per grain", "2 anodic, 200 us, 125 Hz", "${grain.pulseCount} ${grain.polarity.name.lowercase()}, ${grain.pulseWidthMicros.toInt()} us, ${grain.frequencyHz.toInt()} Hz")
        row(out, "scan", "200 us + 50 us (4 kHz)", "${TimeDivisionScan.PULSE_MICROS} us + ${TimeDivisionScan.GAP_MICROS} us (${TimeDivisionScan.SCAN_HZ.toInt()} Hz)")
        row(out, "force to pulse (firmware)", "< 25 ms", "1 sample period + filter (grains_test: first pulse at the press sample)")
    }

    private fun row(out: PrintStream, what: String, paper: String, ours: String) {
        out.println(String.format(Locale.ROOT, "  %-28s %-26s %s", what, paper, ours))
    }
}
