package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertEquals
import org.junit.Assume.assumeTrue
import org.junit.Test

/**
 * Decodes every recorded stream and checks exactly what comes out; docs/protocols.md explains each
 * number. Every stream is also fed in several splits, which must give the same frames and counts.
 */
class RecordedStreamsTest {
    /** What generate.py puts in sample frame k. */
    private fun framedSample(k: Int): String =
        "sample ${k + 1} t=${1_000_000 + 1000 * k} " + (0 until 5).joinToString(",") { c -> ((k * 97 + c * 331 + k * c * 13) % 4096).toString() }

    private fun decode(name: String, make: (Recorder) -> StreamDecoder): Pair<Recorder, StreamStats> {
        val bytes = RecordedStreams.bytes(name)
        val recorder = Recorder()
        val decoder = make(recorder)
        decoder.feed(bytes)
        decoder.finish()
        for (chunk in listOf(1, 3, 64)) {
            val split = Recorder()
            val splitDecoder = make(split)
            splitDecoder.feedInChunks(bytes, chunk)
            splitDecoder.finish()
            assertEquals("$name in pieces of $chunk", recorder.events, split.events)
            assertEquals("$name in pieces of $chunk", decoder.stats.toString(), splitDecoder.stats.toString())
        }
        assertEquals(bytes.size.toLong(), decoder.stats.bytes)
        return recorder to decoder.stats
    }

    private fun framed(name: String) = decode(name) { FramedDecoder(it) }

    @Test
    fun decode_framedClean_everyFrameNoLoss() {
        val (r, stats) = framed(RecordedStreams.FRAMED_CLEAN)
        assertEquals(listOf("info hapticon-ref") + (0 until 20).map(::framedSample) + "ack 7 OK 0", r.events)
        assertEquals("StreamStats(bytes=488, frames=22, badFrames=0, droppedBytes=1, ignoredLines=0, sequenceGaps=0, lostFrames=0)", stats.toString())
    }

    @Test
    fun decode_framedSplitReads_everyFrame() {
        val (r, stats) = framed(RecordedStreams.FRAMED_SPLIT_READS)
        assertEquals(listOf("info hapticon-ref") + (0 until 30).map(::framedSample), r.events)
        assertEquals(0L, stats.droppedBytes)
    }

    @Test
    fun decode_framedGarbage_costsOneFrameWithoutZerosAndNoneWithZeros() {
        val (r, stats) = framed(RecordedStreams.FRAMED_GARBAGE)
        assertEquals(listOf("info hapticon-ref") + (0 until 15).filter { it != 5 }.map(::framedSample), r.events)
        // "GARBAGE!" (8) swallows sample 5 (22 bytes); "ab 00" and "cd ef 00" are two broken frames.
        assertEquals("StreamStats(bytes=378, frames=15, badFrames=3, droppedBytes=35, ignoredLines=0, sequenceGaps=1, lostFrames=1, MALFORMED=3)",
            stats.toString())
    }

    @Test
    fun decode_framedCrcError_dropsThatFrame() {
        val (r, stats) = framed(RecordedStreams.FRAMED_CRC_ERROR)
        assertEquals(listOf("info hapticon-ref") + (0 until 10).filter { it != 4 }.map(::framedSample), r.events)
        assertEquals("StreamStats(bytes=255, frames=10, badFrames=1, droppedBytes=22, ignoredLines=0, sequenceGaps=1, lostFrames=1, CRC=1)",
            stats.toString())
    }

    @Test
    fun decode_framedSequenceGap_countsThreeLost() {
        val (r, stats) = framed(RecordedStreams.FRAMED_SEQUENCE_GAP)
        assertEquals(listOf("info hapticon-ref") + (0 until 10).map(::framedSample) + (13 until 20).map(::framedSample), r.events)
        assertEquals("StreamStats(bytes=409, frames=18, badFrames=0, droppedBytes=0, ignoredLines=0, sequenceGaps=1, lostFrames=3)", stats.toString())
    }

    @Test
    fun decode_framedUnplug_keepsEveryWholeFrameAndCountsTheTruncatedOne() {
        val (r, stats) = framed(RecordedStreams.FRAMED_UNPLUG)
        assertEquals(listOf("info hapticon-ref") + (0 until 10).map(::framedSample), r.events)
        assertEquals("StreamStats(bytes=264, frames=11, badFrames=1, droppedBytes=9, ignoredLines=0, sequenceGaps=0, lostFrames=0, TRUNCATED=1)",
            stats.toString())
    }

    @Test
    fun decode_csvBannerHeader_twentySamplesNamedByTheHeader() {
        val (r, stats) = decode(RecordedStreams.CSV_BANNER_HEADER) { CsvDecoder(it) }
        assertEquals((0 until 20).map { k -> (0 until 4).map { c -> ((k * 37 + c * 211) % 1024).toDouble() } }, r.samples)
        assertEquals("StreamStats(bytes=376, frames=20, badFrames=0, droppedBytes=63, ignoredLines=3, sequenceGaps=0, lostFrames=0)", stats.toString())
        // finish() forgets the names, so look before it.
        val decoder = CsvDecoder(Recorder())
        decoder.feed(RecordedStreams.bytes(RecordedStreams.CSV_BANNER_HEADER))
        assertEquals(listOf("fsr0", "fsr1", "fsr2", "fsr3"), decoder.channelNames)
    }

    @Test
    fun decode_csvGarbageCrlf_everyGoodLineAndEveryBadOneCounted() {
        val (r, stats) = decode(RecordedStreams.CSV_GARBAGE_CRLF) { CsvDecoder(it) }
        val expected = listOf(listOf(512.0, 498.0, 1023.0), listOf(511.0, 497.0, 1022.0), listOf(507.5, 494.25, 1019.0)) +
            (0 until 10).map { k -> listOf(500.0 + k, 480.0 + k, 1000.0 + k) }
        assertEquals(expected, r.samples)
        assertEquals("StreamStats(bytes=1299, frames=13, badFrames=6, droppedBytes=1109, ignoredLines=2, sequenceGaps=0, lostFrames=0, " +
            "OVERLONG=1, FIELD_COUNT=2, SYNTAX=2, TRUNCATED=1)", stats.toString())
    }

    @Test
    fun decode_lucidgloves_tenFramesTwoBadLinesAndABanner() {
        val (r, stats) = decode(RecordedStreams.LUCIDGLOVES) { LucidGloveDecoder(it) }
        val lines = String(RecordedStreams.bytes(RecordedStreams.LUCIDGLOVES), Charsets.US_ASCII).lines().map { it.trimEnd('\r') }
        // Good lines come back exactly as sent (the fixture writes keys in the firmware's order).
        assertEquals(lines.filterIndexed { i, _ -> i in 1..6 || i in 9..12 }, r.events)
        assertEquals("A906B1483C2060D2637E3214P741(AAB)1234", r.events[6])
        assertEquals("StreamStats(bytes=491, frames=10, badFrames=2, droppedBytes=50, ignoredLines=1, sequenceGaps=0, lostFrames=0, " +
            "FIELD_COUNT=1, SYNTAX=1)", stats.toString())
    }

    @Test
    fun splitReadSizes_fixture_isTheReadPlan() {
        assertEquals(listOf(1, 2, 3, 5, 8, 13, 21, 34, 55, 64, 7, 1, 1, 30), RecordedStreams.splitReadSizes().toList())
    }

    @Test
    fun generator_check_checkedInFilesAreUpToDate() {
        assumeTrue("python3 is not installed", ModuleFiles.onPath("python3"))
        val script = ModuleFiles.testFixtures("src/main/resources/streams/generate.py")
        val (exit, output) = ModuleFiles.run("python3", script.path, "--check")
        assertEquals(output, 0, exit)
    }
}
