package org.hapticon.companion.gesture

import org.hapticon.gesture.recognition.ForestParams
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.recognition.LabelledWindows
import org.hapticon.gesture.recognition.LiveRecognizer
import org.hapticon.gesture.recognition.PersonalTrainer
import org.hapticon.gesture.recognition.WindowConfig
import org.hapticon.gesture.synthetic.SimulatedPerson
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.hapticon.gesture.synthetic.SyntheticTake
import java.util.stream.Collectors
import kotlin.math.sqrt

/** What `classify-bench` varies and on how much synthetic data. */
class RecognitionBenchConfig(
    val people: Int,
    val seed: Long,
    val takesPerLabel: Int,
    val windows: List<Double>,
    val treeCounts: List<Int>,
)

/**
 * One (window, trees) cell: leave-one-participant-out window accuracy (mean and SD over held-out people),
 * live decision latency from gesture onset (ms, mean over correctly recognised takes), the share of gesture
 * takes the live recogniser got right, and the feature + predict time per window (µs).
 */
class RecognitionResult(
    val windowSeconds: Double,
    val trees: Int,
    val accuracyMean: Double,
    val accuracySd: Double,
    val latencyMs: Double,
    val liveHitRate: Double,
    val microsPerWindow: Double,
)

/** A personal model's accuracy (mean ± SD over people) from [examples] takes per label, and its training time. */
class PersonalResult(val examples: Int, val trees: Int, val accuracyMean: Double, val accuracySd: Double, val trainMillis: Double)

/**
 * Leave-one-participant-out evaluation of window length × tree count on [SyntheticGestures] people.
 *
 * With `parallel` (the default) the folds (and the personal models' people) run on every core: each fold
 * is independent (its own forest seed, seed + held-out index), its figures are kept per fold and merged
 * in fold order, so every accuracy, latency and hit rate is identical to a run on one thread. Only the
 * µs-per-window timing differs, as any timing does; it is taken while the other folds run.
 */
object RecognitionBench {
    /** Runs every cell of [config]; [progress] gets one line per window length. */
    fun run(config: RecognitionBenchConfig, parallel: Boolean = true, progress: (String) -> Unit): List<RecognitionResult> {
        val people = SyntheticGestures.people(config.people, config.seed)
        val takes = people.map { SyntheticGestures.takesOf(it, config.takesPerLabel) }
        val results = ArrayList<RecognitionResult>()
        for (seconds in config.windows) {
            val window = WindowConfig(seconds, WindowConfig.DEFAULT_HOP_SECONDS)
            val windows = takes.map { person -> LabelledWindows.of(person.map { it.labelled }, window) }
            val maxTrees = config.treeCounts.max()
            val folds = inOrder(people.indices.toList(), parallel) { heldOut ->
                val training = windows.filterIndexed { i, _ -> i != heldOut }.reduce { a, b -> a + b }
                val trainer = PersonalTrainer(window, ForestParams(trees = maxTrees, seed = config.seed + heldOut))
                val full = trainer.train(training, SyntheticGestures.CHANNELS, SyntheticGestures.SAMPLE_RATE)
                config.treeCounts.map { trees ->
                    val model = GestureModel(full.sampleRate, full.channels, full.window, full.labels, full.forest.firstTrees(trees))
                    Cell().also { it.add(model, people[heldOut], takes[heldOut]) }
                }
            }
            for ((k, trees) in config.treeCounts.withIndex()) {
                val cell = Cell()
                for (fold in folds) cell.merge(fold[k])
                results += cell.result(seconds, trees)
            }
            progress("window ${seconds}s done (${windows.sumOf { it.size }} windows over ${people.size} people)")
        }
        return results
    }

    /**
     * Personal models with the default window and [trees]: for each person, train on [examples] takes per label
     * and score the windows of two further takes. Returns accuracy mean, SD and mean training time (ms).
     */
    fun personal(config: RecognitionBenchConfig, trees: Int, examples: Int = 5, parallel: Boolean = true): PersonalResult {
        val perPerson = inOrder(SyntheticGestures.people(config.people, config.seed), parallel) { person ->
            // Takes 100+ are new to the person, unlike the 0.. takes of the leave-one-out runs.
            val training = GestureLabel.ALL.flatMap { label -> (0 until examples).map { SyntheticGestures.perform(person, label, take = 100 + it) } }
            val test = GestureLabel.ALL.flatMap { label -> (examples until examples + 2).map { SyntheticGestures.perform(person, label, take = 100 + it) } }
            val started = System.nanoTime()
            val model = PersonalTrainer(WindowConfig(), ForestParams(trees = trees, seed = config.seed)).train(training.map { it.labelled })
            val millis = (System.nanoTime() - started) / 1e6
            val cell = Cell()
            cell.add(model, person, test, live = false)
            cell.accuracies.single() to millis
        }
        val accuracies = perPerson.map { it.first }
        return PersonalResult(examples, trees, accuracies.average(), sd(accuracies), perPerson.sumOf { it.second } / config.people)
    }

    /** [work] on each of [items], on every core when [parallel]; results in the order of [items] either way. */
    private fun <T, R> inOrder(items: List<T>, parallel: Boolean, work: (T) -> R): List<R> {
        if (!parallel) return items.map(work)
        return items.parallelStream().map { work(it) }.collect(Collectors.toList())
    }

    private fun sd(values: List<Double>): Double {
        val mean = values.average()
        return sqrt(values.sumOf { (it - mean) * (it - mean) } / maxOf(1, values.size - 1))
    }

    private class Cell {
        val accuracies = ArrayList<Double>()
        val latencies = ArrayList<Double>()
        var liveTakes = 0
        var liveHits = 0
        var nanos = 0L
        var classified = 0L

        fun add(model: GestureModel, person: SimulatedPerson, takes: List<SyntheticTake>, live: Boolean = true) {
            val classifier = model.classifier()
            var correct = 0
            var total = 0
            val frames = model.windowFrames
            val start = System.nanoTime()
            for (take in takes) {
                val data = take.labelled.recording.channels.map { it.toDoubleArray() }
                var from = 0
                while (from + frames <= take.labelled.recording.frameCount) {
                    val truth = take.labelled.windowLabel(from, frames)
                    if (truth != null) {
                        total++
                        if (classifier.classify(data, from) == truth) correct++
                    }
                    from += model.hopFrames
                }
            }
            nanos += System.nanoTime() - start
            classified += total
            accuracies += correct.toDouble() / total
            if (!live) return
            // Live: each gesture take after 3 s of the same person's rest, so the first window is full.
            val rest = SyntheticGestures.perform(person, GestureLabel.NONE, take = 999)
            for (take in takes.filter { !it.label.isNone }) {
                val stream = SyntheticGestures.concatenate(listOf(rest, take))
                val onset = stream.spans.single().from
                val recognizer = LiveRecognizer(model)
                val channels = stream.recording.channels.map { it.toDoubleArray() }
                val frame = DoubleArray(channels.size)
                liveTakes++
                for (i in 0 until stream.recording.frameCount) {
                    for (c in channels.indices) frame[c] = channels[c][i]
                    val event = recognizer.push(frame) ?: continue
                    if (event.label == take.label) {
                        liveHits++
                        latencies += (event.decisionFrame - onset) * 1000.0 / model.sampleRate
                    }
                    break
                }
            }
        }

        /** Appends [other]'s figures after this cell's (folds merged in fold order keep sequential results). */
        fun merge(other: Cell) {
            accuracies += other.accuracies
            latencies += other.latencies
            liveTakes += other.liveTakes
            liveHits += other.liveHits
            nanos += other.nanos
            classified += other.classified
        }

        fun result(seconds: Double, trees: Int): RecognitionResult {
            return RecognitionResult(
                seconds, trees, accuracies.average(), sd(accuracies),
                latencyMs = if (latencies.isEmpty()) Double.NaN else latencies.average(),
                liveHitRate = liveHits.toDouble() / maxOf(1, liveTakes),
                microsPerWindow = nanos / 1000.0 / maxOf(1L, classified),
            )
        }
    }
}
