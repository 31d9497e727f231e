package org.hapticon.companion.gesture

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.sensors.InputFiles
import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.MessageFiles
import org.hapticon.gesture.social.SocialTouchEvaluation
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchModel
import org.hapticon.gesture.social.TouchMessages
import java.io.File
import java.util.Locale

/**
 * `hapticon train --classifier logitboost`: one touch message per file ([MessageFiles]: a skin's `SkinCsv` recording
 * or a pointer's `ContactCsv` stream) named `PERSON-LABEL[-N].csv` (e.g. `p3-surprise-12.csv`), the 13
 * [SocialTouchFeatures] of each, LogitBoost over decision stumps as WEKA runs it for [iterations] rounds. Reports the
 * EIT-skin paper's two evaluations on stderr when the data allow: ten 10-fold cross-validations (its Experiment 1)
 * and leave-one-transmitter-out (its Experiment 2).
 */
internal fun trainSocialTouch(files: List<File>, out: File, iterations: Int, console: Console) {
    val rows = files.map { file ->
        val stem = file.name.removeSuffix(".csv").removeSuffix(".CSV")
        val tokens = stem.split('-').let { if (it.size > 2 && it.last().all(Char::isDigit)) it.dropLast(1) else it }
        if (tokens.size < 2) throw UsageException("${file.path}: name must be PERSON-LABEL[-N].csv, e.g. p1-anger-3.csv")
        Triple(tokens[0], tokens.drop(1).joinToString("-"), readMessage(file.path).features)
    }
    val labels = rows.map { it.second }.distinct().sorted()
    if (labels.size < 2) throw UsageException("cannot train: need at least 2 labels, got ${labels.joinToString()}")
    val features = rows.map { it.third }
    val classes = IntArray(rows.size) { labels.indexOf(rows[it].second) }
    val model = SocialTouchModel(labels, LogitBoost.train(features, classes, labels.size, iterations))
    OutputFiles.write(out) { it.write(model.encode().toByteArray(Charsets.UTF_8)) }
    val messages = TouchMessages(features, classes, rows.map { it.first }, labels.size)
    val settings = LogitBoost.WEKA_DEFAULTS.copy(iterations = iterations)
    val cv = if (messages.size >= 10) percent(SocialTouchEvaluation.crossValidate(messages, settings = settings).mean) else "n/a (< 10 messages)"
    val people = messages.people.distinct().size
    val loto = if (people >= 2) percent(SocialTouchEvaluation.leaveOneTransmitterOut(messages, settings).mean) else "n/a (1 person)"
    console.err.println("train: ${rows.size} messages from $people people, labels ${labels.joinToString(" ")}, LogitBoost $iterations rounds; 10x10-fold CV $cv, leave-one-transmitter-out $loto; wrote $out")
}

private fun percent(share: Double) = String.format(Locale.ROOT, "%.1f %%", 100 * share)

private fun readMessage(path: String) = try {
    MessageFiles.read(InputFiles.readText("in", path), path)
} catch (e: IllegalArgumentException) {
    throw UsageException(e.message.orEmpty())
}

/** `hapticon classify --model SOCIAL.json --in MESSAGE.csv`: `label,probability` of the one message. */
internal fun classifySocialTouch(modelText: String, modelPath: String, path: String, console: Console) {
    val model = try {
        SocialTouchModel.decode(modelText)
    } catch (e: IllegalArgumentException) {
        throw UsageException("$modelPath: ${e.message}")
    }
    val (label, probability) = model.classify(readMessage(path).features)
    console.out.println("label,probability")
    console.out.println(String.format(Locale.ROOT, "%s,%.3f", label, probability))
}
