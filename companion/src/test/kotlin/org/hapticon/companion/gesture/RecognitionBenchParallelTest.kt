package org.hapticon.companion.gesture

import org.junit.Assert.assertEquals
import org.junit.Test

class RecognitionBenchParallelTest {
    private val config = RecognitionBenchConfig(people = 3, seed = 7, takesPerLabel = 1, windows = listOf(1.0), treeCounts = listOf(3, 6))

    /** Everything but the timing, which differs between any two runs. */
    private fun figures(results: List<RecognitionResult>) =
        results.map { listOf(it.windowSeconds, it.trees.toDouble(), it.accuracyMean, it.accuracySd, it.latencyMs, it.liveHitRate) }

    @Test fun run_parallelAndSequentialSameSeed_giveIdenticalFigures() {
        val sequential = RecognitionBench.run(config, parallel = false) {}
        val parallel = RecognitionBench.run(config, parallel = true) {}
        assertEquals(2, sequential.size)
        assertEquals(figures(sequential), figures(parallel))
    }

    @Test fun personal_parallelAndSequentialSameSeed_giveIdenticalAccuracy() {
        val sequential = RecognitionBench.personal(config, trees = 5, examples = 2, parallel = false)
        val parallel = RecognitionBench.personal(config, trees = 5, examples = 2, parallel = true)
        assertEquals(listOf(sequential.accuracyMean, sequential.accuracySd), listOf(parallel.accuracyMean, parallel.accuracySd))
    }
}
