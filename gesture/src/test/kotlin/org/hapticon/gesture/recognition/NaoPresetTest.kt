package org.hapticon.gesture.recognition

import org.hapticon.gesture.synthetic.NaoSyntheticPeople
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class NaoPresetTest {
    @Test
    fun preset_isThePapersPipeline() {
        assertEquals(40.0, NaoPreset.SAMPLE_RATE, 0.0)
        assertEquals(80, NaoPreset.WINDOW_FRAMES)
        assertEquals(40, NaoPreset.HOP_FRAMES)
        assertEquals(11, NaoPreset.LABELS.size)
        assertEquals(listOf("hit-gentle", "hit-energetic", "poke-gentle"), NaoPreset.LABELS.take(3))
        assertEquals("none", NaoPreset.LABELS.last())
        val forest = NaoPreset.FOREST
        assertEquals(listOf(100, 32, 20, 8), listOf(forest.trees, forest.maxDepth, forest.featuresPerSplit, forest.minSamplesSplit))
        assertTrue(forest.bootstrap)
        assertEquals(listOf("hand", "lower-arm", "upper-arm", "shoulder"), NaoPreset.LOCATIONS)
    }

    @Test
    fun tasks_areThePapersFourClassifiers_eachWithNoneAndItsChance() {
        // 004_7d5078645d142b2a.txt:205 (1/5, 1/3, 1/6) and :215 (1/11).
        assertEquals(listOf(5, 3, 6, 11), NaoTask.entries.map { it.classes.size })
        assertEquals(listOf("gentle", "energetic", "none"), NaoTask.INTENSITY.classes)
        assertEquals(listOf("hit", "poke", "squeeze", "stroke", "tickle", "none"), NaoTask.GESTURE.classes)
        assertEquals(NaoPreset.LOCATIONS + "none", NaoTask.LOCATION.classes)
        assertEquals(1.0 / 3, NaoTask.INTENSITY.chance, 0.0)
        assertEquals(NaoTask.entries.toSet(), NaoPreset.FORESTS.keys)
        // Table 2 (004_7d5078645d142b2a.txt:180-194): n_estimators and max_depth per task, the rest shared.
        assertEquals(listOf(50 to 40, 100 to 20, 100 to 40, 100 to 32), NaoTask.entries.map { NaoPreset.FORESTS.getValue(it).let { f -> f.trees to f.maxDepth } })
        assertEquals(setOf(Triple(20, 8, 1)), NaoPreset.FORESTS.values.map { Triple(it.featuresPerSplit, it.minSamplesSplit, it.minLeaf) }.toSet())
        val span = NaoSpan(0, 80, "tickle-gentle", "shoulder")
        assertEquals(listOf("shoulder", "gentle", "tickle", "tickle-gentle"), NaoTask.entries.map { it.labelOf(span) })
        assertEquals(List(4) { "none" }, NaoTask.entries.map { it.labelOf(null) })
    }

    @Test
    fun features_are31PerChannel_entropyOnlyOfTheSignal() {
        assertEquals(31, NaoPreset.FEATURES_PER_CHANNEL)
        val names = NaoPreset.featureNames(listOf("r1"))
        assertEquals(31, names.size)
        assertEquals(listOf("r1.entropy"), names.filter { it.endsWith("entropy") })
        for (series in listOf("r1.", "r1.d1.", "r1.d2.")) {
            for (stat in listOf("sum", "max", "min", "mean", "median", "std", "variance", "area", "iqr", "peaks")) {
                assertTrue("$series$stat", "$series$stat" in names)
            }
        }
        // Our default keeps 33: the entropy of both differences too.
        assertEquals(33, WindowFeatures.PER_CHANNEL)
    }

    @Test
    fun naoFeatures_areTheMatchingDefaultFeatures() {
        val ramp = DoubleArray(100) { it * 0.5 }
        val channels = List(4) { c -> DoubleArray(100) { ramp[it] * (c + 1) } }
        val out = DoubleArray(4 * 31)
        NaoFeatures().extract(channels, 10, out)
        val full = DoubleArray(33)
        WindowFeatures(40.0, 80).extract(channels[2], 10, 80, full, 0)
        for (k in 0 until 31) assertEquals(full[NaoPreset.FEATURE_INDICES[k]], out[2 * 31 + k], 0.0)
        // Channel 3's mean over samples 10..89 of 1.5·i.
        assertEquals(1.5 * 49.5, out[2 * 31 + 3], 1e-9)
    }

    @Test
    fun windowLabel_takesTheGestureAtThreeQuartersOfTheWindow() {
        val spans = listOf(NaoSpan(100, 300, "poke-gentle", "hand"))
        // Window [40, 120) overlaps 20 samples; [60, 140) 40; [80, 160) 60 = 0.75 × 80: labelled.
        assertEquals("none", NaoPreset.windowLabel(spans, 40))
        assertEquals("none", NaoPreset.windowLabel(spans, 60))
        assertEquals("none", NaoPreset.windowLabel(spans, 79))
        assertEquals("poke-gentle", NaoPreset.windowLabel(spans, 80))
        assertEquals("poke-gentle", NaoPreset.windowLabel(spans, 240))
        assertEquals("none", NaoPreset.windowLabel(spans, 241))
        // A gesture shorter than 60 samples never labels a window.
        assertEquals("none", NaoPreset.windowLabel(listOf(NaoSpan(100, 159, "hit-energetic", "hand")), 90))
        // Two gestures in one window: the one it overlaps more, if ≥ 60.
        assertEquals("tickle-gentle", NaoPreset.windowLabel(listOf(NaoSpan(0, 15, "hit-gentle", "hand"), NaoSpan(15, 200, "tickle-gentle", "upper-arm")), 0))
    }

    @Test
    fun windows_stepByHalfAWindow_andCarryEveryTasksLabel() {
        val recording = NaoRecording("p", List(4) { DoubleArray(200) { 10.0 } }, listOf(NaoSpan(40, 200, "squeeze-energetic", "lower-arm")))
        val windows = NaoPreset.windows(listOf(recording))
        // Starts 0, 40, 80, 120 (120 + 80 = 200).
        assertEquals(4, windows.size)
        assertEquals(listOf("none", "squeeze-energetic", "squeeze-energetic", "squeeze-energetic"), windows.labels(NaoTask.COMBINED))
        assertEquals(listOf("none", "lower-arm", "lower-arm", "lower-arm"), windows.labels(NaoTask.LOCATION))
        assertEquals(listOf("none", "energetic", "energetic", "energetic"), windows.labels(NaoTask.INTENSITY))
        assertEquals(124, windows.features[0].size)
    }

    @Test
    fun windows_recordingShorterThanAWindow_givesNone() {
        val recording = NaoRecording("p", List(4) { DoubleArray(79) }, emptyList())
        assertEquals(0, NaoPreset.windows(listOf(recording)).size)
    }

    @Test
    fun evaluation_separateForestPerTask_scoresOverTheTasksOwnClasses() {
        val windows = NaoPreset.windows(NaoSyntheticPeople.sessions(count = 3, rounds = 1, seed = 7))
        val small = ForestParams(trees = 10, maxDepth = 32, featuresPerSplit = 20, minSamplesSplit = 8)
        for (task in NaoTask.entries) {
            val split = NaoEvaluation.randomSplit(windows, task, small)
            assertEquals(task.classes.size, split.confusion.size)
            assertEquals(windows.size - (windows.size * 0.7).toInt(), split.total)
            // Far above chance on these well-separated synthetic gestures.
            assertTrue("${task.label} ${split.accuracy}", split.accuracy > 2 * task.chance)
        }
        // Intensity is scored over gentle, energetic and none: every window counts, none-windows included.
        val lopo = NaoEvaluation.leaveOnePersonOut(windows, NaoTask.INTENSITY, small)
        assertEquals(windows.size, lopo.total)
        assertTrue(lopo.confusion[2].sum() > 0)
    }

    @Test
    fun scores_fromAKnownConfusion() {
        val n = NaoPreset.LABELS.size
        val confusion = Array(n) { IntArray(n) }
        val tickle = NaoPreset.LABELS.indexOf("tickle-gentle")
        val poke = NaoPreset.LABELS.indexOf("poke-gentle")
        val none = NaoPreset.LABELS.indexOf("none")
        confusion[tickle][tickle] = 64
        confusion[tickle][poke] = 11
        confusion[tickle][none] = 25
        confusion[none][none] = 300
        val scores = NaoScores(NaoTask.COMBINED, confusion)
        assertEquals(0.64, scores.share("tickle-gentle", "tickle-gentle"), 1e-12)
        assertEquals(0.11, scores.share("tickle-gentle", "poke-gentle"), 1e-12)
        // 364 of 400 windows right; the two classes with windows recall 0.64 and 1.0.
        assertEquals(364.0 / 400, scores.accuracy, 1e-12)
        assertEquals(0.82, scores.averageLabelAccuracy, 1e-12)
    }

    @Test
    fun scores_intensity_noneCountsAsAClass() {
        val confusion = arrayOf(intArrayOf(8, 1, 1), intArrayOf(0, 9, 1), intArrayOf(2, 0, 78))
        val scores = NaoScores(NaoTask.INTENSITY, confusion)
        assertEquals(95.0 / 100, scores.accuracy, 1e-12)
        assertEquals((0.8 + 0.9 + 78.0 / 80) / 3, scores.averageLabelAccuracy, 1e-12)
        assertEquals(2.0 / 80, scores.share("none", "gentle"), 1e-12)
    }
}
