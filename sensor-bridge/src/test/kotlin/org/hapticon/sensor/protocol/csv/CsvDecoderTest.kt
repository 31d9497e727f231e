package org.hapticon.sensor.protocol.csv

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.Recorder
import org.hapticon.sensor.protocol.ascii
import org.hapticon.sensor.protocol.feedInChunks
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class CsvDecoderTest {
    private val recorder = Recorder()

    private fun decode(text: String, decoder: CsvDecoder = CsvDecoder(recorder)): CsvDecoder {
        decoder.feed(ascii(text))
        return decoder
    }

    private fun rows(vararg rows: List<Number>): List<List<Double>> = rows.map { r -> r.map { it.toDouble() } }

    @Test
    fun feed_bannerHeaderAndData_locksOnHeaderAndNamesChannels() {
        val decoder = decode("FSR sketch v1\nthumb,index,middle\n10,20,30\n11,21,31\n")
        assertEquals(rows(listOf(10, 20, 30), listOf(11, 21, 31)), recorder.samples)
        assertEquals(listOf("thumb", "index", "middle"), decoder.channelNames)
        assertEquals(3, decoder.fieldCount)
        assertEquals(2L, decoder.stats.frames)
        assertEquals(2L, decoder.stats.ignoredLines)
        assertEquals(14L + 19, decoder.stats.droppedBytes)
        assertEquals(0L, decoder.stats.badFrames)
    }

    @Test
    fun feed_crlfLineEnds_decodeLikeLf() {
        val decoder = decode("a,b\r\n1,2\r\n3,4\r\n")
        assertEquals(rows(listOf(1, 2), listOf(3, 4)), recorder.samples)
        assertEquals(listOf("a", "b"), decoder.channelNames)
        assertEquals(5L, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_noHeader_firstSampleWaitsForASecondLineWithTheSameCount() {
        val decoder = decode("1,2,3\n")
        assertEquals(0, recorder.samples.size)
        assertEquals(0, decoder.fieldCount)
        decoder.feed(ascii("4,5,6\n"))
        assertEquals(rows(listOf(1, 2, 3), listOf(4, 5, 6)), recorder.samples)
        assertEquals(3, decoder.fieldCount)
        assertEquals(emptyList<String>(), decoder.channelNames)
    }

    @Test
    fun feed_partialFirstLine_isDroppedAsFieldCount() {
        // Attached mid-line: "3,1002" is the tail of a 3-field line.
        val decoder = decode("3,1002\n512,498,1023\n511,497,1022\n")
        assertEquals(rows(listOf(512, 498, 1023), listOf(511, 497, 1022)), recorder.samples)
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(7L, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_wrongFieldCountAfterLock_isFieldCount() {
        val decoder = decode("1,2\n3,4\n5\n6,7,8\n9,10\n")
        assertEquals(rows(listOf(1, 2), listOf(3, 4), listOf(9, 10)), recorder.samples)
        assertEquals(2L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(2L + 6, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_nonNumericOrEmptyFieldAfterLock_isSyntax() {
        val decoder = decode("1,2\n3,4\n5,x\n6,,7\n,8\nnan,1\n9,10\n")
        assertEquals(rows(listOf(1, 2), listOf(3, 4), listOf(9, 10)), recorder.samples)
        assertEquals(4L, decoder.stats.badFrames(FrameError.SYNTAX))
        assertEquals(4L, decoder.stats.badFrames)
        assertEquals(4L + 5 + 3 + 6, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_mixedTextAndNumbersBeforeFirstSample_isIgnoredAsBanner() {
        val decoder = decode("FSR v2, 4 ch\nchannels,4\n1,2,3,4\n5,6,7,8\n")
        assertEquals(2, recorder.samples.size)
        assertEquals(2L, decoder.stats.ignoredLines)
        assertEquals(0L, decoder.stats.badFrames)
    }

    @Test
    fun feed_blankLinesAndTextLinesAfterLock_areIgnored() {
        val decoder = decode("1,2\n3,4\n\n  \nBattery low\n,\n5,6\n")
        assertEquals(3, recorder.samples.size)
        assertEquals(4L, decoder.stats.ignoredLines)
        assertEquals(1L + 3 + 12 + 2, decoder.stats.droppedBytes)
        assertEquals(0L, decoder.stats.badFrames)
    }

    @Test
    fun feed_trailingSeparatorAndSpaces_areTolerated() {
        decode("1, 2 ,3,\n 4\t,5,6 ,\r\n")
        assertEquals(rows(listOf(1, 2, 3), listOf(4, 5, 6)), recorder.samples)
    }

    @Test
    fun feed_decimalsNegativesAndLongIntegers_parseExactly() {
        decode("t,a,b\n12345678901,-1.5,0.1\n12345678902,1e3,.25\n")
        assertEquals(listOf(12_345_678_901.0, -1.5, 0.1), recorder.samples[0])
        assertEquals(listOf(12_345_678_902.0, 1000.0, 0.25), recorder.samples[1])
    }

    @Test
    fun feed_overlongLine_isSkippedUpToItsNewline() {
        val decoder = CsvDecoder(recorder, maxLineLength = 16)
        decode("1,2\n3,4\n1,2,3,4,5,6,7,8,9\n5,6\n1234567890123456\n", decoder)
        assertEquals(rows(listOf(1, 2), listOf(3, 4), listOf(5, 6)), recorder.samples)
        assertEquals(1L, decoder.stats.badFrames(FrameError.OVERLONG))
        // The 16-byte line fits exactly (the limit excludes the newline) and is a wrong field count.
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(18L + 17, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_endlessLineWithoutNewline_boundedAndRecovers() {
        val decoder = CsvDecoder(recorder, maxLineLength = 64)
        decoder.feed(ascii("1,2\n3,4\n"))
        val noise = ByteArray(100_000) { 'x'.code.toByte() }
        decoder.feed(noise)
        decoder.feed(ascii("\n5,6\n"))
        assertEquals(3, recorder.samples.size)
        assertEquals(1L, decoder.stats.badFrames(FrameError.OVERLONG))
        assertEquals(100_001L, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_tooManyFields_isFieldCount() {
        val decoder = CsvDecoder(recorder, fieldCount = 2)
        val wide = (1..CsvDecoder.MAX_FIELDS + 1).joinToString(",") + "\n"
        decode("1,2\n$wide", decoder)
        assertEquals(1, recorder.samples.size)
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
    }

    @Test
    fun feed_maxFields_decodes() {
        val decoder = CsvDecoder(recorder, fieldCount = CsvDecoder.MAX_FIELDS)
        decode((1..CsvDecoder.MAX_FIELDS).joinToString(",") + "\n", decoder)
        assertEquals((1..CsvDecoder.MAX_FIELDS).map { it.toDouble() }, recorder.samples.single())
    }

    @Test
    fun feed_fixedFieldCount_deliversTheFirstLineAtOnce() {
        val decoder = CsvDecoder(recorder, fieldCount = 2)
        decode("hello\n7,8\n1,2,3\n", decoder)
        assertEquals(rows(listOf(7, 8)), recorder.samples)
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(1L, decoder.stats.ignoredLines)
    }

    @Test
    fun feed_fixedFieldCountWithHeader_namesChannels() {
        val decoder = CsvDecoder(recorder, fieldCount = 2)
        decode("x,y\n7,8\n", decoder)
        assertEquals(listOf("x", "y"), decoder.channelNames)
    }

    @Test
    fun feed_otherSeparators_work() {
        val semicolon = CsvDecoder(recorder, fieldCount = 3, separator = ';')
        semicolon.feed(ascii("1;2.5;3\n"))
        // The LucidGloves legacy encoding is '&'-separated numbers.
        val legacy = CsvDecoder(recorder, fieldCount = 4, separator = '&')
        legacy.feed(ascii("512&498&1&0\n"))
        val tabs = CsvDecoder(recorder, fieldCount = 2, separator = '\t')
        tabs.feed(ascii("4\t5\n"))
        assertEquals(rows(listOf(1, 2.5, 3), listOf(512, 498, 1, 0), listOf(4, 5)), recorder.samples)
    }

    @Test
    fun feed_oneByteAtATime_sameSamplesAndStatsAsWhole() {
        val text = ascii("banner\r\n3,1\r\na,b,c\r\n1,2,3\r\n\r\n4,x,6\r\n7,8,9,\r\n" + "9".repeat(2000) + "\r\n10,11,12\r\n13,1")
        val whole = Recorder()
        val wholeDecoder = CsvDecoder(whole)
        wholeDecoder.feed(text)
        wholeDecoder.finish()
        for (chunk in listOf(1, 2, 3, 7, 64)) {
            val split = Recorder()
            val splitDecoder = CsvDecoder(split)
            splitDecoder.feedInChunks(text, chunk)
            splitDecoder.finish()
            assertEquals("chunk $chunk", whole.samples, split.samples)
            assertEquals("chunk $chunk", wholeDecoder.stats.toString(), splitDecoder.stats.toString())
        }
        assertEquals(3, whole.samples.size)
    }

    @Test
    fun finish_unterminatedLine_isTruncated() {
        val decoder = decode("1,2\n3,4\n5,")
        decoder.finish()
        assertEquals(2, recorder.samples.size)
        assertEquals(1L, decoder.stats.badFrames(FrameError.TRUNCATED))
        assertEquals(2L, decoder.stats.droppedBytes)
    }

    @Test
    fun finish_unconfirmedLine_isDeliveredAndLearningRestarts() {
        val decoder = decode("1,2,3\n")
        decoder.finish()
        assertEquals(rows(listOf(1, 2, 3)), recorder.samples)
        assertEquals(0, decoder.fieldCount)
        decoder.feed(ascii("4,5\n6,7\n"))
        assertEquals(rows(listOf(1, 2, 3), listOf(4, 5), listOf(6, 7)), recorder.samples)
        assertEquals(3L, decoder.stats.frames)
        assertEquals(0L, decoder.stats.badFrames)
    }

    @Test
    fun sample_get_checksTheFieldCount() {
        var checked = false
        val decoder = CsvDecoder({ sample ->
            assertEquals(2.0, sample[1], 0.0)
            try {
                sample[2]
            } catch (e: IndexOutOfBoundsException) {
                checked = true
            }
        }, fieldCount = 2)
        decoder.feed(ascii("1,2\n"))
        assertTrue(checked)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun feed_rangeOutsideArray_throws() {
        CsvDecoder(recorder).feed(ByteArray(4), 2, 3)
    }

    @Test
    fun constructor_invalidArguments_throw() {
        for (make in listOf<() -> Unit>(
            { CsvDecoder(recorder, separator = '.') },
            { CsvDecoder(recorder, separator = '-') },
            { CsvDecoder(recorder, separator = '\n') },
            { CsvDecoder(recorder, fieldCount = CsvDecoder.MAX_FIELDS + 1) },
            { CsvDecoder(recorder, maxLineLength = 15) },
        )) {
            try {
                make()
                throw AssertionError("accepted")
            } catch (e: IllegalArgumentException) {
                // expected
            }
        }
    }
}
