package org.hapticon.companion.replicate

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
import java.io.PrintStream
import java.util.Locale

/**
 * 003: Shaping Compliance's published rules (the electrotactile compliance illusion, CHI 2024) against ours: grains
 * per full press (grains = bins − 1), the electrode conditions, calibration and the pulses.
 */
object ComplianceGrainsReplication : Replication {
    override val id: String = "003"
    override val names: List<String> = listOf("shaping-compliance")
    override val title: String = "Shaping Compliance: electrotactile grains, electrodes and calibration"

    /** Grains a 20 s linear press over the default 0–10 N range at 1 kHz fires with [grains] requested. */
    fun grainsPerSlowPress(grains: Int): Int {
        val decider = GrainDecider(GrainSettings(grainCount = grains), 1000.0)
        return (0 until 21_000).count { decider.offer(minOf(10.0, it / 2000.0)) }
    }

    /**
     * What the board fires over a 20 s linear press at 1 kHz across an [adcBits]-bit ADC's whole range (0 to
     * 2^bits − 1 counts) with [grains] requested and the firmware binning over [range] (grains.cpp's decision, run
     * through its Kotlin twin [FirmwareGrainParams.deciderSettings]): the grains fired and where in the press the last
     * one came (0..1).
     */
    fun boardGrainsPerSlowPress(adcBits: Int, grains: Int, range: FirmwareForceRange): Pair<Int, Double> {
        val full = (1 shl adcBits) - 1
        val params = FirmwareGrainParams.of(grains, BinDistribution.LINEAR, range, ElectrodeMask.LARGE_SQUARE.pattern, List(9) { 0 })
        val decider = GrainDecider(params.deciderSettings(), 1000.0)
        val onsets = (0 until 21_000).filter { k -> decider.offer(if (k < 20_000) (k.toLong() * full / 19_999).toDouble() else full.toDouble()) }
        return onsets.size to (onsets.lastOrNull() ?: 0) / 20_000.0
    }

    override fun run(out: PrintStream) {
        out.println()
        out.println("grains per slow full press (20 s, 0-10 N, 1 kHz):")
        out.println("  requested  paper bins  our bins  paper grains  our grains")
        for (g in listOf(0, 9, 19, 39)) {
            out.println(String.format(Locale.ROOT, "  %9d  %10d  %8d  %12d  %10d", g, g + 1, GrainSettings(grainCount = g).binCount, g, grainsPerSlowPress(g)))
        }
        out.println()
        out.println("the board's grains per slow full press of its raw ADC range (SET_GRAINS range from the device info):")
        out.println("  adc     range     requested  fired  last grain at  | assumed 0..1023: fired  last grain at")
        for (bits in listOf(10, 12)) {
            val range = FirmwareForceRange.ofAdcBits(bits)
            for (g in listOf(9, 19, 39)) {
                val (fired, last) = boardGrainsPerSlowPress(bits, g, range)
                val (oldFired, oldLast) = boardGrainsPerSlowPress(bits, g, FirmwareForceRange(0, 1023))
                out.println(
                    String.format(
                        Locale.ROOT, "  %2d-bit  0..%-5d  %9d  %5d  %12.0f %%  | %21d  %12.0f %%", bits, range.max, g, fired, last * 100, oldFired, oldLast * 100,
                    ),
                )
            }
        }
        out.println()
        out.println("electrode conditions (3x3 array; electrodes 0-8 row by row from the top left, sent as SET_GRAINS electrode bits):")
        val paper = mapOf(ElectrodeMask.LARGE_SQUARE to 9, ElectrodeMask.VERTICAL_LINE to 6, ElectrodeMask.HORIZONTAL_LINE to 6, ElectrodeMask.SMALL_SQUARE to 4, ElectrodeMask.TRIANGLE to 6)
        out.println("  shape            paper  ours  rows         members            bits")
        for ((mask, n) in paper) {
            val members = (0 until 9).filter { mask.pattern.bits and (1 shl it) != 0 }.joinToString(",")
            out.println(String.format(Locale.ROOT, "  %-15s  %5d  %4d  %-11s  %-17s  0x%03x", mask.name.lowercase(), n, mask.pattern.activeCount, mask.pattern, members, mask.pattern.bits))
        }
        out.println("  counts: the paper's; placement on the array: ours, not checked against the paper's figure (docs/replication.md)")
        out.println("  fewer than 4 electrodes: paper too weak in the pilot; ours refused for grains (ElectrodePattern.isStrongEnoughForCompliance)")
        out.println()
        out.println("calibration and pulses:      paper                      ours")
        val stimulus = FirmwareStimulus(0, ElectrotactileCalibration.START_STEP)
        row(out, "stimulus per electrode", "200 ms, one electrode", "${stimulus.durationMillis} ms, 1 electrode: STIMULATE, ${stimulus.pulseCount} pulses")
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
