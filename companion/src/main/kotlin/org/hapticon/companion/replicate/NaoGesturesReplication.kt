package org.hapticon.companion.replicate

import org.hapticon.companion.cli.UsageException
import org.hapticon.gesture.recognition.NaoDataset
import org.hapticon.gesture.recognition.NaoEvaluation
import org.hapticon.gesture.recognition.NaoPreset
import org.hapticon.gesture.recognition.NaoRecording
import org.hapticon.gesture.recognition.NaoScores
import org.hapticon.gesture.recognition.NaoTask
import org.hapticon.gesture.synthetic.NaoSyntheticPeople
import java.io.File
import java.io.PrintStream
import java.util.Locale
import java.util.stream.Collectors

/**
 * 004 — the NAO fabric-sensor paper (Burns et al., Front. Robot. AI 9:840335, 2022; [PAPER]): its pipeline's rules
 * beside [NaoPreset] with their lines, its figures on their own, and ours: one forest per task scored the paper's way
 * (a random 70/30 split of windows) and leave-one-person-out. With `--data DIR` on the study's recordings
 * ([NaoDataset]'s layout) ours is computed on the paper's data and printed beside its figures; without, on
 * [simulated] people ([NaoSyntheticPeople]) in a table of its own, not comparable with the paper's.
 */
class NaoGesturesReplication(private val simulated: () -> List<NaoRecording>) : Replication {
    override val id: String = "004"
    override val names: List<String> = listOf("nao")
    override val title: String = "NAO fabric sensor (Burns et al.): touch location, intensity and gesture, one forest per task"
    override val options: String = "[--data DIR]"

    override fun run(out: PrintStream) {
        printPaper(out)
        val recordings = simulated()
        val results = evaluate(recordings)
        out.println()
        out.printSimulated(
            "${recordings.size} simulated people following the paper's protocol (NaoSyntheticPeople; the paper: ${NaoSyntheticPeople.PAPER_PARTICIPANTS} people), ${results.windows} windows",
            listOf("what", "ours, random 70/30", "ours, leave one person out", "chance"),
            results.rows.map { listOf(it.what, it.split, it.lopo, it.chance) },
        )
        out.println("Run with --data DIR on the study's recordings (NaoDataset: PERSON-raw.csv, PERSON-indices.csv) to put ours beside the paper's figures.")
    }

    override fun check(args: List<String>) {
        if (args.isEmpty()) return
        if (args.size != 2 || args[0] != "--data") throw UsageException("replicate $id takes $options, got ${args.joinToString(" ")}")
        if (!File(args[1]).isDirectory) throw UsageException("${args[1]} is not a directory")
    }

    override fun run(out: PrintStream, args: List<String>) {
        check(args)
        if (args.isEmpty()) return run(out)
        val recordings = try {
            NaoDataset.readDirectory(File(args[1]))
        } catch (e: IllegalArgumentException) {
            throw UsageException(e.message.orEmpty())
        }
        if (recordings.size < 2) throw UsageException("${args[1]}: leave-one-person-out needs at least 2 participants, found ${recordings.size}")
        printPaper(out)
        val results = evaluate(recordings)
        out.println()
        out.println("The paper's figures beside ours on ${args[1]}: ${recordings.size} participants, ${recordings.sumOf { it.spans.size }} performances, ${results.windows} windows (the paper: 15, 1683):")
        val paper = PAPER_FIGURES.associateBy { it.what }
        out.printTable(
            listOf("what", "paper", "cited", "ours, random 70/30", "ours, leave one person out", "chance"),
            results.rows.map { r -> listOf(r.what, paper[r.what]?.value ?: "—", paper[r.what]?.cited ?: "—", r.split, r.lopo, r.chance) },
        )
    }

    private fun printPaper(out: PrintStream) {
        val p = PAPER
        out.println(p.legend)
        out.println()
        out.println("Rules:")
        out.printRules(
            listOf(
                RuleRow("sensors", "4 fabric sensors: hand, lower arm, upper arm, shoulder", p.at("5, 105"), "4 channels in that order (NaoPreset.LOCATIONS)", "same"),
                RuleRow("sample rate", "40 Hz", p.at("156"), "${fmt(NaoPreset.SAMPLE_RATE, 0)} Hz", "same"),
                RuleRow("participants", "15 (P2-P16)", p.at("127"), "--data: the data's; simulated: $SIMULATED_PEOPLE by default", "the data's are the paper's; simulated people are not (4 keep the run short)"),
                RuleRow("protocol", "one sensor at a time; 5 gestures in random order, 5 s each with 5 s breaks; 3 of each; each intensity a half", p.at("152"), "NaoSyntheticPeople: the same, ${NaoSyntheticPeople.PERFORMANCES} performances a person", "same; whether the order is redrawn each round: paper silent, ours redraws"),
                RuleRow("performances", "1800 recorded, 117 with electrical shorts discarded: 1683", p.at("166"), "NaoDataset reads however many each index file lists", "same"),
                RuleRow("data layout", "raw resistances + start/end indices + the pre-generated order", p.at("121, 162, 166"), "PERSON-raw.csv + PERSON-indices.csv (NaoDataset)", "paper silent on the files' columns: ours, documented in NaoDataset"),
                RuleRow("no-gesture label", "\"none\"", p.at("166"), NaoPreset.NONE, "same"),
                RuleRow("window", "w = 80 samples, about 2 s", p.at("170"), "${NaoPreset.WINDOW_FRAMES} samples", "same"),
                RuleRow("window overlap", "0.5w between successive windows", p.at("168"), "hop ${NaoPreset.HOP_FRAMES}", "same"),
                RuleRow("window label", "a gesture's if it overlaps it by >= 0.75w, else none", p.at("168"), "${NaoPreset.LABEL_OVERLAP}w = ${(NaoPreset.LABEL_OVERLAP * NaoPreset.WINDOW_FRAMES).toInt()} samples", "same"),
                RuleRow("features", "124 = 31 per sensor: entropy; sum, max, min, average, median, SD, variance, area, IQR, number of peaks of the signal and its 1st and 2nd derivatives", p.at("168"), "${NaoPreset.CHANNELS * NaoPreset.FEATURES_PER_CHANNEL} (NaoPreset.FEATURE_INDICES)", "same"),
                RuleRow("high-pass filter", "tried at 0.5 Hz, omitted", p.at("295"), "none", "same"),
                RuleRow("classifier", "scikit-learn random forest", p.at("168, 170"), "our RandomForest (CART, Gini)", "same kind; not scikit-learn's code"),
                RuleRow("one forest per task", "location, intensity, gesture, gesture + intensity", p.at("174, 205-209"), NaoTask.entries.joinToString(", ") { it.label }, "same"),
                RuleRow(
                    "forest parameters",
                    "Table 2, trees/depth: location 50/40, intensity 100/20, gesture 100/40, combined 100/32; 20 features/split, min split 8, min leaf 1, gini, bootstrap, random_state None",
                    p.at("174-199"),
                    NaoTask.entries.joinToString(", ") { "${it.label} " + NaoPreset.FORESTS.getValue(it).let { f -> "${f.trees}/${f.maxDepth}" } } +
                        NaoPreset.FOREST.let { f -> "; ${f.featuresPerSplit} features/split, min split ${f.minSamplesSplit}, min leaf ${f.minLeaf}, gini, bootstrap, seeded" },
                    "same; seeded so that a run repeats (the paper's random_state None)",
                ),
                RuleRow("classes", "location 4 + none, intensity 2 + none, gesture 5 + none, combined 10 + none", p.at("205, 215"), NaoTask.entries.joinToString(", ") { "${it.label} ${it.classes.size}" }, "same"),
                RuleRow("evaluation", "random 70 %-30 % split across all participants' windows", p.at("170"), "NaoEvaluation.randomSplit (70 %); also leave one person out", "same; LOPO is ours: the random split puts one person's overlapping windows on both sides"),
                RuleRow("score", "\"average (label) accuracy\"", p.at("205, 209"), "accuracy and the mean of per-class recalls", "paper silent on the formula: both printed"),
            ),
        )
        out.println()
        out.println("The paper's figures (its participants; not recomputed here):")
        out.printTable(listOf("what", "paper", "cited", "chance"), PAPER_FIGURES.map { listOf(it.what, it.value, it.cited, it.chance) })
        out.println("74.1 % / (100 % / 11) = ${fmt(0.741 * 11, 2)}: \"about 8.2 times higher than the chance\" (${p.at("209-215")}).")
    }

    /** One printed figure of ours: [split] and [lopo] as text, [chance] of its task. */
    class Row(val what: String, val split: String, val lopo: String, val chance: String)

    /** Every task's scores, as printed rows, over [windows] windows. */
    class Results(val windows: Int, val rows: List<Row>)

    /**
     * Windows [recordings] the paper's way and scores every task both ways. The tasks' forests are grown in parallel
     * (each is deterministic for its seed, so the figures do not depend on the cores).
     */
    fun evaluate(recordings: List<NaoRecording>): Results {
        val windows = NaoPreset.windows(recordings)
        val scored = NaoTask.entries.parallelStream()
            .map { task -> Triple(task, NaoEvaluation.randomSplit(windows, task), NaoEvaluation.leaveOnePersonOut(windows, task)) }
            .collect(Collectors.toList())
        val split = scored.associate { it.first to it.second }
        val lopo = scored.associate { it.first to it.third }
        val rows = ArrayList<Row>()
        fun add(what: String, task: NaoTask, chance: Boolean = true, value: (NaoScores) -> Double) =
            rows.add(Row(what, percent(value(split.getValue(task))), percent(value(lopo.getValue(task))), if (chance) percent(task.chance) else "—"))
        for (task in listOf(NaoTask.LOCATION, NaoTask.INTENSITY, NaoTask.GESTURE, NaoTask.COMBINED)) {
            add("${task.label}: accuracy", task) { it.accuracy }
            add("${task.label}: average label accuracy", task) { it.averageLabelAccuracy }
            if (task == NaoTask.LOCATION) for (l in NaoPreset.LOCATIONS) add("location recall, $l", task) { it.share(l, l) }
            if (task == NaoTask.GESTURE) for (l in NaoPreset.LOCATIONS) add("gesture accuracy at the $l", task) { it.accuracyAt(l) }
        }
        add("squeezing (gesture task) recall", NaoTask.GESTURE) { it.share("squeeze", "squeeze") }
        add("energetic squeezing recall", NaoTask.COMBINED) { it.share("squeeze-energetic", "squeeze-energetic") }
        add("gentle squeezing recall", NaoTask.COMBINED) { it.share("squeeze-gentle", "squeeze-gentle") }
        add("gentle tickling recall", NaoTask.COMBINED) { it.share("tickle-gentle", "tickle-gentle") }
        add("gentle tickling -> gentle poking", NaoTask.COMBINED, chance = false) { it.share("tickle-gentle", "poke-gentle") }
        return Results(windows.size, rows)
    }

    /** One of the paper's figures. */
    class Figure(val what: String, val value: String, val cited: String, val chance: String)

    companion object {
        /** The paper's text in the papers' index. */
        val PAPER: PaperText = PaperText("004_7d5078645d142b2a.txt")

        /** The paper's figures, named as ours are in [evaluate]. */
        val PAPER_FIGURES: List<Figure> = listOf(
            Figure("location recall, hand", ">= 96 %", PAPER.at("205"), "20.0 %"),
            Figure("location recall, lower-arm", ">= 96 %", PAPER.at("205"), "20.0 %"),
            Figure("location recall, upper-arm", ">= 96 %", PAPER.at("205"), "20.0 %"),
            Figure("location recall, shoulder", ">= 96 %", PAPER.at("205"), "20.0 %"),
            Figure("intensity: average label accuracy", "89.3 %", PAPER.at("205"), "33.3 %"),
            Figure("gesture: average label accuracy", "74.3 %", PAPER.at("205"), "16.7 %"),
            Figure("gesture accuracy at the hand", "78 %", PAPER.at("205"), "16.7 %"),
            Figure("gesture accuracy at the lower-arm", "74 %", PAPER.at("205"), "16.7 %"),
            Figure("gesture accuracy at the upper-arm", "77 %", PAPER.at("205"), "16.7 %"),
            Figure("gesture accuracy at the shoulder", "68 %", PAPER.at("205"), "16.7 %"),
            Figure("combined: average label accuracy", "74.1 %, about 8.2x chance", PAPER.at("209-215"), "9.1 %"),
            Figure("squeezing (gesture task) recall", "90 %", PAPER.at("215"), "16.7 %"),
            Figure("energetic squeezing recall", "88 % (the highest)", PAPER.at("215"), "9.1 %"),
            Figure("gentle squeezing recall", "80 %", PAPER.at("215"), "9.1 %"),
            Figure("gentle tickling recall", "64 % (the lowest)", PAPER.at("215"), "9.1 %"),
            Figure("gentle tickling -> gentle poking", "11 %", PAPER.at("215"), "—"),
        )

        /**
         * People in the default simulation, each through the whole protocol (1204 windows a person): 4 keeps `replicate
         * nao` to about 3 minutes of one core (6 took 7), and leave-one-person-out still trains on three people.
         */
        const val SIMULATED_PEOPLE: Int = 4

        private fun percent(value: Double): String = if (value.isNaN()) "—" else String.format(Locale.ROOT, "%.1f %%", 100 * value)

        private fun fmt(value: Double, decimals: Int): String = String.format(Locale.ROOT, "%.${decimals}f", value)
    }
}
