package org.hapticon.companion.replicate

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ProtocolJson
import org.hapticon.study.StudyProtocol
import org.hapticon.study.TaskPresentation
import java.io.PrintStream
import java.util.Locale
import kotlin.math.abs

/**
 * 000 — the haptic icons of Wei et al.: the paper's Table 3 beside what Hapticon renders (the envelope times, levels
 * and carrier frequencies measured on the samples, in both envelope models), and the paper's procedure beside the
 * built-in protocols. Measured at Processing Sound's 44.1 kHz.
 */
object HapticIconsReplication : Replication {
    override val id: String = "000"
    override val names: List<String> = listOf("haptic-icons")
    override val title: String = "Haptic icons (Wei et al.): Table 3 stimuli and the study procedure"

    /** The rate the study's Processing sketch played at. */
    const val SAMPLE_RATE: Int = 44_100

    override fun run(out: PrintStream) {
        out.println("000 — $title")
        out.println()
        out.println("Table 3 (paper) beside the rendered stimuli, measured on the samples at $SAMPLE_RATE Hz:")
        out.println("attack = onset to the first corner, sustain = to the start of the release, release = to silence,")
        out.println("level = envelope at the start of the release, peak = largest envelope value, f = carrier from zero crossings.")
        out.println()
        out.println(String.format(Locale.ROOT, "%-7s %-16s %8s %8s %6s %8s %6s %9s %7s %5s", "icon", "source", "attack", "sustain", "level", "release", "peak", "f (Hz)", "period", "count"))
        for (icon in HapticIcon.PRESETS) {
            out.println(row(icon.name, "Table 3", icon.attack, icon.sustain, icon.level, icon.release, null, icon.frequency, icon.period, icon.count))
            for (model in listOf(EnvelopeModel.PROCESSING, EnvelopeModel.PAPER)) {
                val m = measure(icon, model)
                out.println(row("", "${model.name.lowercase()} model", m.attack, m.sustain, m.level, m.release, m.peak, m.frequency, m.period, m.count))
            }
        }
        out.println()
        out.println("processing is what the participants felt (Processing Sound 2.0.1–2.3.1 + JSyn; docs/envelope-models.md):")
        out.println("its attack always peaks at 1 and its 'sustain' ramps from 1 to the level; paper holds the level.")
        out.println("Periods (median spacing) and counts are measured from where the whole render's envelope starts rising.")
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
        out.println("Procedure: the paper beside the built-in protocols. The paper column is issue 14's summary of the paper")
        out.println("(Wei et al.), not re-checked against the paper's text; 'cited from' says, per row, what the issue states and what is ours.")
        val paper = OriginatingStudy.PAPER_PROTOCOL
        val perTrial = OriginatingStudy.PROTOCOL
        val format = "%-16s | %-42s | %-31s | %-32s | %s"
        out.println(String.format(Locale.ROOT, format, "", "paper", "cited from", paper.id, perTrial.id))
        for (r in procedureRows()) out.println(String.format(Locale.ROOT, format, r.what, r.inPaper, r.citedFrom, r.of(paper), r.of(perTrial)))
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

    /** One procedure row: [what], the paper's value [inPaper] and where that value is [citedFrom], and ours per protocol. */
    class ProcedureRow(val what: String, val inPaper: String, val citedFrom: String, val of: (StudyProtocol) -> String)

    /** The procedure rows; [ProcedureRow.citedFrom] says which part of the paper column issue 14 states and which is ours. */
    fun procedureRows(): List<ProcedureRow> = listOf(
        ProcedureRow("participants", "16", ISSUE) { p -> p.participants?.toString() ?: "open" },
        ProcedureRow("task order", "1 (icons) first; 2, 3 counterbalanced", ISSUE) { p -> "${p.fixedFirst.joinToString()} first; rest ${p.taskOrder.jsonName}" },
        ProcedureRow("icon numbering", "icon 1 = stroke, 2 hit, 3 knock, 4 hug", "$ISSUE (1 = stroke); 2-4 ours") { p ->
            val numbers = p.tasks.first().stimuli.map { it.number }
            if (numbers.all { it != null }) p.tasks.first().stimuli.joinToString(", ") { "${it.number} ${it.icon.name}" } else "by position in the order"
        },
        ProcedureRow("presentation", "4 icons on one chat screen, pressed freely", ISSUE) { p ->
            if (p.tasks.all { it.presentation == TaskPresentation.TOGETHER }) "all together, pressed freely" else "one icon per trial"
        },
        ProcedureRow("questionnaire", "items after each task", ISSUE) { p ->
            if (p.tasks.all { it.presentation == TaskPresentation.TOGETHER }) "items after each task" else "one item per trial"
        },
        ProcedureRow("stimulus order", "fixed (numbered)", "ours, from the numbering") { p ->
            p.tasks.joinToString(", ") { it.stimulusOrder.jsonName }.let { o -> o.split(", ").distinct().joinToString() }
        },
        ProcedureRow("masking", "white noise on headphones", ISSUE) { p -> p.masking.jsonName },
        ProcedureRow("scale", "5-point agreement", "ours, not in $ISSUE") { p -> "${p.scale.points}-point" },
        ProcedureRow("envelopes", "Processing Sound (JSyn)", ISSUE) { p -> ProtocolJson.modelName(p.envelopeModel) },
    )

    /** The source of most of the paper column: the issue that summarised the paper, not the paper's text. */
    private const val ISSUE: String = "issue 14"

    private fun row(name: String, source: String, attack: Double, sustain: Double, level: Double, release: Double, peak: Double?, f: Double, period: Double, count: Int) =
        String.format(
            Locale.ROOT, "%-7s %-16s %8.5f %8.5f %6.3f %8.5f %6s %9.2f %7.3f %5d",
            name, source, attack, sustain, level, release, peak?.let { String.format(Locale.ROOT, "%.3f", it) } ?: "—", f, period, count,
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
