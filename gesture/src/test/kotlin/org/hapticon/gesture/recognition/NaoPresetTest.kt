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
        val spans = listOf(NaoSpan(100, 300, "poke-gentle"))
        // Window [40, 120) overlaps 20 samples; [60, 140) 40; [80, 160) 60 = 0.75 × 80: labelled.
        assertEquals("none", NaoPreset.windowLabel(spans, 40))
        assertEquals("none", NaoPreset.windowLabel(spans, 60))
        assertEquals("none", NaoPreset.windowLabel(spans, 79))
        assertEquals("poke-gentle", NaoPreset.windowLabel(spans, 80))
        assertEquals("poke-gentle", NaoPreset.windowLabel(spans, 240))
        assertEquals("none", NaoPreset.windowLabel(spans, 241))
        // A gesture shorter than 60 samples never labels a window.
        assertEquals("none", NaoPreset.windowLabel(listOf(NaoSpan(100, 159, "hit-energetic")), 90))
        // Two gestures in one window: the one it overlaps more, if ≥ 60.
        assertEquals("tickle-gentle", NaoPreset.windowLabel(listOf(NaoSpan(0, 15, "hit-gentle"), NaoSpan(15, 200, "tickle-gentle")), 0))
    }

    @Test
    fun windows_stepByHalfAWindow() {
        val recording = NaoRecording("p", List(4) { DoubleArray(200) { 10.0 } }, listOf(NaoSpan(40, 200, "squeeze-energetic")))
        val windows = NaoPreset.windows(listOf(recording))
        // Starts 0, 40, 80, 120 (120 + 80 = 200).
        assertEquals(4, windows.size)
        assertEquals(listOf("none", "squeeze-energetic", "squeeze-energetic", "squeeze-energetic"), windows.labels)
        assertEquals(124, windows.features[0].size)
    }

    @Test
    fun windows_recordingShorterThanAWindow_givesNone() {
        val recording = NaoRecording("p", List(4) { DoubleArray(79) }, emptyList())
        assertEquals(0, NaoPreset.windows(listOf(recording)).size)
    }

    @Test
    fun evaluation_syntheticPeople_randomSplitFlattersLeaveOnePersonOut() {
        val windows = NaoPreset.windows(NaoSyntheticPeople.sessions(count = 4, takesPerClass = 2, seed = 7))
        val small = ForestParams(trees = 20, maxDepth = 32, featuresPerSplit = 20, minSamplesSplit = 8)
        val split = NaoEvaluation.randomSplit(windows, small)
        val lopo = NaoEvaluation.leaveOnePersonOut(windows, small)
        assertEquals(windows.size - (windows.size * 0.7).toInt(), split.total)
        assertEquals(windows.size, lopo.total)
        // Far above the 1-in-11 guess on these well-separated synthetic gestures.
        assertTrue("split ${split.combined}", split.combined > 0.5)
        assertTrue("lopo ${lopo.combined}", lopo.combined > 0.3)
        assertTrue(split.gesture >= split.combined)
    }

    @Test
    fun scores_fromAKnownConfusion() {
        val n = NaoPreset.LABELS.size
        val confusion = Array(n) { IntArray(n) }
        val tickle = NaoPreset.LABELS.indexOf("tickle-gentle")
        val poke = NaoPreset.LABELS.indexOf("poke-gentle")
        val pokeEnergetic = NaoPreset.LABELS.indexOf("poke-energetic")
        confusion[tickle][tickle] = 64
        confusion[tickle][poke] = 11
        confusion[tickle][pokeEnergetic] = 25
        val scores = NaoScores(confusion)
        assertEquals(0.64, scores.share("tickle-gentle", "tickle-gentle"), 1e-12)
        assertEquals(0.11, scores.share("tickle-gentle", "poke-gentle"), 1e-12)
        assertEquals(0.64, scores.combined, 1e-12)
        assertEquals(0.64, scores.gesture, 1e-12)
        // Intensity right for tickle-gentle and poke-gentle predictions: 75 of 100.
        assertEquals(0.75, scores.intensity, 1e-12)
    }

    @Test
    fun naoCsv_readsTimeFourResistancesAndLabelSpans() {
        val csv = "time_s,r1,r2,r3,r4,label\n" +
            (0 until 6).joinToString("\n") { i -> "${i * 0.025},10,11,12,13,${if (i in 2..4) "poke_gentle" else "none"}" }
        val recording = NaoCsv.read(csv, "p1")
        assertEquals(6, recording.frameCount)
        assertEquals(13.0, recording.channels[3][5], 0.0)
        assertEquals("[poke-gentle[2, 5)]", recording.spans.toString())
    }

    @Test
    fun naoCsv_badRows_nameTheLine() {
        for ((csv, message) in listOf(
            "time,r1,r2,r3\n0,1,2,3\n" to "line 1: expected 4 resistance columns, found 3",
            "time,r1,r2,r3,r4\n0,1,2,3,x\n" to "line 2: resistance r4 must be a finite number >= 0, was \"x\"",
            "time,r1,r2,r3,r4\n0,1,2,3,4\n0,1,2,3,4\n" to "line 3: time must be a number after the previous row's, was \"0\"",
            "time,r1,r2,r3,r4,label\n0,1,2,3,4,wave-gentle\n" to "line 2: unknown gesture 'wave-gentle'; expected one of ${NaoPreset.LABELS.joinToString()}",
        )) {
            try {
                NaoCsv.read(csv, "p")
                fail("accepted $csv")
            } catch (e: IllegalArgumentException) {
                assertEquals(message, e.message)
            }
        }
    }
}
