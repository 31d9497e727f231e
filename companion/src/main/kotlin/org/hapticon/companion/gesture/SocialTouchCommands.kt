package org.hapticon.companion.gesture

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.sensors.InputFiles
import org.hapticon.gesture.social.ContactCsv
import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchEvaluation
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchModel
import org.hapticon.gesture.social.TouchMessages
import java.io.File
import java.util.Locale

/**
 * `hapticon train --classifier logitboost`: one touch message per contact CSV ([ContactCsv]) named
 * `PERSON-LABEL[-N].csv` (e.g. `p3-sympathy-12.csv`), the 13 [SocialTouchFeatures] of each, LogitBoost over
 * stumps for [iterations] rounds. Reports 10×10-fold CV (the EIT-skin paper's) and leave-one-person-out (ours)
 * on stderr when the data allow.
 */
internal fun trainSocialTouch(files: List<File>, out: File, iterations: Int, console: Console) {
    val rows = files.map { file ->
        val stem = file.name.removeSuffix(".csv").removeSuffix(".CSV")
        val tokens = stem.split('-').let { if (it.size > 2 && it.last().all(Char::isDigit)) it.dropLast(1) else it }
        if (tokens.size < 2) throw UsageException("${file.path}: name must be PERSON-LABEL[-N].csv, e.g. p1-anger-3.csv")
        val frames = try {
            ContactCsv.read(InputFiles.readText("in", file.path), file.path)
        } catch (e: IllegalArgumentException) {
            throw UsageException(e.message.orEmpty())
        }
        Triple(tokens[0], tokens.drop(1).joinToString("-"), SocialTouchFeatures.of(frames.asSequence()))
    }
    val labels = rows.map { it.second }.distinct().sorted()
    if (labels.size < 2) throw UsageException("cannot train: need at least 2 labels, got ${labels.joinToString()}")
    val features = rows.map { it.third }
    val classes = IntArray(rows.size) { labels.indexOf(rows[it].second) }
    val model = SocialTouchModel(labels, LogitBoost.train(features, classes, labels.size, iterations))
    OutputFiles.write(out) { it.write(model.encode().toByteArray(Charsets.UTF_8)) }
    val messages = TouchMessages(features, classes, rows.map { it.first }, labels.size)
    val cv = if (messages.size >= 10) String.format(Locale.ROOT, "%.1f %%", 100 * SocialTouchEvaluation.crossValidate(messages, iterations = iterations)) else "n/a (< 10 messages)"
    val people = messages.people.distinct().size
    val lopo = if (people >= 2) String.format(Locale.ROOT, "%.1f %%", 100 * SocialTouchEvaluation.leaveOnePersonOut(messages, iterations)) else "n/a (1 person)"
    console.err.println("train: ${rows.size} messages from $people people, labels ${labels.joinToString(" ")}, LogitBoost $iterations rounds; 10x10-fold CV $cv, leave-one-person-out $lopo; wrote $out")
}

/** `hapticon classify --model SOCIAL.json --in MESSAGE.csv`: `label,probability` of the one message. */
internal fun classifySocialTouch(modelText: String, modelPath: String, path: String, console: Console) {
    val model = try {
        SocialTouchModel.decode(modelText)
    } catch (e: IllegalArgumentException) {
        throw UsageException("$modelPath: ${e.message}")
    }
    val frames = try {
        ContactCsv.read(InputFiles.readText("in", path), path)
    } catch (e: IllegalArgumentException) {
        throw UsageException(e.message.orEmpty())
    }
    val (label, probability) = model.classify(SocialTouchFeatures.of(frames.asSequence()))
    console.out.println("label,probability")
    console.out.println(String.format(Locale.ROOT, "%s,%.3f", label, probability))
}
