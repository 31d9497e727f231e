package org.hapticon.companion.bench

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assume.assumeTrue
import org.junit.Test

class GrainLatencyTest {
    @Test
    fun run_onePressCycle_measuresEveryGrainItCauses() {
        // One 2 s press-and-release at 1 kHz fires 46 grains (SensorDemoTest sees the same 46 in the CSV).
        val result = GrainLatency(samples = 2_000, warmupSamples = 0).run()
        assertEquals(2_000, result.samples)
        assertEquals(46, result.grains)
        assertTrue(result.toString(), result.p50Micros > 0 && result.p50Micros <= result.p99Micros && result.p99Micros <= result.maxMicros)
    }

    @Test
    fun run_warmupSamples_areNotCounted() {
        // The first 1000 samples are the rest and the 0.8 s rise, whose 24 grains climb bins 1..24 of 25; the release fires the other 22.
        val result = GrainLatency(samples = 1_000, warmupSamples = 1_000).run()
        assertEquals(22, result.grains)
    }

    @Test
    fun run_afterWarmup_frameToCommandAllocatesNothingPerSample() {
        // The default route is the real GrainEngine: LiveFrame decoding, the engine, its sink encoding the command.
        val result = GrainLatency(samples = 2_000, warmupSamples = 20_000).run()
        assertTrue(result.toString(), !result.handlerBytesPerSample.isNaN() && result.readerBytesPerSample >= result.handlerBytesPerSample)
        // Nothing per sample: one object per sample would cost at least 16 bytes per sample. Below one byte allows
        // only a one-off allocation in the run (a JIT tier change briefly running unoptimised code: 432 bytes once
        // in 2,000 samples was seen in a full `./build test`).
        assertTrue(result.toString(), result.handlerBytesPerSample < 1.0)
    }

    @Test
    fun run_onLinux_attributesTheWorstGrainsRunQueueWait() {
        assumeTrue("the attribution reads Linux's schedstat", java.io.File("/proc/thread-self/schedstat").exists())
        val result = GrainLatency(samples = 2_000, warmupSamples = 2_000).run()
        assertTrue(result.toString(), result.runQueueMicrosAtMax >= 0.0)
        assertTrue(result.toString(), result.maxWithoutRunQueueMicros <= result.maxMicros)
        assertTrue(result.toString(), result.over1msByRunQueue <= result.over1ms && result.over1msWithGc <= result.over1ms)
    }

    @Test
    fun run_readerSetup_runsOnTheReaderThreadWithItsLinuxId() {
        assumeTrue("thread ids come from Linux's /proc/thread-self", java.io.File("/proc/thread-self").exists())
        var seen: Pair<String, Long>? = null
        val result = GrainLatency(samples = 2_000, warmupSamples = 0, readerSetup = { tid -> seen = Thread.currentThread().name to tid }).run()
        assertEquals(46, result.grains)
        val (name, tid) = seen!!
        assertEquals("hapticon-bench-grain-latency", name)
        assertTrue("tid $tid", tid > 0 && tid != ProcessHandle.current().pid())
    }

    @Test
    fun run_onLinuxHotSpot_sortsSlowGrainsByCauseAndLogsSafepoints() {
        assumeTrue("steal and the reader's CPU are read from /proc", java.io.File("/proc/stat").exists())
        val result = GrainLatency(samples = 2_000, warmupSamples = 2_000).run()
        // The safepoint log was on (HotSpot's VM.log), and the run's steal share was read.
        assertTrue(result.toString(), result.safepoints >= 0 && result.stealShare in 0.0..1.0)
        val causes = result.over1msByRunQueue + result.over1msBySafepoint + result.over1msByWaitAndSafepoint + result.over1msWithGc + result.over1msBySteal
        assertTrue(result.toString(), result.over1msUnexplained <= result.over1ms && (result.over1ms == 0 || causes + result.over1msUnexplained >= result.over1ms))
    }

    @Test
    fun run_bothRoutes_seeTheSameGrainsOfOnePressCycle() {
        // GrainEngine (counts -> FSR force from the channel's RAW unit and the 12-bit device info) decides as the
        // re-created arithmetic does: the same 46 grains.
        val engine = GrainLatency(samples = 2_000, warmupSamples = 0, route = GrainLatency.Route.ENGINE).run()
        val baseline = GrainLatency(samples = 2_000, warmupSamples = 0, route = GrainLatency.Route.ARITHMETIC).run()
        assertEquals(46, engine.grains)
        assertEquals(46, baseline.grains)
    }

    @Test
    fun run_arithmeticBaseline_afterWarmup_allocatesNothingPerSample() {
        val result = GrainLatency(samples = 2_000, warmupSamples = 20_000, route = GrainLatency.Route.ARITHMETIC).run()
        assertTrue(result.toString(), result.handlerBytesPerSample < 1.0)
    }

    @Test
    fun run_pacedAtTheBoardsRate_takesAPeriodPerSampleAndSeesTheSameGrains() {
        // 1 kHz pacing: 2,000 samples cannot take less than 2 s, and pacing changes no decision.
        val started = System.nanoTime()
        val result = GrainLatency(samples = 2_000, warmupSamples = 0, intervalMicros = 1_000).run()
        val seconds = (System.nanoTime() - started) / 1e9
        assertEquals(46, result.grains)
        assertTrue("took $seconds s", seconds >= 2.0)
    }

    @Test
    fun run_readerKeptSpinning_seesTheSameGrains() {
        val result = GrainLatency(samples = 2_000, warmupSamples = 0, readerSpinMicros = 200).run()
        assertEquals(46, result.grains)
    }

    @Test
    fun run_onLinux_measuresTheReadersCpuAsAShareOfOneCore() {
        assumeTrue("the reader's CPU time is read from Linux's schedstat", java.io.File("/proc/thread-self/schedstat").exists())
        val result = GrainLatency(samples = 500, warmupSamples = 100, intervalMicros = 1_000).run()
        // A thread runs on at most one core; paced at 1 kHz the reader is parked most of each period.
        assertTrue(result.toString(), result.readerCpuMicrosPerSample > 0.0 && result.readerCpuShare > 0.0 && result.readerCpuShare < 1.0)
    }

    @Test(expected = IllegalArgumentException::class)
    fun constructor_negativeSpin_isRejected() {
        GrainLatency(samples = 1, warmupSamples = 0, readerSpinMicros = -1)
    }

    @Test(expected = IllegalArgumentException::class)
    fun constructor_noSamples_isRejected() {
        GrainLatency(samples = 0, warmupSamples = 0)
    }
}
