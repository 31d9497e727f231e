package org.hapticon.companion.replicate

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.companion.study.StudyDemo
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ProtocolJson
import org.hapticon.study.StudyProtocol
import org.hapticon.study.TaskPresentation
import org.hapticon.study.analysis.IconPairComparison
import org.hapticon.study.analysis.PairedTTest
import org.hapticon.study.analysis.StudyAnalysis
import org.hapticon.study.analysis.StudyResponse
import java.io.PrintStream
import java.util.Locale
import kotlin.math.abs

/**
 * 000 — the haptic icons of Wei, Hu, Li & Feijs ([PAPER]): the paper's Table 3 as printed beside what Hapticon renders
 * (the envelope times, levels and carrier frequencies measured on the samples, in both envelope models), the MIDI
 * formula's frequencies beside the table's rounded ones, the paper's procedure cell by cell with its lines beside the
 * built-in protocols, its t(15) values with the p our t distribution gives them, and, in a table of its own, the same
 * analysis rerun on a simulated study. Measured at Processing Sound's 44.1 kHz.
 */
object HapticIconsReplication : Replication {
    override val id: String = "000"
    override val names: List<String> = listOf("haptic-icons")
    override val title: String = "Haptic icons (Wei et al.): Table 3 stimuli, the study procedure and its t tests"

    /** The paper's text in the papers' index. */
    val PAPER: PaperText = PaperText("000_f26496a15a0d284b.txt")

    /** The rate the study's Processing sketch played at. */
    const val SAMPLE_RATE: Int = 44_100

    /** Table 3's Frequency (Hz) column as printed, stroke, hit, knock, hug (000_f26496a15a0d284b.txt:88-91). */
    val TABLE_3_HZ: List<Int> = listOf(350, 220, 220, 147)

    /** One published paired t test: [pair] ("stroke-hit": stroke − hit) in [task] with t(15) = [t] (000_f26496a15a0d284b.txt:145). */
    class PublishedT(val task: String, val pair: String, val t: Double)

    /** Every t(15) the paper prints, each "p<0.05"; "no significant effect in other pairs" (000_f26496a15a0d284b.txt:131, :145). */
    val PUBLISHED_T: List<PublishedT> = listOf(
        PublishedT(OriginatingStudy.ICONS_TASK, "hit-hug", 2.423),
        PublishedT(OriginatingStudy.ICONS_TASK, "knock-hug", 3.651),
        PublishedT(OriginatingStudy.TEXT_TASK, "stroke-hit", -3.656),
        PublishedT(OriginatingStudy.TEXT_TASK, "hit-hug", 5.000),
        PublishedT(OriginatingStudy.TEXT_TASK, "knock-hug", 2.448),
        PublishedT(OriginatingStudy.STICKERS_TASK, "stroke-hit", -2.522),
        PublishedT(OriginatingStudy.STICKERS_TASK, "stroke-knock", -4.038),
        PublishedT(OriginatingStudy.STICKERS_TASK, "knock-hug", 2.908),
    )

    /** Simulated participants in the rerun: the paper's 16 (000_f26496a15a0d284b.txt:117). */
    const val SIMULATED_PARTICIPANTS: Int = OriginatingStudy.PAPER_PARTICIPANTS

    override fun run(out: PrintStream) {
        val p = PAPER
        out.println(p.legend)
        out.println()
        out.println("Table 3 (${p.at("85-91")}) as printed beside the rendered stimuli, measured on the samples at $SAMPLE_RATE Hz:")
        out.println("attack = onset to the first corner, sustain = to the start of the release, release = to silence,")
        out.println("level = envelope at the start of the release, peak = largest envelope value, f = carrier from zero crossings.")
        out.println()
        out.println(String.format(Locale.ROOT, "%-7s %-16s %8s %8s %6s %8s %6s %4s %9s %7s %5s", "icon", "source", "attack", "sustain", "level", "release", "peak", "note", "f (Hz)", "period", "count"))
        HapticIcon.PRESETS.forEachIndexed { i, icon ->
            out.println(
                String.format(
                    Locale.ROOT, "%-7s %-16s %8.5f %8.5f %6.3f %8.5f %6s %4d %9s %7s %5d",
                    icon.name, "Table 3", icon.attack, icon.sustain, icon.level, icon.release, "—", icon.note.toInt(), TABLE_3_HZ[i].toString(),
                    if (icon.count == 1) "-" else String.format(Locale.ROOT, "%.3f", icon.period), icon.count,
                ),
            )
            for (model in listOf(EnvelopeModel.PROCESSING, EnvelopeModel.PAPER)) {
                val m = measure(icon, model)
                out.println(row("", "${model.name.lowercase()} model", m.attack, m.sustain, m.level, m.release, m.peak, icon.note.toInt(), m.frequency, m.period, m.count))
            }
        }
        out.println()
        out.println("Frequencies: the paper's formula, note = 69 + 12·log2(f/440) (${p.at("78-81")}), solved for f, beside Table 3's printed column:")
        out.printTable(
            listOf("icon", "note", "Table 3 f", "cited", "440·2^((note − 69)/12)", "rendered (zero crossings)", "same?"),
            HapticIcon.PRESETS.mapIndexed { i, icon ->
                val exact = 440.0 * Math.pow(2.0, (icon.note - 69) / 12.0)
                listOf(
                    icon.name, trim(icon.note), "${TABLE_3_HZ[i]} Hz", p.at("${88 + i}"), String.format(Locale.ROOT, "%.2f Hz", exact),
                    String.format(Locale.ROOT, "%.2f Hz", measure(icon, EnvelopeModel.PROCESSING).frequency),
                    if (Math.round(exact).toInt() == TABLE_3_HZ[i]) "same, rounded" else "the table rounds ${String.format(Locale.ROOT, "%.2f", exact)} to ${TABLE_3_HZ[i]}",
                )
            },
        )
        out.println()
        out.println("processing is what the participants felt, and the default everywhere (EnvelopeModel.DEFAULT). It assumes Processing Sound")
        out.println("2.0.1-2.3.1 + JSyn: the paper names only \"the Sound Library in Processing 3\" (${p.at("66, 95")}); it cites work of 2018")
        out.println("(${p.at("175")}), so the study ran in 2018 or later, when Processing 3's Sound library was the JSyn-based 2.x, whose Env")
        out.println("did not change from 2.0.1 to 2.3.1 (docs/envelope-models.md). If it was another version, only stroke's overlapping")
        out.println("repetitions would differ (2.4.0 replaces a running envelope instead of adding to it).")
        out.println("Its attack always peaks at 1 and its 'sustain' ramps from 1 to the level; paper holds the level, as the text describes")
        out.println("(${p.at("66")}). Periods (median spacing) and counts are measured from where the whole render's envelope starts rising.")
        out.println()
        out.println("The envelope at named times of the first repetition, paper / processing, at the sample nearest each time:")
        out.println(String.format(Locale.ROOT, "%-7s %-26s %s", "icon", "times", NAMED_TIMES.joinToString("  ") { String.format(Locale.ROOT, "%-15s", it) }).trimEnd())
        for (icon in HapticIcon.PRESETS) {
            val times = namedTimes(icon)
            val paper = namedValues(icon, EnvelopeModel.PAPER)
            val processing = namedValues(icon, EnvelopeModel.PROCESSING)
            val unit = if (icon.attack < 0.1) 1000.0 else 1.0
            val label = times.joinToString(", ") { String.format(Locale.ROOT, "%s", trim(it * unit)) } + if (unit > 1) " ms" else " s"
            out.println(
                String.format(Locale.ROOT, "%-7s %-26s %s", icon.name, label, paper.indices.joinToString("  ") { String.format(Locale.ROOT, "%-15s", String.format(Locale.ROOT, "%.3f / %.3f", paper[it], processing[it])) }).trimEnd(),
            )
        }
        out.println()
        val paperProtocol = OriginatingStudy.PAPER_PROTOCOL
        val perTrial = OriginatingStudy.PROTOCOL
        out.println("Procedure: the paper, cell by cell, beside the built-in protocols ${paperProtocol.id} and ${perTrial.id}:")
        out.printTable(
            listOf("rule", "paper", "cited", paperProtocol.id, perTrial.id, "same/different and why"),
            procedureRows().map { r -> listOf(r.what, r.inPaper, r.cited, r.of(paperProtocol), r.of(perTrial), r.verdict) },
        )
        out.println()
        out.println("The paper's paired-sample t tests (${p.at("131, 145")}; \"no significant effect in other pairs\"), with the two-sided p")
        out.println("our t distribution gives each published t(15):")
        out.printTable(
            listOf("task", "pair (A − B)", "paper t(15)", "paper p", "p from t(15)"),
            PUBLISHED_T.map { listOf(it.task, it.pair, String.format(Locale.ROOT, "%.3f", it.t), "< 0.05", String.format(Locale.ROOT, "%.4f", PairedTTest.twoSidedP(it.t, 15))) },
        )
        out.println()
        val simulated = simulatedTTests()
        out.printSimulated(
            "$SIMULATED_PARTICIPANTS simulated participants through ${paperProtocol.id}, ratings drawn around our per-icon means " +
                StudyDemo.MEANS.entries.joinToString(", ", "(", ")") { "${it.key} ${it.value}" } + "; shows the analysis runs the paper's test, not its result",
            listOf("task", "pair (A − B)", "n", "df", "t", "p"),
            simulated.map { c ->
                val t = c.tTest!!
                listOf(c.task, "${c.iconA}-${c.iconB}", t.n.toString(), t.df.toString(), t.t?.let { String.format(Locale.ROOT, "%.3f", it) } ?: "—", t.p?.let { String.format(Locale.ROOT, "%.4f", it) } ?: "—")
            },
        )
    }

    /**
     * The paper's analysis, paired t tests of every icon pair within each task (000_f26496a15a0d284b.txt:131), rerun
     * on [SIMULATED_PARTICIPANTS] simulated participants through [OriginatingStudy.PAPER_PROTOCOL] ([StudyDemo.simulate]).
     */
    fun simulatedTTests(): List<IconPairComparison> {
        val rows = StudyDemo.simulate(OriginatingStudy.PAPER_PROTOCOL, SIMULATED_PARTICIPANTS).rows
        return StudyAnalysis.compare(rows.map { StudyResponse(it.participant, it.task, it.icon, it.response.toDouble()) }, tTest = true, wilcoxon = false)
    }

    /** The named times of one repetition, in [namedTimes] order. */
    val NAMED_TIMES: List<String> = listOf("mid-attack", "end of attack", "mid-sustain", "end of sustain", "mid-release")

    /** A/2, A, A + S/2, A + S, A + S + R/2 of [icon] in seconds. */
    fun namedTimes(icon: HapticIcon): DoubleArray =
        doubleArrayOf(icon.attack / 2, icon.attack, icon.attack + icon.sustain / 2, icon.attack + icon.sustain, icon.attack + icon.sustain + icon.release / 2)

    /** [icon]'s envelope under [model] at [SAMPLE_RATE], at the sample nearest each of [namedTimes]. */
    fun namedValues(icon: HapticIcon, model: EnvelopeModel): DoubleArray {
        val renderer = IconRenderer(icon, SAMPLE_RATE, model)
        return namedTimes(icon).map { renderer.envelopeAt(Math.round(it * SAMPLE_RATE)) }.toDoubleArray()
    }

    private fun trim(value: Double): String = String.format(Locale.ROOT, "%.4f", value).trimEnd('0').trimEnd('.')

    /** One procedure row: [what], the paper's value [inPaper] and where its text says so ([cited]), ours per protocol, and the [verdict]. */
    class ProcedureRow(val what: String, val inPaper: String, val cited: String, val of: (StudyProtocol) -> String, val verdict: String)

    /** The procedure rows, each cell of the paper's column cited from its text or marked "paper silent". */
    fun procedureRows(): List<ProcedureRow> {
        val p = PAPER
        return listOf(
            ProcedureRow("participants", "16 (4 male, 12 female, aged 25-30)", p.at("117"), { it.participants?.toString() ?: "open" }, "same (paper protocol); the default leaves it open"),
            ProcedureRow("device", "LG V30's LRA, driven by audio", p.at("95"), { "the phone's vibrator" }, "different: any Android phone with a vibrator"),
            ProcedureRow("envelopes", "Sound Library in Processing 3", p.at("66, 95"), { ProtocolJson.modelName(it.envelopeModel) }, "same; Sound 2.0.1-2.3.1 assumed (above)"),
            ProcedureRow("task order", "1, 2, 3; the last two counterbalanced between participants", p.at("127"), { "${it.fixedFirst.joinToString()} first; rest ${it.taskOrder.jsonName}" }, "same"),
            ProcedureRow("task 1 items", "'Haptic icon 1 feels like stroking.' ... '4 ... hugging.'", p.at("121"), { pr -> pr.tasks.first().question }, "same words; the per-trial protocol numbers icons by position"),
            ProcedureRow(
                "icon numbering", "1 stroke, 2 hit, 3 knock, 4 hug (from the task 1 items)", p.at("121"),
                { pr -> if (pr.tasks.first().stimuli.all { it.number != null }) pr.tasks.first().stimuli.joinToString(", ") { "${it.number} ${it.icon.name}" } else "by position in the order" },
                "same (paper protocol)",
            ),
            ProcedureRow("task 2 item", "'This haptic icon enhance the effect of text.'", p.at("121"), { pr -> pr.tasks[1].question }, "different words: grammar mended; the paper protocol names the icon by number, its items follow the task"),
            ProcedureRow("task 3 item", "'This haptic icon enhance the touch effect of stickers.'", p.at("121"), { pr -> pr.tasks[2].question }, "different words: as task 2"),
            ProcedureRow("scale", "5-point Likert, 1 strongly disagree .. 5 strongly agree", p.at("121"), { "${it.scale.points}-point" }, "same"),
            ProcedureRow(
                "presentation", "a virtual partner has sent the four icons, one screen (Fig. 4); participants press each", p.at("95, 127"),
                { pr -> if (pr.tasks.all { it.presentation == TaskPresentation.TOGETHER }) "all together, pressed freely" else "one icon per trial" },
                "same (paper protocol); how often to press: paper silent, ours freely",
            ),
            ProcedureRow("stimulus order", "—", "—", { pr -> pr.tasks.joinToString(", ") { it.stimulusOrder.jsonName }.split(", ").distinct().joinToString() }, "paper silent (one screen): ours fixed by number / a Williams square"),
            ProcedureRow(
                "questionnaire", "on a computer, after each task", p.at("127"),
                { pr -> if (pr.tasks.all { it.presentation == TaskPresentation.TOGETHER }) "in the app, after each task" else "in the app, one item per trial" },
                "different: in the app, so the participant keeps the phone",
            ),
            ProcedureRow("instructions", "the experimenter explains before each task", p.at("127"), { "an intro screen per task" }, "same moment; ours written"),
            ProcedureRow("masking", "white noise on headphones, no rhythm or pitch", p.at("125"), { it.masking.jsonName }, "same (paper protocol); none in the per-trial default"),
            ProcedureRow("task 2 texts", "not in the text (Fig. 4 centre, Tables 4-5 are images)", p.at("74, 95, 97"), { pr -> pr.tasks[1].stimuli.joinToString(" / ") { "\"${it.text}\"" } }, "ours: the paper does not publish its texts"),
            ProcedureRow("task 3 stickers", "WeChat dialog-box stickers; not in the text", p.at("95"), { pr -> pr.tasks[2].stimuli.joinToString(", ") { it.sticker.orEmpty() } }, "ours: the paper does not publish its stickers"),
            ProcedureRow("analysis", "paired-sample t tests of the icon pairs per task", p.at("131"), { "paired t (hapticon analyze; + Wilcoxon, --holm)" }, "same test; a correction for the six pairs: paper silent"),
        )
    }

    private fun row(name: String, source: String, attack: Double, sustain: Double, level: Double, release: Double, peak: Double, note: Int, f: Double, period: Double, count: Int) =
        String.format(
            Locale.ROOT, "%-7s %-16s %8.5f %8.5f %6.3f %8.5f %6.3f %4d %9.2f %7.3f %5d",
            name, source, attack, sustain, level, release, peak, note, f, period, count,
        )

    /** What one render shows. */
    class Measured(val attack: Double, val sustain: Double, val level: Double, val release: Double, val peak: Double, val frequency: Double, val period: Double, val count: Int)

    /**
     * Measures [icon] rendered with [model]: the shape on one repetition rendered alone (stroke's repetitions
     * overlap), onsets and count on the whole icon, the carrier's frequency from its zero crossings.
     */
    fun measure(icon: HapticIcon, model: EnvelopeModel): Measured {
        val fs = SAMPLE_RATE.toDouble()
        val single = IconRenderer(icon.copy(count = 1, period = 0.0), SAMPLE_RATE, model)
        val e = DoubleArray(single.sampleCount.toInt()) { single.envelopeAt(it.toLong()) }
        // Corners: where the slope changes by more than rounding (second difference). A boundary between samples
        // bends two neighbouring differences; the later sample, the new segment's first, stands for both.
        val bends = (1 until e.size - 1).filter { abs(e[it + 1] - 2 * e[it] + e[it - 1]) > 1e-9 }
        val corners = bends.filterIndexed { i, n -> i == bends.lastIndex || bends[i + 1] != n + 1 }
        val end = e.indexOfLast { it > 0.0 } + 1
        val attackEnd = corners.firstOrNull { it > 0 } ?: 0
        val releaseStart = corners.lastOrNull { it < end - 1 && it > attackEnd } ?: attackEnd
        val whole = IconRenderer(icon, SAMPLE_RATE, model)
        val onsets = onsets(whole)
        // The median spacing: paper's stroke repetitions combine by maximum, so its second attack only shows
        // where it overtakes the first's release (2.8 s), while later spacings are the period.
        val spacings = onsets.zipWithNext { a, b -> (b - a) / fs }.sorted()
        val period = if (spacings.isEmpty()) 0.0 else spacings[spacings.size / 2]
        return Measured(
            attack = attackEnd / fs,
            sustain = (releaseStart - attackEnd) / fs,
            level = e[releaseStart],
            release = (end - releaseStart) / fs,
            peak = e.max(),
            frequency = zeroCrossingFrequency(single, attackEnd, end),
            period = period,
            count = onsets.size,
        )
    }

    /** Samples where a repetition starts: the envelope rises from a sample at or below the one before after falling. */
    private fun onsets(renderer: IconRenderer): List<Long> {
        val onsets = ArrayList<Long>()
        var previous = 0.0
        var falling = true
        for (i in 0 until renderer.sampleCount) {
            val v = renderer.envelopeAt(i)
            if (falling && v > previous) onsets += maxOf(0L, i - 1)
            falling = v < previous || (v == 0.0)
            previous = v
        }
        return onsets
    }

    /** Carrier frequency from the rising zero crossings between samples [from] and [to] (linear interpolation). */
    private fun zeroCrossingFrequency(renderer: IconRenderer, from: Int, to: Int): Double {
        var first = Double.NaN
        var last = Double.NaN
        var crossings = 0
        var previous = renderer.sampleAt(from.toLong())
        for (i in from + 1 until to) {
            val v = renderer.sampleAt(i.toLong())
            if (previous < 0.0 && v >= 0.0) {
                val at = i - 1 + previous / (previous - v)
                if (crossings == 0) first = at
                last = at
                crossings++
            }
            previous = v
        }
        return if (crossings < 2) Double.NaN else (crossings - 1) * SAMPLE_RATE / (last - first)
    }
}
