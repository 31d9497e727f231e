package org.hapticon.gesture.social

import org.junit.Assert.assertEquals
import org.junit.Test
import weka.classifiers.evaluation.Evaluation
import weka.core.Attribute
import weka.core.DenseInstance
import weka.core.Instances
import java.util.Random
import kotlin.math.abs

/**
 * Our [LogitBoost] against WEKA's own (weka-stable 3.8.6, `weka.classifiers.meta.LogitBoost` over its default
 * `weka.classifiers.trees.DecisionStump`), the EIT-skin paper's tool: the same data in the same order and the same
 * settings must give the same class for every test instance and the same probabilities to the last bit, and our
 * 10 × 10-fold cross-validation the same number right per run as WEKA's `Evaluation.crossValidateModel` with
 * `new Random(run)`.
 */
class LogitBoostWekaOracleTest {
    private fun instances(rows: List<DoubleArray>, labels: IntArray, classCount: Int): Instances {
        val width = rows[0].size
        val attributes = ArrayList<Attribute>()
        for (k in 0 until width) attributes += Attribute("f$k")
        attributes += Attribute("class", (0 until classCount).map { "c$it" })
        val data = Instances("oracle", attributes, rows.size)
        data.setClassIndex(width)
        for ((i, row) in rows.withIndex()) data.add(DenseInstance(1.0, row + labels[i].toDouble()))
        return data
    }

    private fun weka(settings: LogitBoost.Settings) = weka.classifiers.meta.LogitBoost().apply {
        numIterations = settings.iterations
        shrinkage = settings.shrinkage
        zMax = settings.zMax
        weightThreshold = settings.weightThresholdPercent
        likelihoodThreshold = settings.likelihoodThreshold
    }

    /** Trains both on [train]; returns how many of [test]'s classes differ and the largest probability difference. */
    private fun compare(train: TouchMessages, test: List<DoubleArray>, settings: LogitBoost.Settings): Pair<Int, Double> {
        val data = instances(train.features, train.labels, train.classCount)
        val theirs = weka(settings).also { it.buildClassifier(data) }
        val ours = LogitBoost.train(train.features, train.labels, train.classCount, settings)
        val p = DoubleArray(train.classCount)
        var differ = 0
        var worst = 0.0
        val probe = instances(test, IntArray(test.size), train.classCount)
        for ((i, row) in test.withIndex()) {
            val q = theirs.distributionForInstance(probe.instance(i))
            val ourClass = ours.predict(row, p)
            if (ourClass != theirs.classifyInstance(probe.instance(i)).toInt()) differ++
            for (j in p.indices) worst = maxOf(worst, abs(p[j] - q[j]))
        }
        return differ to worst
    }

    /** Participant A of the simulated Experiment 1, the emotions and no touch: 350 messages of Table 1's 13 features. */
    private val participantA: TouchMessages by lazy {
        SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.experiment1(), SocialTouchClasses.EMOTION_SET).of("A")
    }

    /** A messy set: 3 classes, integer-valued (tied) columns, a constant column and one that only separates class 2. */
    private val messy: TouchMessages by lazy {
        val random = Random(7)
        val rows = ArrayList<DoubleArray>()
        val labels = ArrayList<Int>()
        repeat(240) { i ->
            val c = i % 3
            rows += doubleArrayOf(random.nextInt(5) + c.toDouble(), 1.0, random.nextGaussian() + 0.7 * c, if (c == 2) 1.0 else 0.0, random.nextInt(3).toDouble())
            labels += c
        }
        TouchMessages(rows, labels.toIntArray(), List(rows.size) { "p" }, 3)
    }

    @Test
    fun defaults_onSimulatedTouchFeatures_giveWekasClassesAndProbabilities() {
        val train = TouchMessages(participantA.features.take(300), participantA.labels.copyOf(300), participantA.people.take(300), 7)
        val (differ, worst) = compare(train, participantA.features, LogitBoost.WEKA_DEFAULTS)
        assertEquals(0, differ)
        assertEquals("largest probability difference $worst", 0.0, worst, 0.0)
    }

    @Test
    fun everySetting_onAMessySet_givesWekasClassesAndProbabilities() {
        for (settings in listOf(
            LogitBoost.Settings(iterations = 30),
            LogitBoost.Settings(shrinkage = 0.3, iterations = 25),
            LogitBoost.Settings(zMax = 2.0),
            LogitBoost.Settings(zMax = 4.0),
            LogitBoost.Settings(weightThresholdPercent = 90, iterations = 20),
            LogitBoost.Settings(likelihoodThreshold = 0.01, iterations = 50),
        )) {
            val (differ, worst) = compare(messy, messy.features, settings)
            assertEquals("$settings", 0, differ)
            assertEquals("$settings: largest probability difference $worst", 0.0, worst, 0.0)
        }
    }

    @Test
    fun twoClasses_oneStumpPerRound_givesWekasClassesAndProbabilities() {
        val keep = messy.labels.indices.filter { messy.labels[it] < 2 }
        val two = TouchMessages(keep.map { messy.features[it] }, IntArray(keep.size) { messy.labels[keep[it]] }, keep.map { "p" }, 2)
        val (differ, worst) = compare(two, messy.features, LogitBoost.Settings(iterations = 15))
        assertEquals(0, differ)
        assertEquals(0.0, worst, 0.0)
        assertEquals(15, LogitBoost.train(two.features, two.labels, 2, 15).iterations)
    }

    @Test
    fun tenTenFoldCrossValidation_countsWhatWekasEvaluationCounts() {
        val ours = SocialTouchEvaluation.crossValidate(participantA, runs = 3)
        val data = instances(participantA.features, participantA.labels, 7)
        for (run in 1..3) {
            val evaluation = Evaluation(data)
            evaluation.crossValidateModel(weka(LogitBoost.WEKA_DEFAULTS), data, 10, Random(run.toLong()))
            val ourRight = ours.values.subList((run - 1) * 10, run * 10).zip(foldSizes(participantA.size)).sumOf { (a, n) -> Math.round(a * n).toInt() }
            assertEquals("run $run", evaluation.correct().toInt(), ourRight)
        }
    }

    private fun foldSizes(n: Int) = List(10) { fold -> n / 10 + if (fold < n % 10) 1 else 0 }
}
