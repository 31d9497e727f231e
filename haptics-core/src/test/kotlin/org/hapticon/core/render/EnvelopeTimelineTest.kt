package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Test

class EnvelopeTimelineTest {
    /** Icons whose runs are awkward: coinciding onsets, missing segments, silent repetitions, a tail after the last envelope. */
    private val awkward = listOf(
        HapticIcon.LONGEST_ALLOWED,
        HapticIcon("sub-sample-period", 0.001, 0.002, 0.9, 0.003, 60.0, 0.00001, 64),
        HapticIcon("no-attack", 0.0, 0.05, 0.8, 0.05, 60.0, 0.2, 3),
        HapticIcon("attack-only", 0.05, 0.0, 0.6, 0.0, 62.0, 0.03, 9),
        HapticIcon("release-only", 0.0, 0.0, 0.6, 0.05, 62.0, 0.03, 9),
        HapticIcon("silent-repeats", 0.0, 0.0, 0.5, 0.0, 60.0, 0.01, 5),
        HapticIcon("odd-period", 0.0123, 0.0, 0.7, 0.0377, 61.3, 0.0311, 37),
        HapticIcon("dense", 0.4, 0.3, 0.8, 0.3, 64.0, 0.0157, 64),
    ) + HapticIcon.PRESETS

    /** The run starts by definition: 0 and every onset + segment boundary below sampleCount, sorted, distinct. */
    private fun definedRunStarts(icon: HapticIcon, model: EnvelopeModel, fs: Int, sampleCount: Long): List<Long> {
        val starts = sortedSetOf(0L)
        for (k in 0 until icon.count) {
            val onset = Math.round(k * icon.period * fs)
            for (segment in envelopeSegments(icon, model, fs).filter { it.endSample > it.firstSample }) {
                starts += onset + segment.firstSample
                starts += onset + segment.endSample
            }
        }
        return starts.filter { it < sampleCount }
    }

    private fun sweptRunStarts(timeline: EnvelopeTimeline): List<Long> {
        val sweep = EnvelopeSweep(timeline)
        val starts = ArrayList<Long>()
        while (true) {
            starts += sweep.start
            if (sweep.end >= timeline.sampleCount) break
            sweep.advance()
        }
        assertEquals(timeline.sampleCount, sweep.end)
        return starts
    }

    @Test
    fun sweep_longestIconAt44100_visitsItsTwoHundredFiftyFiveRunsInOrder() {
        val timeline = EnvelopeTimeline(HapticIcon.LONGEST_ALLOWED, EnvelopeModel.PAPER, 44_100, 1_323_000)
        val starts = sweptRunStarts(timeline)
        assertEquals(255, starts.size)
        // Onsets round(k · 19293.75); one envelope's boundaries at 0, 35832, 71663, 107494.
        assertEquals(listOf(0L, 19_294L, 35_832L, 38_588L, 55_126L, 57_881L, 71_663L, 74_420L), starts.take(8))
    }

    @Test
    fun sweep_awkwardIconsBothModels_visitsExactlyTheDefinedRunStarts() {
        for (icon in awkward) for (fs in listOf(8_000, 44_100)) for (model in EnvelopeModel.values()) {
            val sampleCount = Math.round(icon.duration * fs)
            val timeline = EnvelopeTimeline(icon, model, fs, sampleCount)
            assertEquals("${icon.name} $fs $model", definedRunStarts(icon, model, fs, sampleCount), sweptRunStarts(timeline))
        }
    }

    @Test
    fun read_exactDoubles_awkwardIconsBothModels_equalSampleAtBitForBit() {
        // The stream sweeps the runs; sampleAt finds each by binary search. They must agree exactly.
        for (icon in awkward) for (fs in listOf(8_000, 44_100)) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, fs, model, RenderMode.EXACT)
            assertEquals(renderer.sampleCount, RenderAssertions.streamEqualsSampleAt(renderer, "${icon.name} $fs $model"))
        }
    }

    @Test
    fun envelopeAt_awkwardIconsBothModels_isTheMaximumOverAllRepetitions() {
        for (icon in awkward) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, 8_000, model)
            for (i in 0 until renderer.sampleCount) {
                assertEquals("${icon.name} $model $i", IconReference.envelope(icon, model, i, 8_000), renderer.envelopeAt(i), 1e-12)
            }
        }
    }

    @Test
    fun envelopeAt_silentRepetitions_isZeroThroughout() {
        val renderer = IconRenderer(HapticIcon("silent-repeats", 0.0, 0.0, 0.5, 0.0, 60.0, 0.01, 5), 8_000)
        assertEquals(320L, renderer.sampleCount)
        for (i in 0 until 320L) assertEquals(0.0, renderer.envelopeAt(i), 0.0)
    }
}
