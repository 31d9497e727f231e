package org.hapticon.companion.replicate

import org.hapticon.sensor.glove.CalibrationState
import org.hapticon.sensor.glove.DividerReading
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.FlexCalibrationFlow
import org.hapticon.sensor.glove.FlexDivider
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.SettleCriterion
import java.io.PrintStream
import java.util.Locale
import java.util.SplittableRandom
import kotlin.math.sqrt

/**
 * 002: the tele-handshake paper's glove calibration: each pose taken twice and averaged ([SOURCE]; only its abstract
 * could be reached, so the paper column rests on the project's summary of it: docs/replication.md). Simulated people whose
 * thumb follows the paper's calibration (α = 0.016/°, β = 16.17 kΩ) hold each pose with a random error
 * (SD [POSE_SD_DEGREES]°); the fitted α and β are compared with one take per pose and with the paper's two.
 */
object HandshakeCalibrationReplication : Replication {
    override val id: String = "002"
    override val names: List<String> = listOf("handshake", "glove")
    override val title: String = "Tele-handshake glove: calibration with each pose taken twice and averaged"

    /**
     * The paper, as its publisher's page names it (mdpi.com/2079-9292/14/3/537, reached in issue 15; the page's
     * abstract, not its Methods, was in the search index).
     */
    const val SOURCE: String = "\"Tele Haptic Handshake Using Distributed Pressure Presentation Device and Mutual " +
        "Interaction Pressure Model\", Electronics 14(3):537, 2025, doi:10.3390/electronics14030537"

    /** How far off a person holds a pose, SD in degrees (our assumption for the simulation). */
    const val POSE_SD_DEGREES: Double = 3.0

    /** Simulated calibrations per arm. */
    const val TRIALS: Int = 500

    /** RMS relative errors of (α, β) over [TRIALS] calibrations with [takes] per pose. */
    fun rmsErrors(takes: Int, seed: Long = 1L): Pair<Double, Double> {
        val truth = FlexCalibration.THUMB_DEFAULT
        val random = SplittableRandom(seed)
        var alpha = 0.0
        var beta = 0.0
        repeat(TRIALS) {
            val flow = FlexCalibrationFlow(GloveFinger.THUMB, criterion = SettleCriterion(windowSamples = 2), takesPerPose = takes)
            while (true) {
                val waiting = flow.beginPose() as? CalibrationState.Settling ?: break
                val held = waiting.targetDegrees + POSE_SD_DEGREES * gaussian(random)
                val reading = DividerReading.Resistance(truth.resistanceAt(held))
                flow.offer(reading)
                flow.offer(reading)
            }
            val fit = (flow.state as CalibrationState.Calibrated).fit.calibration
            alpha += sq(fit.alphaPerDegree / truth.alphaPerDegree - 1)
            beta += sq(fit.betaKiloohms / truth.betaKiloohms - 1)
        }
        return sqrt(alpha / TRIALS) to sqrt(beta / TRIALS)
    }

    override fun run(out: PrintStream) {
        out.println()
        out.println("source: $SOURCE")
        out.println("checked: its abstract (flex sensors measure finger joint angles; region-specific weights; self and partner actions);")
        out.println("         its Methods were not reached: the paper column is the project's summary of it, not re-checked (docs/replication.md)")
        out.println()
        out.println("procedure:                 paper                    ours")
        out.println("  takes per pose           2, averaged              ${FlexCalibrationFlow.DEFAULT_TAKES_PER_POSE}, averaged (two rounds through the poses)")
        out.println("  poses                    0, 30, 50, 70, 90 deg    ${FlexCalibrationFlow.DEFAULT_POSES_DEGREES.joinToString(", ") { it.toInt().toString() }} deg")
        out.println("  thumb alpha, beta        0.016/deg, 16.17         ${FlexCalibration.THUMB_DEFAULT.alphaPerDegree}/deg, ${FlexCalibration.THUMB_DEFAULT.betaKiloohms} kOhm")
        out.println("  middle alpha, beta       0.019/deg, 16.24         ${FlexCalibration.MIDDLE_DEFAULT.alphaPerDegree}/deg, ${FlexCalibration.MIDDLE_DEFAULT.betaKiloohms} kOhm")
        out.println("  divider supply           5 V                      ${FlexDivider.DEFAULT_SUPPLY_VOLTS} V")
        out.println("  divider fixed resistor   not reached (see docs)   ${FlexDivider.DEFAULT_FIXED_KILOOHMS} kOhm: sqrt(16 x 68) kOhm, widest swing")
        out.println()
        out.println(String.format(Locale.ROOT, "simulated thumbs, poses held with SD %.0f deg, %d calibrations each:", POSE_SD_DEGREES, TRIALS))
        out.println("  takes per pose   RMS error alpha   RMS error beta")
        for (takes in listOf(1, 2)) {
            val (a, b) = rmsErrors(takes)
            out.println(String.format(Locale.ROOT, "  %14d   %14.2f %%   %13.2f %%", takes, 100 * a, 100 * b))
        }
    }

    private fun sq(x: Double) = x * x

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; 1 − u keeps the logarithm finite.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * kotlin.math.ln(u)) * kotlin.math.cos(2 * Math.PI * random.nextDouble())
    }
}
