package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.Recorder
import org.hapticon.sensor.protocol.feedInChunks
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Test

class FramedDecoderTest {
    private val recorder = Recorder()
    private val decoder = FramedDecoder(recorder)
    private val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)

    private val info = DeviceInfo(1, 2, 3, 12, 1000, 5, listOf(ChannelUnit.RAW, ChannelUnit.GRAM, ChannelUnit.CENTIDEGREE), "glove")

    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    private fun FramedEncoder.wire(encode: FramedEncoder.(ByteArray) -> Int): ByteArray = buffer.copyOf(encode(buffer))

    /** A frame built by hand: header, payload, CRC high byte first, COBS, delimiter. */
    private fun handFrame(version: Int, type: Int, sequence: Int, payload: ByteArray): ByteArray {
        val raw = bytes(version, type, sequence and 0xFF, sequence ushr 8) + payload
        val crc = Crc16.compute(raw)
        val framed = raw + bytes(crc ushr 8, crc and 0xFF)
        val out = ByteArray(Cobs.maxEncodedLength(framed.size))
        return out.copyOf(Cobs.encode(framed, 0, framed.size, out, 0)) + bytes(0)
    }

    @Test
    fun feed_handDerivedAckFrame_decodes() {
        // ack of command 10, OK, from device sequence 42: raw 01 03 2a 00 0a 00 00 00 75 ce.
        decoder.feed(bytes(0x04, 0x01, 0x03, 0x2a, 0x02, 0x0a, 0x01, 0x01, 0x03, 0x75, 0xce, 0x00))
        assertEquals(listOf("ack 10 OK 0"), recorder.events)
        assertEquals(1L, decoder.stats.frames)
        assertEquals(12L, decoder.stats.bytes)
        assertEquals(0L, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_encodedInfoSamplesAndAcks_roundTrip() {
        val encoder = FramedEncoder()
        val stream = encoder.wire { deviceInfo(info, it) } +
            encoder.wire { sample(5_000_000, intArrayOf(0, 65535, 256), it) } +
            encoder.wire { ack(9, AckStatus.BAD_OUTPUT, 7, it) } +
            encoder.wire { sample(5_001_000, intArrayOf(1, 2, 3), it) }
        decoder.feed(stream)
        assertEquals(listOf("info glove", "sample 1 t=5000000 0,65535,256", "ack 9 BAD_OUTPUT 7", "sample 3 t=5001000 1,2,3"), recorder.events)
        assertEquals(info, recorder.infos.single())
        assertEquals(info, decoder.deviceInfo)
        assertEquals("1.2.3", decoder.deviceInfo!!.firmwareVersion)
        assertEquals("StreamStats(bytes=${stream.size}, frames=4, badFrames=0, droppedBytes=0, ignoredLines=0, sequenceGaps=0, lostFrames=0)",
            decoder.stats.toString())
    }

    @Test
    fun feed_oneByteAtATime_sameAsWhole() {
        val encoder = FramedEncoder(65_530)
        var stream = encoder.wire { deviceInfo(info, it) } + bytes(0x11, 0x22, 0x00)
        for (k in 0 until 12) stream += encoder.wire { sample(k * 1000L, intArrayOf(k, 0, k * 300), it) }
        stream += stream.copyOfRange(0, 7)
        val whole = Recorder()
        FramedDecoder(whole).apply { feed(stream); finish() }
        for (chunk in listOf(1, 2, 3, 5, 63)) {
            val split = Recorder()
            val splitDecoder = FramedDecoder(split)
            splitDecoder.feedInChunks(stream, chunk)
            splitDecoder.finish()
            assertEquals(whole.events, split.events)
            assertEquals("StreamStats(bytes=${stream.size}, frames=13, badFrames=2, droppedBytes=10, ignoredLines=0, sequenceGaps=0, " +
                "lostFrames=0, MALFORMED=1, TRUNCATED=1)", splitDecoder.stats.toString())
        }
        assertEquals(13, whole.events.size)
    }

    @Test
    fun feed_crcError_dropsTheFrameAndCountsTheGap() {
        val encoder = FramedEncoder()
        val first = encoder.wire { sample(0, intArrayOf(1), it) }
        val damaged = encoder.wire { sample(1000, intArrayOf(2), it) }
        damaged[6] = (damaged[6].toInt() xor 0x40).toByte() // a data byte of the timestamp, not a code byte
        val third = encoder.wire { sample(2000, intArrayOf(3), it) }
        decoder.feed(first + damaged + third)
        assertEquals(listOf("sample 0 t=0 1", "sample 2 t=2000 3"), recorder.events)
        assertEquals(1L, decoder.stats.badFrames(FrameError.CRC))
        assertEquals(damaged.size.toLong(), decoder.stats.droppedBytes)
        assertEquals(1L, decoder.stats.sequenceGaps)
        assertEquals(1L, decoder.stats.lostFrames)
    }

    @Test
    fun feed_sequenceWrapsAt65535_noGap() {
        val encoder = FramedEncoder(65_534)
        repeat(4) { k -> decoder.feed(encoder.wire { sample(k.toLong(), intArrayOf(k), it) }) }
        assertEquals(listOf("sample 65534 t=0 0", "sample 65535 t=1 1", "sample 0 t=2 2", "sample 1 t=3 3"), recorder.events)
        assertEquals(0L, decoder.stats.sequenceGaps)
    }

    @Test
    fun feed_sequenceJumps_forwardCountsLostFramesBackwardDoesNot() {
        for (sequence in listOf(10, 11, 15, 16, 3, 4)) decoder.feed(FramedEncoder(sequence).wire { sample(0, intArrayOf(0), it) })
        assertEquals(2L, decoder.stats.sequenceGaps)
        assertEquals(3L, decoder.stats.lostFrames)
        assertEquals(6L, decoder.stats.frames)
    }

    @Test
    fun feed_deviceInfo_restartsSequenceAndClock() {
        decoder.feed(FramedEncoder(500).wire { sample(4_000_000_000, intArrayOf(1, 2, 3), it) })
        decoder.feed(FramedEncoder(0).wire { deviceInfo(info, it) }) // the device rebooted
        decoder.feed(FramedEncoder(1).wire { sample(100, intArrayOf(1, 2, 3), it) })
        assertEquals(0L, decoder.stats.sequenceGaps)
        assertEquals("sample 1 t=100 1,2,3", recorder.events.last())
    }

    @Test
    fun feed_timestampWraps_unwrapsTo64Bits() {
        val encoder = FramedEncoder()
        for (t in listOf(0xFFFF_FF00L, 0x1_0000_0100L, 0x1_FFFF_FFFFL, 0x2_0000_0000L)) decoder.feed(encoder.wire { sample(t, intArrayOf(0), it) })
        assertEquals(listOf("sample 0 t=4294967040 0", "sample 1 t=4294967552 0", "sample 2 t=8589934591 0", "sample 3 t=8589934592 0"),
            recorder.events)
    }

    @Test
    fun feed_channelCountDifferentFromDeviceInfo_isFieldCount() {
        val encoder = FramedEncoder()
        decoder.feed(encoder.wire { deviceInfo(info, it) })
        val wrong = encoder.wire { sample(0, intArrayOf(1, 2), it) }
        decoder.feed(wrong)
        decoder.feed(encoder.wire { sample(0, intArrayOf(1, 2, 3), it) })
        assertEquals(listOf("info glove", "sample 2 t=0 1,2,3"), recorder.events)
        assertEquals(1L, decoder.stats.badFrames(FrameError.FIELD_COUNT))
        assertEquals(wrong.size.toLong(), decoder.stats.droppedBytes)
        assertEquals(0L, decoder.stats.sequenceGaps)
    }

    @Test
    fun feed_badPayloadsWithGoodCrc_countedByKind() {
        val frames = listOf(
            handFrame(2, 0x02, 0, bytes(0, 0, 0, 0, 1, 0)) to FrameError.VERSION,
            handFrame(1, 0x7F, 1, bytes()) to FrameError.UNKNOWN_TYPE,
            handFrame(1, 0x10, 2, bytes(0, 1, 0)) to FrameError.UNKNOWN_TYPE, // a host command
            handFrame(1, 0x02, 3, bytes(0, 0, 0, 0)) to FrameError.FIELD_COUNT, // no channel
            handFrame(1, 0x02, 4, bytes(0, 0, 0, 0, 1)) to FrameError.FIELD_COUNT, // half a value
            handFrame(1, 0x02, 5, ByteArray(4 + 2 * 33)) to FrameError.FIELD_COUNT, // 33 channels
            handFrame(1, 0x03, 6, bytes(1, 0, 0)) to FrameError.FIELD_COUNT, // short ack
            handFrame(1, 0x01, 7, bytes(1, 0, 0, 12, 0xE8, 3, 0, 0, 1, 0, 0, 'x'.code, 0x7F)) to FrameError.SYNTAX, // DEL in the name
            handFrame(1, 0x01, 8, bytes(1, 0, 0, 17, 0xE8, 3, 0, 0, 1, 0, 0)) to FrameError.SYNTAX, // 17-bit ADC
            handFrame(1, 0x01, 9, bytes(1, 0, 0, 12, 0, 0, 0, 0, 1, 0, 0)) to FrameError.SYNTAX, // rate 0
            handFrame(1, 0x01, 10, bytes(1, 0, 0, 12, 0xE8, 3, 0, 0, 0, 0)) to FrameError.FIELD_COUNT, // no channels
            handFrame(1, 0x01, 11, bytes(1, 0, 0, 12, 0xE8, 3, 0, 0, 2, 0, 0)) to FrameError.FIELD_COUNT, // units missing
            handFrame(1, 0x01, 12, bytes(1, 0, 0, 12, 0xE8, 3, 0, 0, 1, 17, 0)) to FrameError.FIELD_COUNT, // 17 outputs
        )
        var dropped = 0L
        for ((frame, error) in frames) {
            val before = decoder.stats.badFrames(error)
            decoder.feed(frame)
            dropped += frame.size
            assertEquals("$error", before + 1, decoder.stats.badFrames(error))
        }
        assertEquals(0L, decoder.stats.frames)
        assertEquals(frames.size.toLong(), decoder.stats.badFrames)
        assertEquals(dropped, decoder.stats.droppedBytes)
        assertEquals(emptyList<String>(), recorder.events)
    }

    @Test
    fun feed_unknownUnitAndStatusCodes_decodeAsUnknown() {
        decoder.feed(handFrame(1, 0x01, 0, bytes(0, 0, 1, 10, 50, 0, 0, 0, 2, 0, 4, 99) + "dev".toByteArray()))
        decoder.feed(handFrame(1, 0x03, 1, bytes(5, 0, 200, 1)))
        assertEquals(listOf(ChannelUnit.CENTIDEGREE, ChannelUnit.UNKNOWN), recorder.infos.single().channelUnits)
        assertEquals(50, recorder.infos.single().sampleRateHz)
        assertEquals("ack 5 UNKNOWN 1", recorder.events.last())
    }

    @Test
    fun feed_brokenCobsAndShortFrames_areMalformed() {
        decoder.feed(bytes(0x05, 0x11, 0x22, 0x00)) // the code promises 4 bytes, 2 come
        decoder.feed(bytes(0x03, 0x01, 0x02, 0x00)) // 2 bytes: shorter than header and CRC
        assertEquals(2L, decoder.stats.badFrames(FrameError.MALFORMED))
        assertEquals(8L, decoder.stats.droppedBytes)
    }

    @Test
    fun feed_overlongFrame_skippedAndDecodingContinues() {
        val tooLong = ByteArray(FramedProtocol.MAX_FRAME_LENGTH + 10) { 0x01 } + bytes(0)
        decoder.feed(tooLong)
        decoder.feed(FramedEncoder().wire { sample(7, intArrayOf(7), it) })
        assertEquals(listOf("sample 0 t=7 7"), recorder.events)
        assertEquals(1L, decoder.stats.badFrames(FrameError.OVERLONG))
        assertEquals(tooLong.size.toLong(), decoder.stats.droppedBytes)
    }

    @Test
    fun feed_endlessGarbageWithoutZeros_boundedAndRecovers() {
        decoder.feed(ByteArray(1_000_000) { ((it % 255) + 1).toByte() })
        decoder.feed(bytes(0))
        decoder.feed(FramedEncoder().wire { sample(7, intArrayOf(7), it) })
        assertEquals(1, recorder.events.size)
        assertEquals(1_000_001L, decoder.stats.droppedBytes)
        assertEquals(1L, decoder.stats.badFrames)
    }

    @Test
    fun feed_idleDelimiters_onlyDroppedBytes() {
        decoder.feed(bytes(0, 0, 0))
        assertEquals("StreamStats(bytes=3, frames=0, badFrames=0, droppedBytes=3, ignoredLines=0, sequenceGaps=0, lostFrames=0)",
            decoder.stats.toString())
    }

    @Test
    fun finish_midFrame_truncatedAndStartsAfresh() {
        val encoder = FramedEncoder()
        decoder.feed(encoder.wire { deviceInfo(info, it) })
        val next = encoder.wire { sample(1, intArrayOf(1, 2, 3), it) }
        decoder.feed(next, 0, 9)
        decoder.finish()
        assertEquals(1L, decoder.stats.badFrames(FrameError.TRUNCATED))
        assertEquals(9L, decoder.stats.droppedBytes)
        assertNull(decoder.deviceInfo)
        // Afresh: no device info, so a 2-channel sample is fine now, and no sequence is expected.
        decoder.feed(FramedEncoder(40).wire { sample(1, intArrayOf(1, 2), it) })
        assertEquals("sample 40 t=1 1,2", recorder.events.last())
        assertEquals(0L, decoder.stats.sequenceGaps)
    }

    @Test
    fun sampleFrame_get_checksTheChannelCount() {
        val frames = ArrayList<String>()
        val d = FramedDecoder(object : FramedDecoder.Listener {
            override fun onSample(frame: SampleFrame) {
                frames += "${frame[0]} ${frame[1]}"
                try {
                    frame[2]
                    frames += "no exception"
                } catch (e: IndexOutOfBoundsException) {
                    frames += "checked"
                }
            }
        })
        d.feed(FramedEncoder().wire { sample(0, intArrayOf(4, 5), it) })
        assertEquals(listOf("4 5", "checked"), frames)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun feed_rangeOutsideArray_throws() {
        decoder.feed(ByteArray(2), 1, 2)
    }
}
