package org.hapticon.companion.bench

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.Json
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.sensor.grains.SensorBenchmarkResult
import org.hapticon.testing.TestIcons
import org.hapticon.testing.readAllSamples
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.sin

class BenchmarkTest {
    @Test
    fun run_quick_measuresEveryPartWithoutAllocatingPerBlock() {
        val steps = ArrayList<String>()
        val result = Benchmark(BenchConfig.QUICK) { steps += it }.run()

        assertEquals(listOf("longest", "presets"), result.throughputs.map { it.workload })
        assertEquals(1_323_000L, result.throughputs[0].samples)
        assertEquals(HapticIcon.PRESETS.sumOf { IconRenderer(it, 44_100).sampleCount }, result.throughputs[1].samples)
        // Note 127 is above Nyquist at 8 kHz, so it is compared at 44.1 kHz only, for each model.
        val cases = result.errorCases.map { Triple(it.model, it.sampleRate, it.note) }
        val expected = EnvelopeModel.values().flatMap { listOf(Triple(it, 8_000, 0.0), Triple(it, 44_100, 0.0), Triple(it, 44_100, 127.0)) }
        assertEquals(expected, cases)
        assertTrue(result.worstError.maxAbsError <= 1e-6)
        assertEquals(listOf("stroke", "hit", "knock", "hug", "longest"), result.firstBlocks.map { it.icon })
        assertEquals(441, result.firstBlockSamples)
        assertEquals(0.0, result.allocatedBytesPerBlockExact, 0.0)
        assertEquals(0.0, result.allocatedBytesPerBlockFast, 0.0)
        assertEquals(0.0, result.sensors.decode.maxOf { it.bytesAllocatedPerFrame }, 0.0)
        assertEquals(listOf("csv", "framed", "lucidgloves"), result.sensors.decode.map { it.name })
        assertEquals(listOf("grainDecider", "handshakePressure"), result.sensors.models.map { it.name })
        assertEquals(2_000, result.sensors.latency.samples)
        assertEquals(8, steps.size)
        assertEquals("fake-port sample to grain command", steps.last())
    }

    @Test
    fun longest_isTheSharedLongestTestIcon() {
        assertEquals(TestIcons.LONGEST, Benchmark.LONGEST)
    }

    @Test
    fun plainSineLoop_writesSinOfTheSampleIndexForEverySample() {
        val loop = PlainSineLoop(440.0, 8_000, 2_500)
        val block = FloatArray(1000)
        val seen = ArrayList<Float>()
        while (true) {
            val count = loop.read(block)
            if (count < 0) break
            for (j in 0 until count) seen += block[j]
        }
        assertEquals(2_500, seen.size)
        for (i in listOf(0, 1, 999, 1000, 2_499)) assertEquals("sample $i", sin(2 * PI * 440.0 * i / 8_000).toFloat(), seen[i], 0f)
    }

    @Test
    fun singlePhasorLoop_tracksTheSineWithinOneFloatStep() {
        val loop = SinglePhasorLoop(440.0, 8_000, 8_000)
        val block = FloatArray(3_000)
        var index = 0
        while (true) {
            val count = loop.read(block)
            if (count < 0) break
            for (j in 0 until count) assertEquals("sample ${index + j}", sin(2 * PI * 440.0 * (index + j) / 8_000), block[j].toDouble(), 1e-7)
            index += count
        }
        assertEquals(8_000, index)
    }

    @Test
    fun spread_ofValues_isMinMedianMaxAndCount() {
        assertEquals(Spread(1.0, 2.5, 4.0, 4), Spread.of(listOf(4.0, 1.0, 3.0, 2.0)))
    }

    @Test
    fun median_oddAndEvenCounts() {
        assertEquals(2.0, median(listOf(3.0, 1.0, 2.0)), 0.0)
        assertEquals(2.5, median(listOf(4.0, 1.0, 2.0, 3.0)), 0.0)
    }

    @Test
    fun targets_judgeTheWorstCaseOfEachFigure() {
        val targets = SAMPLE_RESULT.targets.associateBy { it.name }
        assertEquals(1100.0, targets.getValue("fast").measured, 1e-9) // the slower workload
        assertEquals(true, targets.getValue("fast").met)
        assertEquals(0.85, targets.getValue("exactVsSine").measured, 1e-9) // the lower median ratio
        assertEquals(false, targets.getValue("exactVsSine").met)
        assertEquals(150.0, targets.getValue("firstBlock").measured, 0.0)
        assertEquals(false, targets.getValue("firstBlock").met)
        assertEquals(true, targets.getValue("allocation").met)
    }

    @Test
    fun table_listsEveryFigureAndMarksMissedTargets() {
        val table = BenchReport.table(SAMPLE_RESULT)
        val lines = table.lines()
        assertEquals("hapticon bench: paper model, 44100 Hz, reads into a reused 4096-sample block", lines[0])
        assertTrue(table, "  longest, 1323000 samples" in lines)
        assertTrue(table, "    sin loop                40 / 50 / 55" in lines)
        assertTrue(table, "    exact                   38 / 45 / 50   ratio to sin loop 0.80× / 0.90× / 1.05×" in lines)
        assertTrue(table, "    fast              1000 / 1100 / 1200   ratio to phasor   2.40× / 2.75× / 3.00×" in lines)
        assertTrue(table, "  longest       150.0     120.0" in lines)
        assertTrue(table, "  exactVsSine      >= 0.9x plain sin    measured      0.850 x (median)   NOT MET" in lines)
        assertTrue(table, "  fast             >= 1000 M samples/s  measured       1100 M samples/s  met" in lines)
        assertTrue(table, "FAST max |error| vs EXACT: 5.96e-08 over 2 full streams (rates 8000, 44100 Hz; notes 0, 127; both models)" in lines)
        assertTrue(table, "FAST max |error| vs EXACT in double precision: 1.14e-11 over the same streams, read as doubles before narrowing" in lines)
        assertEquals("total 12.5 s", lines.last())
    }

    @Test
    fun table_listsSensorFiguresAndTheirTargets() {
        val table = BenchReport.table(SAMPLE_RESULT)
        val lines = table.lines()
        val expected = listOf(
            "sensor decoding on one core: synthetic streams fed in 4096-byte reads, median of the runs",
            "  protocol               MB      MB/s  M frames/s  bytes/frame",
            "  csv                  16.8     120.0       10.00            0",
            "  framed               16.8      45.5        2.00            0",
            "  lucidgloves          16.8     300.0        4.00        0.250",
            "sensor models, ns per sample (median / best) and bytes allocated per sample",
            "  grainDecider           8.5 /    8.0            0",
            "  handshakePressure     70.0 /   66.0          n/a",
            "fake-port FSR sample to grain command, µs: p50 3.5, p99 1200.0, max 5000.0 (2200 grains from 100000 samples at 1 kHz)",
        )
        val start = lines.indexOf(expected[0])
        assertEquals(expected, lines.subList(start, start + expected.size))
        assertTrue(table, "  decodeCsv        >= 50 MB/s           measured        120 MB/s         met" in lines)
        assertTrue(table, "  decodeFramed     >= 50 MB/s           measured       45.5 MB/s         NOT MET" in lines)
        assertTrue(table, "  decodeAllocation 0 bytes/frame        measured      0.250 bytes/frame  NOT MET" in lines)
        assertTrue(table, "  grainDecision    <= 1000 ns/sample    measured       8.50 ns/sample    met" in lines)
        assertTrue(table, "  grainLatencyP99  <= 1000 µs           measured       1200 µs           NOT MET" in lines)
        assertTrue(table, "  grainLatencyMax  <= 1000 µs (quiet)   measured       5000 µs           NOT MET" in lines)
        assertTrue(
            table,
            "  baseline, same run (the engine's arithmetic re-created, no GrainEngine): p50 3.1, p99 12.4, max 3956.0 µs (2200 grains);" +
                " without run-queue wait 120.5 µs; 0 bytes per sample" in lines,
        )
    }

    @Test
    fun json_isOneObjectWithEveryFigure() {
        val json = Json.decode(BenchReport.json(SAMPLE_RESULT)) as JsonObject
        assertEquals(JsonPrimitive(44_100), json["sampleRate"])
        val longest = (json["throughput"] as JsonArray)[0] as JsonObject
        assertEquals(JsonPrimitive(1_100_000_000), (longest["fast"] as JsonObject)["median"])
        assertEquals(JsonPrimitive(2.75), (longest["fastVsPhasor"] as JsonObject)["median"])
        assertEquals(JsonPrimitive(0.8), (longest["exactVsSine"] as JsonObject)["min"])
        assertEquals(JsonPrimitive(5.960464477539063E-8), json["fastMaxAbsError"])
        assertEquals(JsonPrimitive(1.14e-11), json["fastMaxAbsErrorDouble"])
        assertEquals(2, (json["fastErrorCases"] as JsonArray).size)
        val firstBlock = (json["targets"] as JsonObject)["firstBlock"] as JsonObject
        assertEquals(JsonPrimitive(false), firstBlock["met"])
        assertEquals(JsonPrimitive(150), firstBlock["measured"])
        val sensors = json["sensors"] as JsonObject
        val framed = (sensors["decode"] as JsonArray)[1] as JsonObject
        assertEquals(JsonPrimitive("framed"), framed["protocol"])
        assertEquals(JsonPrimitive(45.5), framed["megabytesPerSecond"])
        assertEquals(JsonPrimitive(2_000_000), framed["framesPerSecond"])
        val handshake = (sensors["models"] as JsonArray)[1] as JsonObject
        assertEquals(JsonPrimitive(70), handshake["medianNanosPerSample"])
        assertEquals(null, handshake["allocatedBytesPerSample"]) // -1: not counted, so left out
        val latency = sensors["grainLatency"] as JsonObject
        assertEquals(JsonPrimitive(1200), latency["p99Micros"])
        assertEquals(JsonPrimitive(2200), latency["grains"])
        // Every slow grain by cause, beside the safepoint and steal figures the one-line table prints.
        assertEquals(JsonPrimitive(7), latency["over1ms"])
        assertEquals(JsonPrimitive(1), latency["over1msBySafepoint"])
        assertEquals(JsonPrimitive(1), latency["over1msByWaitAndSafepoint"])
        assertEquals(JsonPrimitive(0), latency["over1msBySteal"])
        assertEquals(JsonPrimitive(2), latency["over1msUnexplained"])
        assertEquals(JsonPrimitive(12), latency["safepoints"])
        assertEquals(JsonPrimitive(812.3), latency["longestSafepointMicros"])
        assertEquals(JsonPrimitive("G1CollectForAllocation"), latency["longestSafepoint"])
        assertEquals(JsonPrimitive(0), latency["safepointMicrosAtMax"])
        assertEquals(null, latency["stealTicksAtMax"]) // -1: the worst grain was not slow by steal, so left out
        assertEquals(JsonPrimitive(1.23), latency["stealPercent"])
        val baseline = sensors["grainLatencyBaseline"] as JsonObject
        assertEquals(JsonPrimitive(3956), baseline["maxMicros"])
        assertEquals(JsonPrimitive(12.4), baseline["p99Micros"])
        val p99 = (json["targets"] as JsonObject)["grainLatencyP99"] as JsonObject
        assertEquals(JsonPrimitive(false), p99["met"])
    }

    @Test
    fun json_sameBytesAsTheTreeBuiltByHandBefore() {
        // recorded/bench-report.json: this SAMPLE_RESULT as BenchReport wrote it when it built a JsonObject tree by hand.
        val recorded = BenchmarkTest::class.java.getResource("/recorded/bench-report.json")!!.readText()
        assertEquals(recorded, BenchReport.json(SAMPLE_RESULT))
    }

    @Test
    fun benchCommand_quickJson_printsOneParsableObjectAndProgressOnStderr() {
        val result = cli("bench", "--json", "--quick")
        assertEquals(result.toString(), 0, result.exitCode)
        val json = Json.decode(result.stdout) as JsonObject
        val allocation = json["allocatedBytesPerBlock"] as JsonObject
        assertEquals(JsonPrimitive(0), allocation["exact"])
        assertEquals(JsonPrimitive(0), allocation["fast"])
        val targets = setOf("fast", "exactVsSine", "firstBlock", "allocation", "decodeCsv", "decodeFramed", "decodeAllocation", "grainDecision", "grainLatencyP99", "grainLatencyMax", "grainLatencyMaxFreeCore")
        assertEquals(targets, (json["targets"] as JsonObject).keys)
        val latency = (json["sensors"] as JsonObject)["grainLatency"] as JsonObject
        assertEquals(JsonPrimitive(2_000), latency["samples"])
        assertEquals(JsonPrimitive(2_000), ((json["sensors"] as JsonObject)["grainLatencyBaseline"] as JsonObject)["samples"])
        assertTrue(result.stderr, result.stderr.startsWith("bench: throughput over longest"))
    }

    @Test
    fun benchCommand_grainQuick_printsOneLinePerRunWithTheLoadBesideIt() {
        val result = cli("bench", "--grain", "--quick", "--runs", "2", "--spin-us", "20")
        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.trimEnd().lines()
        assertEquals(result.stdout, "grain latency through GrainEngine, µs; samples back to back, reader spin 20 µs after each sample", lines[0])
        assertEquals(result.stdout, 3, lines.size)
        // 2,000 samples after 500 of warm-up (QUICK): the press cycle repeats, so 46 grains as in GrainLatencyTest.
        for ((k, line) in lines.drop(1).withIndex()) {
            assertTrue(line, line.startsWith("run ${k + 1} (load "))
            assertTrue(line, "(46 grains)" in line)
            assertTrue(line, "reader CPU " in line)
        }
    }

    @Test
    fun benchCommand_grainOptionWithoutGrain_exitsTwoNamingIt() {
        val result = cli("bench", "--spin-us", "50")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --spin-us goes with --grain"), result.stderrLines)
    }

    @Test
    fun benchCommand_grainRunsOutOfRange_exitsTwo() {
        val result = cli("bench", "--grain", "--runs", "0")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --runs must be in 1..100, got 0"), result.stderrLines)
    }

    @Test
    fun benchCommand_grainBadCpuLatencyOrNice_exitsTwoWithOneLine() {
        for ((args, said) in listOf(
            listOf("--reader-nice", "25") to "hapticon: --reader-nice must be in -20..19, got 25",
            listOf("--reader-nice", "-21") to "hapticon: --reader-nice must be in -20..19, got -21",
            listOf("--cpu-latency-us", "-1") to "hapticon: --cpu-latency-us must be in 0..100000, got -1",
            listOf("--cpu-latency-us", "abc") to "hapticon: --cpu-latency-us must be a whole number, got 'abc'",
        )) {
            val result = cli("bench", "--grain", *args.toTypedArray())
            assertEquals(result.toString(), 2, result.exitCode)
            assertEquals(listOf(said), result.stderrLines)
        }
        val alone = cli("bench", "--cpu-latency-us", "0")
        assertEquals(listOf("hapticon: --cpu-latency-us goes with --grain"), alone.stderrLines)
    }

    @Test
    fun benchCommand_grainCpuLatencyAndReaderNice_sayWhatWasGrantedOnEachRunsLine() {
        // Nice 5 lowers the reader's priority, which Linux lets any user do to their own thread: always granted.
        // The CPU latency request needs root (the node is 0600): granted or refused, the runs go on.
        val root = java.nio.file.Files.isWritable(CpuLatencyRequest.DEVICE)
        val result = cli("bench", "--grain", "--quick", "--runs", "1", "--cpu-latency-us", "100", "--reader-nice", "5")
        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.trimEnd().lines()
        assertEquals(result.stdout, 3, lines.size)
        if (root) {
            assertTrue(lines[1], lines[1].startsWith("cpu latency 100 µs granted (limit in force "))
            assertTrue(lines[2], "; cpu latency 100 µs held; reader nice 5 granted): p50 " in lines[2])
        } else {
            assertTrue(lines[1], lines[1].startsWith("cpu latency 100 µs refused (") && lines[1].endsWith("; runs go on without it"))
            assertTrue(lines[2], "; cpu latency refused; reader nice 5 granted): p50 " in lines[2])
        }
        assertTrue(lines[2], "(46 grains)" in lines[2] && " unexplained); " in lines[2])
    }

    @Test
    fun benchCommand_unknownOption_exitsTwo() {
        val result = cli("bench", "--fast")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: unknown option --fast for bench"), result.stderrLines)
    }

    private companion object {
        private fun spread(min: Double, median: Double, max: Double) = Spread(min, median, max, 7)

        val SAMPLE_RESULT = BenchResult(
            sampleRate = 44_100,
            blockSamples = 4096,
            throughputs = listOf(
                Throughput(
                    "longest", 1_323_000, sineLoop = spread(40e6, 50e6, 55e6), phasor = spread(380e6, 400e6, 420e6),
                    exact = spread(38e6, 45e6, 50e6), fast = spread(1000e6, 1100e6, 1200e6),
                    exactVsSine = spread(0.8, 0.9, 1.05), fastVsPhasor = spread(2.4, 2.75, 3.0),
                ),
                Throughput(
                    "presets", 701_190, sineLoop = spread(40e6, 50e6, 55e6), phasor = spread(380e6, 400e6, 420e6),
                    exact = spread(38e6, 42e6, 50e6), fast = spread(1100e6, 1200e6, 1300e6),
                    exactVsSine = spread(0.8, 0.85, 1.0), fastVsPhasor = spread(2.5, 2.9, 3.1),
                ),
            ),
            errorCases = listOf(
                ErrorCase(EnvelopeModel.PAPER, 8_000, 0.0, 240_000, 0.0, 2.5e-13),
                ErrorCase(EnvelopeModel.PROCESSING, 44_100, 127.0, 1_323_000, 5.960464477539063E-8, 1.14e-11),
            ),
            firstBlockSamples = 441,
            firstBlockRuns = 2000,
            firstBlocks = listOf(FirstBlock("stroke", 15.0, 4.0), FirstBlock("longest", 150.0, 120.0)),
            allocatedBytesPerBlockExact = 0.0,
            allocatedBytesPerBlockFast = 0.0,
            sensors = SensorFigures(
                decode = listOf(
                    ProtocolBenchmark.Result("csv", 16_777_224, 1_400_000, 120.0, 10e6, 0.0),
                    ProtocolBenchmark.Result("framed", 16_777_222, 760_000, 45.5, 2e6, 0.0),
                    ProtocolBenchmark.Result("lucidgloves", 16_777_219, 210_000, 300.0, 4e6, 0.25),
                ),
                models = listOf(
                    SensorBenchmarkResult("grainDecider", 8.5, 8.0, 0.0, 65_536, 900),
                    SensorBenchmarkResult("handshakePressure", 70.0, 66.0, -1.0, 65_536, 200),
                ),
                latency = GrainLatencyResult(
                    samples = 100_000, grains = 2_200, p50Micros = 3.5, p99Micros = 1200.0, maxMicros = 5000.0,
                    over1ms = 7, over1msByRunQueue = 3, over1msBySafepoint = 1, over1msByWaitAndSafepoint = 1, over1msBySteal = 0,
                    over1msUnexplained = 2, safepoints = 12, longestSafepointMicros = 812.34, longestSafepoint = "G1CollectForAllocation",
                    safepointMicrosAtMax = 0.0, stealTicksAtMax = -1, stealShare = 0.0123,
                ),
                latencyBaseline = GrainLatencyResult(
                    samples = 100_000, grains = 2_200, p50Micros = 3.1, p99Micros = 12.4, maxMicros = 3956.0,
                    handlerBytesPerSample = 0.0, maxWithoutRunQueueMicros = 120.5,
                ),
            ),
            elapsedSeconds = 12.5,
        )
    }
}
