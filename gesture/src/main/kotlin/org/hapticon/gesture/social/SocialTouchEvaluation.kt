package org.hapticon.gesture.social

import java.util.Random
import kotlin.math.sqrt

/** Labelled touch messages: the 13 [features] of each, its class index in [labels] and whose it is in [people]. */
public class TouchMessages(public val features: List<DoubleArray>, public val labels: IntArray, public val people: List<String>, public val classCount: Int) {
    init {
        require(features.size == labels.size && labels.size == people.size) { "${features.size} rows, ${labels.size} labels, ${people.size} people" }
        require(labels.all { it in 0 until classCount }) { "labels must be in 0 until $classCount" }
    }

    /** Number of messages. */
    public val size: Int get() = labels.size

    /** The messages of [classes] only (indices into this set's classes), in order, relabelled by their place in [classes]. */
    public fun select(classes: List<Int>): TouchMessages {
        val keep = labels.indices.filter { labels[it] in classes }
        return TouchMessages(keep.map { features[it] }, IntArray(keep.size) { classes.indexOf(labels[keep[it]]) }, keep.map { people[it] }, classes.size)
    }

    /** The messages of [person] only, in order. */
    public fun of(person: String): TouchMessages {
        val keep = people.indices.filter { people[it] == person }
        return TouchMessages(keep.map { features[it] }, IntArray(keep.size) { labels[keep[it]] }, keep.map { people[it] }, classCount)
    }
}

/**
 * Accuracies of several scorings (folds or people), each the share of its messages classified right, with the
 * [confusion] matrix summed over all of them (rows: actual class; columns: predicted).
 */
public class Accuracies(public val values: List<Double>, public val confusion: Array<IntArray>) {
    /** The mean of [values]. */
    public val mean: Double get() = values.average()

    /** The sample standard deviation of [values] (n − 1; 0 for one value). */
    public val sd: Double
        get() {
            if (values.size < 2) return 0.0
            val m = mean
            return sqrt(values.sumOf { (it - m) * (it - m) } / (values.size - 1))
        }

    /** Each class's share of its messages classified right (the diagonal of [confusion] by row). */
    public fun perClass(): DoubleArray = DoubleArray(confusion.size) { c -> confusion[c][c].toDouble() / maxOf(1, confusion[c].sum()) }
}

/**
 * The EIT-skin paper's evaluations, each cited from its text (`001_e790093bbd2e3cd3.txt`):
 *
 * - Experiment 1, [crossValidate]: one transmitter's messages, "ten 10-fold cross validations … using different
 *   randomly created subsets of the data" (:166), as WEKA's Experimenter runs them — run r shuffles with
 *   `new Random(r)`, r = 1..10, stratifies and deals the folds, shuffling each training set with the same generator
 *   (weka-stable 3.8.6 `weka/experiment/CrossValidationResultProducer.java` lines 376–391, through [WekaOrder]). The
 *   paper reports a mean and standard deviation (Table 3, :178–182) without saying over what (paper silent); ours
 *   are over the 100 folds, as the Experimenter reports ten runs of 10-fold cross-validation.
 * - Experiment 2, [leaveOneTransmitterOut]: "trained with the data from 41 participants and tested with touch data
 *   from the one remaining participant … repeated until touch from all 42 participants had been classified" (:212);
 *   mean and standard deviation across transmitters (Table 6, :218).
 * - Experiment 1's cross-participant check, [trainTest]: "trained with data from Participant A to classify data
 *   from Participant B, and vice versa" (Table 4, :176).
 */
public object SocialTouchEvaluation {
    /** [runs] runs of stratified [folds]-fold cross-validation, WEKA's Experimenter's way, runs numbered from [firstRun]. */
    public fun crossValidate(
        messages: TouchMessages,
        folds: Int = 10,
        runs: Int = 10,
        settings: LogitBoost.Settings = LogitBoost.WEKA_DEFAULTS,
        firstRun: Int = 1,
    ): Accuracies {
        require(folds >= 2 && messages.size >= folds) { "need at least $folds messages for $folds folds, got ${messages.size}" }
        require(runs >= 1) { "runs must be >= 1, was $runs" }
        val confusion = Array(messages.classCount) { IntArray(messages.classCount) }
        val accuracies = ArrayList<Double>(runs * folds)
        for (run in firstRun until firstRun + runs) {
            val random = Random(run.toLong())
            val order = IntArray(messages.size) { it }
            WekaOrder.randomize(order, random)
            val dealt = WekaOrder.stratify(order, messages.labels, folds)
            for (fold in 0 until folds) {
                val train = WekaOrder.trainFold(dealt, folds, fold, random)
                val test = WekaOrder.testFold(dealt, folds, fold)
                accuracies += score(messages, train, test, settings, confusion)
            }
        }
        return Accuracies(accuracies, confusion)
    }

    /** Each person's messages scored by a model trained on everyone else's (in the messages' order). */
    public fun leaveOneTransmitterOut(messages: TouchMessages, settings: LogitBoost.Settings = LogitBoost.WEKA_DEFAULTS): Accuracies {
        val people = messages.people.distinct()
        require(people.size >= 2) { "leave-one-transmitter-out needs at least 2 people, got ${people.size}" }
        val confusion = Array(messages.classCount) { IntArray(messages.classCount) }
        val accuracies = people.map { person ->
            val train = messages.people.indices.filter { messages.people[it] != person }.toIntArray()
            val test = messages.people.indices.filter { messages.people[it] == person }.toIntArray()
            score(messages, train, test, settings, confusion)
        }
        return Accuracies(accuracies, confusion)
    }

    /** The accuracy on [test] of a model trained on [train] (the same classes). */
    public fun trainTest(train: TouchMessages, test: TouchMessages, settings: LogitBoost.Settings = LogitBoost.WEKA_DEFAULTS): Double {
        require(train.classCount == test.classCount) { "train has ${train.classCount} classes, test ${test.classCount}" }
        val model = LogitBoost.train(train.features, train.labels, train.classCount, settings)
        val p = DoubleArray(train.classCount)
        return test.labels.indices.count { model.predict(test.features[it], p) == test.labels[it] }.toDouble() / test.size
    }

    private fun score(messages: TouchMessages, train: IntArray, test: IntArray, settings: LogitBoost.Settings, confusion: Array<IntArray>): Double {
        val model = LogitBoost.train(train.map { messages.features[it] }, IntArray(train.size) { messages.labels[train[it]] }, messages.classCount, settings)
        val p = DoubleArray(messages.classCount)
        var right = 0
        for (i in test) {
            val predicted = model.predict(messages.features[i], p)
            confusion[messages.labels[i]][predicted]++
            if (predicted == messages.labels[i]) right++
        }
        return right.toDouble() / test.size
    }
}
