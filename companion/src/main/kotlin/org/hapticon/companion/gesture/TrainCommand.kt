package org.hapticon.companion.gesture

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.sensors.InputFiles
import org.hapticon.gesture.recognition.ForestParams
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.recognition.LabelledRecording
import org.hapticon.gesture.recognition.LiveRecognizer
import org.hapticon.gesture.recognition.PersonalTrainer
import org.hapticon.gesture.recognition.WindowConfig
import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchModel
import java.io.File
import java.util.Locale

/** Default forest size of `train`, chosen from `classify-bench` (docs/gesture-recognition.md). */
const val DEFAULT_TREES: Int = 30

/**
 * `hapticon train --in DIR_OR_CSV [MORE..] --out MODEL.json [--window S] [--trees N] [--seed S]`: a model
 * from labelled CSV recordings ([LabelledCsv]); a directory contributes its `*.csv` files in name order.
 */
fun runTrain(args: List<String>, console: Console) {
    val arguments = Arguments.parse("train", args, valueOptions = setOf("in", "out", "window", "trees", "seed", "classifier", "iterations"))
    val inputs = listOf(arguments.required("in")) + arguments.positionals
    val out = File(arguments.required("out"))
    when (arguments.value("classifier") ?: "forest") {
        "forest" -> Unit
        "logitboost" -> {
            val iterations = arguments.int("iterations", LogitBoost.DEFAULT_ITERATIONS)
            if (iterations !in 1..10_000) throw UsageException("--iterations must be in 1..10000, got $iterations")
            return trainSocialTouch(inputs.flatMap { csvFiles(it) }, out, iterations, console)
        }
        else -> throw UsageException("--classifier must be forest or logitboost, got '${arguments.value("classifier")}'")
    }
    val windowText = arguments.value("window")
    val window = windowText?.let { text ->
        val seconds = text.toDoubleOrNull()
        if (seconds == null || !seconds.isFinite() || seconds <= 0.0 || seconds > WindowConfig.MAX_WINDOW_SECONDS) {
            throw UsageException("--window must be seconds in (0, ${WindowConfig.MAX_WINDOW_SECONDS}], got '$text'")
        }
        WindowConfig(seconds, minOf(WindowConfig.DEFAULT_HOP_SECONDS, seconds))
    } ?: WindowConfig()
    val trees = arguments.int("trees", DEFAULT_TREES)
    if (trees !in 1..ForestParams.MAX_TREES) throw UsageException("--trees must be in 1..${ForestParams.MAX_TREES}, got $trees")
    val seedText = arguments.value("seed")
    val seed = if (seedText == null) 1L else seedText.toLongOrNull() ?: throw UsageException("--seed must be a whole number, got '$seedText'")
    val files = inputs.flatMap { csvFiles(it) }
    val examples = files.map { LabelledCsv.parse(InputFiles.readText("in", it.path), it.path) }
    val started = System.nanoTime()
    val model = try {
        PersonalTrainer(window, ForestParams(trees = trees, seed = seed)).train(examples)
    } catch (e: IllegalArgumentException) {
        throw UsageException("cannot train: ${e.message}")
    }
    val millis = (System.nanoTime() - started) / 1e6
    OutputFiles.write(out) { it.write(model.encode().toByteArray(Charsets.UTF_8)) }
    console.err.println(
        String.format(
            Locale.ROOT, "train: %d recordings, labels %s, %d trees (%d nodes), %.2f s window, trained in %.0f ms; wrote %s",
            examples.size, model.labels.joinToString(" ") { it.id }, model.forest.treeCount, model.forest.nodeCount, window.windowSeconds, millis, out,
        ),
    )
}

/**
 * `hapticon classify --model MODEL.json --in REC.csv`: one CSV line per decision
 * `time_s,label,probability,event` (event 1 where the live recogniser reports a gesture).
 */
fun runClassify(args: List<String>, console: Console) {
    val arguments = Arguments.parse("classify", args, valueOptions = setOf("model", "in"))
    arguments.requireNoPositionals()
    val modelPath = arguments.required("model")
    val modelText = InputFiles.readText("model", modelPath)
    if (SocialTouchModel.isSocialTouchModel(modelText)) return classifySocialTouch(modelText, modelPath, arguments.required("in"), console)
    val model = try {
        GestureModel.decode(modelText)
    } catch (e: IllegalArgumentException) {
        throw UsageException("$modelPath: ${e.message}")
    }
    val path = arguments.required("in")
    val input: LabelledRecording = LabelledCsv.parse(InputFiles.readText("in", path), path, requireLabel = false)
    val recording = input.recording
    try {
        model.requireMatches(recording)
    } catch (e: IllegalArgumentException) {
        throw UsageException("$path: ${e.message}")
    }
    val recognizer = LiveRecognizer(model)
    val channels = recording.channels.map { it.toDoubleArray() }
    val frame = DoubleArray(channels.size)
    var events = 0
    console.out.println("time_s,label,probability,event")
    for (i in 0 until recording.frameCount) {
        for (c in channels.indices) frame[c] = channels[c][i]
        val before = recognizer.decisionCount
        val event = recognizer.push(frame)
        if (recognizer.decisionCount == before) continue
        if (event != null) events++
        console.out.println(
            String.format(Locale.ROOT, "%.3f,%s,%.3f,%d", i / recording.sampleRate, recognizer.lastDecision!!.id, recognizer.lastProbability, if (event != null) 1 else 0),
        )
    }
    console.err.println("classify: ${recognizer.decisionCount} decisions, $events events ($model)")
}

private fun csvFiles(path: String): List<File> {
    val file = File(path)
    if (file.isDirectory) {
        val files = file.listFiles { f -> f.isFile && f.name.endsWith(".csv", ignoreCase = true) }.orEmpty().sortedBy { it.name }
        if (files.isEmpty()) throw UsageException("--in: no .csv files in $file")
        return files
    }
    return listOf(InputFiles.existing("in", path))
}
