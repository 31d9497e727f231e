package org.hapticon.companion.study

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.StudyPlan
import org.hapticon.study.StudyProtocol
import org.hapticon.study.StudySession
import org.hapticon.study.StudyStep
import org.hapticon.study.export.ResponseCsv
import org.hapticon.study.export.ResponseRow
import org.hapticon.study.export.ResponseRows
import org.hapticon.study.log.ChainVerification
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.HashChain
import org.hapticon.study.log.StudyEvent
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream
import java.util.SplittableRandom

/**
 * The demo's user study: the originating study's protocol run end to end by [PARTICIPANTS] simulated
 * participants (counterbalanced plans, every event through the hash-chained log, which is verified), their
 * responses exported as the long-format CSV, and that CSV analysed as `hapticon analyze --holm` would.
 * The ratings are simulated (seeded): each icon has its own mean, so the tests have something to find.
 */
object StudyDemo {
    /** Participants in the demo: a multiple of the designs' cycles (2 task orders, 4-icon Williams squares). */
    const val PARTICIPANTS = 12

    private const val SEED = 2026L
    private const val START_MILLIS = 1_795_000_000_000L

    /** Simulated mean rating per icon (1..5) in each task (ours, not the paper's). */
    val MEANS = mapOf("stroke" to 3.8, "hit" to 4.2, "knock" to 4.4, "hug" to 3.1)

    /** What [simulate] produced: every response row and one line per participant's verified log. */
    class Simulation(val rows: List<ResponseRow>, val logLines: String)

    /**
     * Runs [protocol] end to end with [participants] simulated participants (plans seeded with [seed]): each rates an
     * icon around its own mean ([MEANS], the same in every task), every event goes through a hash-chained log that
     * must verify, and the logs become the export's response rows.
     */
    fun simulate(protocol: StudyProtocol = OriginatingStudy.PROTOCOL, participants: Int = PARTICIPANTS, seed: Long = SEED): Simulation {
        val random = SplittableRandom(seed)
        val rows = ArrayList<ResponseRow>()
        val logLines = StringBuilder()
        var now = START_MILLIS
        for (index in 0 until participants) {
            val plan = StudyPlan.of(protocol, index, seed)
            val session = StudySession(plan)
            val log = EventLog.start(plan.participantId)
            log.append(StudyEvent.SessionStarted(protocol.id, protocol.revision, index, seed), now)
            while (true) {
                val step = session.nextStep(log.events)
                now += 1_000L + random.nextInt(2_000)
                when (step) {
                    is StudyStep.TaskIntro -> log.append(StudyEvent.TaskStarted(step.task.id), now)
                    // The simulated participant presses each icon once on the shared screen, then goes on.
                    is StudyStep.Explore -> {
                        for (stimulus in step.stimuli) log.append(StudyEvent.IconPressed(step.task.id, stimulus.id), now + 500)
                        log.append(StudyEvent.ExplorationEnded(step.task.id), now + 1_000)
                    }
                    is StudyStep.Trial -> {
                        val task = step.task.id
                        val stimulus = step.stimulus.id
                        log.append(StudyEvent.StimulusShown(task, stimulus), now)
                        log.append(StudyEvent.IconPressed(task, stimulus), now + 800)
                        log.append(StudyEvent.PlaybackStarted(task, stimulus), now + 801)
                        now += 800 + (step.stimulus.icon.duration * 1000).toLong()
                        log.append(StudyEvent.PlaybackFinished(task, stimulus), now)
                        now += 1_500L + random.nextInt(3_000)
                        log.append(StudyEvent.Answer(task, stimulus, rating(step.stimulus.icon.name, random)), now)
                    }
                    is StudyStep.TaskEnd -> log.append(StudyEvent.TaskEnded(step.task.id), now)
                    StudyStep.Done -> {
                        log.append(StudyEvent.SessionEnded, now)
                        break
                    }
                }
            }
            val verdict = HashChain.verify(log.entries)
            check(verdict == ChainVerification.Intact) { "the demo's own log must verify: $verdict" }
            logLines.append("${plan.participantId}: ${log.entries.size} events, chain intact, last hash ${log.entries.last().hash}\n")
            rows += ResponseRows.of(protocol, log.entries)
        }
        return Simulation(rows, logLines.toString())
    }

    /** Writes `study/results.csv`, `study/logs.txt` and `study/analysis/` into [dir]. */
    fun write(dir: File, report: (String) -> Unit) {
        val out = File(dir, "study")
        OutputFiles.ensureDirectory(out)
        val simulation = simulate()
        val rows = simulation.rows
        val csv = File(out, "results.csv")
        OutputFiles.write(csv) { it.write(ResponseCsv.write(rows).toByteArray(Charsets.UTF_8)) }
        report("wrote $csv: ${rows.size} responses of $PARTICIPANTS simulated participants (the originating study's protocol)")
        val logs = File(out, "logs.txt")
        OutputFiles.write(logs) { it.write(simulation.logLines.toByteArray(Charsets.UTF_8)) }
        report("wrote $logs: every participant's hash-chained event log verified")

        val analysis = File(out, "analysis")
        val markdown = ByteArrayOutputStream()
        val diagnostics = ByteArrayOutputStream()
        runAnalyze(
            listOf(csv.path, "--out", analysis.path, "--holm"),
            Console(PrintStream(markdown, true, "UTF-8"), PrintStream(diagnostics, true, "UTF-8")),
        )
        val summary = File(analysis, "summary.md")
        OutputFiles.write(summary) { it.write(markdown.toByteArray()) }
        report("wrote $analysis: descriptives, paired t and Wilcoxon tests with Holm, box plots")
    }

    /** A Likert rating around the icon's mean, rounded and kept in 1..5. */
    private fun rating(icon: String, random: SplittableRandom): Int {
        val mean = MEANS[icon] ?: 3.0
        // Sum of three uniforms: a bell shape without a normal generator, SD ≈ 0.87.
        val noise = (random.nextDouble() + random.nextDouble() + random.nextDouble() - 1.5) * 1.5
        return Math.round(mean + noise).toInt().coerceIn(1, 5)
    }
}
