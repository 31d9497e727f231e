package org.hapticon.gesture.social

import java.util.SplittableRandom

/** Labelled touch messages: the 13 [features] of each, its class index in [labels] and whose it is in [people]. */
public class TouchMessages(public val features: List<DoubleArray>, public val labels: IntArray, public val people: List<String>, public val classCount: Int) {
    init {
        require(features.size == labels.size && labels.size == people.size) { "${features.size} rows, ${labels.size} labels, ${people.size} people" }
        require(labels.all { it in 0 until classCount }) { "labels must be in 0 until $classCount" }
    }

    /** Number of messages. */
    public val size: Int get() = labels.size
}

/**
 * The EIT-skin paper's evaluation, 10 × 10-fold cross-validation (Weka's default: ten runs of stratified 10-fold CV
 * with a fresh shuffle each), and ours, leave one person out. Both return the share of messages classified right.
 */
public object SocialTouchEvaluation {
    /**
     * Mean accuracy over [runs] runs of [folds]-fold cross-validation: each run deals every class's messages round
     * robin into the folds after a shuffle seeded from [seed] and the run (stratified), trains on all folds but one
     * and scores that one.
     */
    public fun crossValidate(messages: TouchMessages, folds: Int = 10, runs: Int = 10, iterations: Int = LogitBoost.DEFAULT_ITERATIONS, seed: Long = 1L): Double {
        require(folds >= 2 && messages.size >= folds) { "need at least $folds messages for $folds folds, got ${messages.size}" }
        require(runs >= 1) { "runs must be >= 1, was $runs" }
        var right = 0L
        var scored = 0L
        repeat(runs) { run ->
            val random = SplittableRandom(seed + run)
            val fold = IntArray(messages.size)
            var next = 0
            for (c in 0 until messages.classCount) {
                val members = messages.labels.indices.filter { messages.labels[it] == c }.toMutableList()
                for (i in members.size - 1 downTo 1) {
                    val j = random.nextInt(i + 1)
                    val t = members[i]; members[i] = members[j]; members[j] = t
                }
                for (m in members) fold[m] = next++ % folds
            }
            for (k in 0 until folds) {
                val train = messages.labels.indices.filter { fold[it] != k }
                val test = messages.labels.indices.filter { fold[it] == k }
                right += score(messages, train, test, iterations)
                scored += test.size
            }
        }
        return right.toDouble() / scored
    }

    /** Accuracy when each person's messages are scored by a model trained on everyone else's. */
    public fun leaveOnePersonOut(messages: TouchMessages, iterations: Int = LogitBoost.DEFAULT_ITERATIONS): Double {
        val people = messages.people.distinct()
        require(people.size >= 2) { "leave-one-person-out needs at least 2 people, got ${people.size}" }
        var right = 0L
        for (person in people) {
            val train = messages.people.indices.filter { messages.people[it] != person }
            val test = messages.people.indices.filter { messages.people[it] == person }
            right += score(messages, train, test, iterations)
        }
        return right.toDouble() / messages.size
    }

    private fun score(messages: TouchMessages, train: List<Int>, test: List<Int>, iterations: Int): Int {
        val model = LogitBoost.train(train.map { messages.features[it] }, IntArray(train.size) { messages.labels[train[it]] }, messages.classCount, iterations)
        val p = DoubleArray(messages.classCount)
        return test.count { model.predict(messages.features[it], p) == messages.labels[it] }
    }
}
