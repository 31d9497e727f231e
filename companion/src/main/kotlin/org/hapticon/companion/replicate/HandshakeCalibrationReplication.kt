package org.hapticon.companion.replicate

import org.hapticon.sensor.glove.AdcScale
import org.hapticon.sensor.glove.CalibrationState
import org.hapticon.sensor.glove.DividerReading
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.FlexCalibrationFlow
import org.hapticon.sensor.glove.FlexDivider
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.HandRegion
import org.hapticon.sensor.glove.HandshakeDetector
import org.hapticon.sensor.glove.HandshakeSession
import org.hapticon.sensor.glove.InteractionPressureModel
import org.hapticon.sensor.glove.SettleCriterion
import org.hapticon.sensor.safety.SafetyLimits
import java.io.PrintStream
import java.util.Locale
import java.util.SplittableRandom
import kotlin.math.sqrt

/**
 * 002 — the tele-handshake glove of Watatani, Nagano, Tazaki & Yokokohji (Electronics 14(3):537, 2025; [PAPER]):
 * every rule Hapticon takes from it beside ours with its line, Table 1 per participant with its mean and SD
 * recomputed from its rows, why the printed 22 Ω divider cannot work with the paper's own sensor, the face-to-face
 * measurement the model's constants come from, and, in a table of its own, a simulation of the two-take calibration.
 */
object HandshakeCalibrationReplication : Replication {
    override val id: String = "002"
    override val names: List<String> = listOf("handshake", "glove")
    override val title: String = "Tele-handshake glove (Watatani et al.): divider, calibration, start angle and pressure model"

    /** The paper's text in the papers' index. */
    val PAPER: PaperText = PaperText("002_12aacdd60a14fec1.txt")

    /** One participant's column of Table 1 (002_12aacdd60a14fec1.txt:255-262): thumb and middle-finger α, β. */
    class Table1Participant(val name: String, val thumbAlpha: Double, val thumbBeta: Double, val middleAlpha: Double, val middleBeta: Double)

    /** Table 1's six participants A–F (002_12aacdd60a14fec1.txt:258-262). */
    val TABLE_1: List<Table1Participant> = listOf(
        Table1Participant("A", 0.014, 17.80, 0.017, 18.92),
        Table1Participant("B", 0.014, 17.60, 0.024, 14.01),
        Table1Participant("C", 0.014, 20.63, 0.017, 22.67),
        Table1Participant("D", 0.013, 15.51, 0.016, 14.69),
        Table1Participant("E", 0.012, 16.59, 0.016, 14.49),
        Table1Participant("F", 0.027, 8.88, 0.021, 12.65),
    )

    /** Table 1's printed mean column, thumb α, β, middle α, β (002_12aacdd60a14fec1.txt:259-262). */
    val TABLE_1_MEAN: List<Double> = listOf(0.016, 16.17, 0.019, 16.24)

    /** Table 1's printed S.D. column, in [TABLE_1_MEAN]'s order. */
    val TABLE_1_SD: List<Double> = listOf(0.005, 3.61, 0.003, 3.46)

    /** Table 6: the three following participants' thumb angles in the Both Weak phase (002_12aacdd60a14fec1.txt:287-291). */
    val TABLE_6_THUMB: List<Double> = listOf(28.6, 9.57, 22.4)

    /** Table 6: their middle-finger angles (002_12aacdd60a14fec1.txt:292); the smallest is θM0. */
    val TABLE_6_MIDDLE: List<Double> = listOf(55.1, 43.2, 30.9)

    /** How far off a simulated person holds a calibration pose, SD in degrees (ours: the paper reads a goniometer). */
    const val POSE_SD_DEGREES: Double = 3.0

    /** Simulated calibrations per arm. */
    const val TRIALS: Int = 500

    /** Mean and population SD (÷ n) of [values]: the form Table 1's and Table 6's S.D. columns turn out to use. */
    fun meanAndSd(values: List<Double>): Pair<Double, Double> {
        val mean = values.average()
        return mean to sqrt(values.sumOf { (it - mean) * (it - mean) } / values.size)
    }

    /** One divider's output over a 0–90° bend of the paper's mean thumb. */
    class Swing(val fixedKiloohms: Double, val voltsAt0: Double, val voltsAt90: Double) {
        val volts: Double get() = voltsAt90 - voltsAt0

        /** Counts of an ADC of [scale] the bend spans. */
        fun counts(scale: AdcScale): Double = volts / scale.voltsOf(1)
    }

    /** The swing of the paper's mean thumb (Table 1) through a 5 V divider with [fixedKiloohms]. */
    fun swing(fixedKiloohms: Double): Swing {
        val divider = FlexDivider(fixedKiloohms = fixedKiloohms)
        val thumb = FlexCalibration.THUMB_DEFAULT
        return Swing(fixedKiloohms, divider.voltsFor(thumb.resistanceAt(0.0)), divider.voltsFor(thumb.resistanceAt(90.0)))
    }

    /** RMS relative errors of (α, β) over [TRIALS] simulated calibrations with [takes] per pose. */
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

    /** The palm's pressure (V) of a fresh [HandshakeSession] after one step at these angles; 0 when it did not start. */
    fun palmAfterOneStep(selfMiddle: Double, partnerThumb: Double, partnerMiddle: Double): Double =
        HandshakeSession().step(0.0, selfMiddle, partnerThumb, partnerMiddle).command(HandRegion.PALM).pressureVolts

    override fun run(out: PrintStream) {
        val p = PAPER
        val model = InteractionPressureModel()
        out.println(p.legend)
        out.println()
        out.println("Rules:")
        out.printRules(
            listOf(
                RuleRow("flex sensors", "thumb IP and middle-finger PIP joints", p.at("61"), "thumb and middle flex channels (GloveFinger)", "same"),
                RuleRow("divider supply Vin", "5 V", p.at("62"), fmt(FlexDivider.DEFAULT_SUPPLY_VOLTS, 1) + " V", "same"),
                RuleRow("divider fixed resistor", "22 Ω", p.at("62"), "${fmt(FlexDivider.DEFAULT_FIXED_KILOOHMS, 0)} kΩ", "different: 22 Ω leaves ~5 mV of swing (below); 33 kΩ is the E6 value nearest √(R0°·R90°)"),
                RuleRow("resistance from Vout", "R = Vout/(Vin − Vout)·Rfix (Eq. 4)", p.at("63"), "FlexDivider.resistanceOf", "same"),
                RuleRow("calibration model", "ln R = α·θ + ln β (Eq. 5)", p.at("85"), "FlexCalibration", "same; β read as kΩ (paper gives no unit)"),
                RuleRow("fit", "least squares", p.at("84"), "ordinary least squares on (θ, ln R)", "same"),
                RuleRow("calibration poses", "0, 30, 50, 70, 90°", p.at("77"), FlexCalibrationFlow.DEFAULT_POSES_DEGREES.joinToString(", ") { fmt(it, 0) } + "°", "same"),
                RuleRow("repetitions", "whole procedure twice, averaged", p.at("79, 83"), "${FlexCalibrationFlow.DEFAULT_TAKES_PER_POSE} takes per pose, averaged", "same count; order differs: paper thumb, middle, thumb, middle; ours one finger's two rounds, then the other's"),
                RuleRow("calibration participants", "6 (5 male, 1 female)", p.at("67"), "each user calibrates their own glove", "same rule (per user, before use, " + p.at("84") + ")"),
                RuleRow("thumb α, β", "0.016, 16.17 (Table 1 mean)", p.at("259-260"), "${FlexCalibration.THUMB_DEFAULT.alphaPerDegree}, ${FlexCalibration.THUMB_DEFAULT.betaKiloohms} kΩ", "same, as the uncalibrated default"),
                RuleRow("middle α, β", "0.019, 16.24 (Table 1 mean)", p.at("261-262"), "${FlexCalibration.MIDDLE_DEFAULT.alphaPerDegree}, ${FlexCalibration.MIDDLE_DEFAULT.betaKiloohms} kΩ", "same, as the uncalibrated default"),
                RuleRow(
                    "handshake start", "own middle finger exceeds 30.9°", p.at("138, 169-170"),
                    "own middle > ${fmt(HandshakeDetector.START_ABOVE_DEGREES, 1)}°: partner at 60°/90°, own 30.9° -> palm ${fmtVolts(palmAfterOneStep(30.9, 60.0, 90.0))}; own 31° -> ${fmtVolts(palmAfterOneStep(31.0, 60.0, 90.0))}",
                    "same",
                ),
                RuleRow("initiation angle θM0", "30.9° = smallest Table 6 middle angle", p.at("168, 296"), fmt(model.middleZeroDegrees, 1) + "°", "same"),
                RuleRow("thumb initiation angle θT0", "none set for the thumb", p.at("167"), "θT0 = ${fmt(model.thumbZeroDegrees, 0)}° in Eq. 6", "paper silent on Eq. 6's θT0: 0° counts the thumb from straight"),
                RuleRow("handshake end", "—", "—", "own middle ≤ 30.9 − ${fmt(HandshakeDetector.DEFAULT_HYSTERESIS_DEGREES, 0)}°", "paper silent: 2° of hysteresis so a finger resting at 30.9° does not flicker"),
                RuleRow("θTmax, θMmax", "100°, 105°", p.at("126"), "${fmt(model.thumbMaxDegrees, 0)}°, ${fmt(model.middleMaxDegrees, 0)}°", "same"),
                RuleRow("interaction pressure", "Eq. 6: α/2 nT + α/2 nM (self) + β/2 nT + β/2 nM (partner)", p.at("127"), "InteractionPressureModel, n clamped to 0..1", "same; the clamp is ours (paper silent beyond θmax)"),
                RuleRow("motor range", "fingers 190°, palm 310°", p.at("112"), "${fmt(SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 0)}°, ${fmt(SafetyLimits.PALM_ACTUATOR_MAX_DEGREES, 0)}° (hard limits)", "same"),
                RuleRow("pressure -> motor angle table", "measured every 10°, 3 people x 2 runs; values only in Figure 10", p.at("111-117, 241"), "5 points, Pmin..Pmax -> 0..max, linear", "different: the figure's values are not in the text; ours is a placeholder to replace with a table measured on the actuator"),
                RuleRow("table interpolation", "linear", p.at("118"), "ActuatorTable, linear, clamped", "same"),
            ),
        )
        out.println()
        out.println("Tables 2-5 (per region) beside HandRegion:")
        val tableLines = mapOf(HandRegion.THUMB to "266, 274", HandRegion.INDEX to "267, 275", HandRegion.MIDDLE to "268, 276", HandRegion.RING to "269, 277", HandRegion.PINKY to "270, 278", HandRegion.PALM to "282, 286")
        val published = mapOf(
            HandRegion.THUMB to listOf(0.93, 2.57, 0.77, 0.23), HandRegion.INDEX to listOf(0.37, 1.29, 0.70, 0.30),
            HandRegion.MIDDLE to listOf(0.62, 2.30, 0.82, 0.18), HandRegion.RING to listOf(0.19, 1.23, 0.69, 0.31),
            HandRegion.PINKY to listOf(0.33, 1.66, 0.67, 0.33), HandRegion.PALM to listOf(1.23, 4.10, 0.17, 0.83),
        )
        out.printTable(
            listOf("region", "paper Pmin, Pmax (V), α, β", "cited", "ours", "same?"),
            HandRegion.ALL.map { r ->
                val paper = published.getValue(r)
                val ours = listOf(r.minPressureVolts, r.maxPressureVolts, r.selfWeight, r.partnerWeight)
                listOf(r.label, paper.joinToString(", ") { fmt(it, 2) }, p.at(tableLines.getValue(r)), ours.joinToString(", ") { fmt(it, 2) }, if (paper == ours) "same" else "DIFFERENT")
            },
        )
        out.println()
        out.println("Table 1 per participant (calibration, " + p.at("255-262") + "); mean and SD recomputed from its six rows:")
        val columns = listOf<(Table1Participant) -> Double>({ it.thumbAlpha }, { it.thumbBeta }, { it.middleAlpha }, { it.middleBeta })
        val decimals = listOf(3, 2, 3, 2)
        out.printTable(
            listOf("participant", "thumb α", "thumb β", "middle α", "middle β"),
            TABLE_1.map { t -> listOf(t.name) + columns.indices.map { fmt(columns[it](t), decimals[it]) } } +
                listOf(
                    listOf("paper's mean") + TABLE_1_MEAN.indices.map { fmt(TABLE_1_MEAN[it], decimals[it]) },
                    listOf("recomputed mean") + columns.indices.map { c -> fmt(meanAndSd(TABLE_1.map(columns[c])).first, decimals[c] + 1) },
                    listOf("paper's S.D.") + TABLE_1_SD.indices.map { fmt(TABLE_1_SD[it], decimals[it]) },
                    listOf("recomputed SD (÷n)") + columns.indices.map { c -> fmt(meanAndSd(TABLE_1.map(columns[c])).second, decimals[c] + 1) },
                    listOf("ours (default)", fmt(FlexCalibration.THUMB_DEFAULT.alphaPerDegree, 3), fmt(FlexCalibration.THUMB_DEFAULT.betaKiloohms, 2), fmt(FlexCalibration.MIDDLE_DEFAULT.alphaPerDegree, 3), fmt(FlexCalibration.MIDDLE_DEFAULT.betaKiloohms, 2)),
                ),
        )
        out.println("The printed S.D. is the population SD (÷ n); ÷ (n − 1) would give thumb α ${fmt(sampleSd(TABLE_1.map { it.thumbAlpha }), 4)}, β ${fmt(sampleSd(TABLE_1.map { it.thumbBeta }), 2)}.")
        out.println()
        out.println("Why not 22 Ω: the paper's mean thumb (16.17 kΩ at 0°, 68.25 kΩ at 90°) through a 5 V divider:")
        out.printTable(
            listOf("Rfix", "source", "Vout 0°", "Vout 90°", "swing", "10-bit counts", "12-bit counts", "° per 10-bit count"),
            listOf(
                Triple(FlexDivider.PAPER_PRINTED_FIXED_KILOOHMS, "22 Ω", "paper as printed, " + p.at("62")),
                Triple(FlexDivider.PAPER_READ_AS_KILOOHMS, "22 kΩ", "the same read in β's kΩ"),
                Triple(FlexDivider.DEFAULT_FIXED_KILOOHMS, "33 kΩ", "ours (FlexDivider default)"),
            ).map { (kiloohms, name, source) ->
                val s = swing(kiloohms)
                val counts = s.counts(AdcScale.TEN_BIT)
                listOf(name, source, fmt(s.voltsAt0, 4) + " V", fmt(s.voltsAt90, 4) + " V", fmt(1000 * s.volts, 1) + " mV", fmt(counts, 1), fmt(s.counts(AdcScale.TWELVE_BIT), 1), fmt(90.0 / counts, 2))
            },
        )
        out.println("ADCs over 0-5 V; the paper's A/D (AIO-121602LN-USB, ${p.at("62")}) states neither bits nor range. Widest swing: Rfix = √(R0°·R90°) = ${fmt(FlexDivider.widestSwingKiloohms(FlexCalibration.THUMB_DEFAULT.resistanceAt(0.0), FlexCalibration.THUMB_DEFAULT.resistanceAt(90.0)), 1)} kΩ.")
        out.println()
        out.println("The face-to-face measurement the model's constants come from (Section 3.4; Hapticon uses its results, Tables 2-7, and does not run it):")
        out.printTable(
            listOf("phase", "paper", "cited"),
            listOf(
                listOf("roles", "9 male participants in their 20s: 6 lead, 3 following; only the following one wears the glove; 6 x 3 = 18 trials", p.at("147, 152")),
                listOf("Both Weak", "both grip weakly, 10 s (handshake initiation)", p.at("148, 152")),
                listOf("Pre-Strong", "only the lead grips strongly, 5 s", p.at("149, 152")),
                listOf("Post-Strong", "only the following grips strongly, 5 s", p.at("150, 152")),
                listOf("Both Strong", "both grip strongly, 5 s", p.at("151, 152")),
                listOf("between phases", "5 s interval, timed by a metronome", p.at("152")),
                listOf("Pmin, Pmax", "from the Both Weak and Both Strong phases", p.at("158, 162")),
                listOf("α, β", "from the differences between phases (the formula is not given)", p.at("158")),
                listOf("θM0", "Table 6's smallest middle angle in Both Weak", p.at("166-170")),
            ),
        )
        val (thumbMean, thumbSd) = meanAndSd(TABLE_6_THUMB)
        val (middleMean, middleSd) = meanAndSd(TABLE_6_MIDDLE)
        out.println(
            "Table 6 (${p.at("287-292")}): thumb ${TABLE_6_THUMB.joinToString(", ") { fmt(it, 2) }}° (paper mean 20.2, SD 7.9; recomputed ${fmt(thumbMean, 2)}, ${fmt(thumbSd, 2)} ÷n); " +
                "middle ${TABLE_6_MIDDLE.joinToString(", ") { fmt(it, 1) }}° (paper 43.1, 9.9; recomputed ${fmt(middleMean, 2)}, ${fmt(middleSd, 2)}); min ${fmt(TABLE_6_MIDDLE.min(), 1)}° = θM0.",
        )
        out.println()
        out.printSimulated(
            String.format(Locale.ROOT, "%d calibrations of a thumb following Table 1's mean, each pose held with SD %.0f° (ours; the paper has no such figure)", TRIALS, POSE_SD_DEGREES),
            listOf("takes per pose", "RMS error of α", "RMS error of β"),
            listOf(1, 2).map { takes ->
                val (a, b) = rmsErrors(takes)
                listOf(takes.toString(), fmt(100 * a, 2) + " %", fmt(100 * b, 2) + " %")
            },
        )
    }

    private fun sampleSd(values: List<Double>): Double {
        val mean = values.average()
        return sqrt(values.sumOf { (it - mean) * (it - mean) } / (values.size - 1))
    }

    private fun fmt(value: Double, decimals: Int): String = String.format(Locale.ROOT, "%.${decimals}f", value)

    private fun fmtVolts(volts: Double): String = if (volts == 0.0) "rest" else fmt(volts, 2) + " V"

    private fun sq(x: Double) = x * x

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; 1 − u keeps the logarithm finite.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * kotlin.math.ln(u)) * kotlin.math.cos(2 * Math.PI * random.nextDouble())
    }
}
