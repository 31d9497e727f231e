package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class FramedEncoderTest {
    private val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)

    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    @Test
    fun requestInfo_sequenceZero_handDerivedBytes() {
        // raw 01 11 00 00, CRC-16/CCITT-FALSE 0x8627 high byte first; COBS 03 01 11 | 01 | 03 86 27; delimiter.
        val n = FramedEncoder().requestInfo(buffer)
        assertArrayEquals(bytes(0x03, 0x01, 0x11, 0x01, 0x03, 0x86, 0x27, 0x00), buffer.copyOf(n))
    }

    @Test
    fun encoder_successiveFrames_sequenceAdvancesAndWraps() {
        val encoder = FramedEncoder(65_534)
        assertEquals(-1, encoder.lastSequence)
        encoder.requestInfo(buffer)
        assertEquals(65_534, encoder.lastSequence)
        encoder.setSampleRate(100, buffer)
        assertEquals(65_535, encoder.lastSequence)
        val n = encoder.setOutputs(0, intArrayOf(1), buffer)
        assertEquals(0, encoder.lastSequence)
        assertEquals(1, encoder.nextSequence)
        // version 1, SET_OUTPUTS, sequence 0 (LE), output 0, value 1 (LE), then the CRC.
        assertArrayEquals(bytes(0x01, 0x10, 0x00, 0x00, 0x00, 0x01, 0x00), Cobs.decode(buffer.copyOf(n - 1))!!.copyOf(7))
    }

    @Test
    fun setOutputs_valueOutsideServoRange_refusedWithoutUsingASequenceNumber() {
        val encoder = FramedEncoder(7)
        for (bad in listOf(-1, 1001)) {
            val e = assertThrows(SafetyLimitException::class.java) { encoder.setOutputs(0, intArrayOf(0, bad), buffer) }
            assertEquals("servo", e.limit)
        }
        assertEquals(7, encoder.nextSequence)
        assertArrayEquals(ByteArray(buffer.size), buffer)
    }

    @Test
    fun setOutputs_outputsOutOfRangeOrTooMany_throwIllegalArgument() {
        val encoder = FramedEncoder()
        assertThrows(IllegalArgumentException::class.java) { encoder.setOutputs(0, IntArray(0), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.setOutputs(0, IntArray(FramedProtocol.MAX_OUTPUTS + 1), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.setOutputs(15, IntArray(2), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.setOutputs(-1, IntArray(1), buffer) }
        assertEquals(0, encoder.nextSequence)
        encoder.setOutputs(0, IntArray(FramedProtocol.MAX_OUTPUTS) { 1000 }, buffer)
        assertEquals(1, encoder.nextSequence)
    }

    @Test
    fun sample_invalidArguments_throw() {
        val encoder = FramedEncoder()
        assertThrows(IllegalArgumentException::class.java) { encoder.sample(0, intArrayOf(65_536), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.sample(0, intArrayOf(-1), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.sample(0, IntArray(0), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.sample(0, IntArray(FramedProtocol.MAX_CHANNELS + 1), buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.sample(0, IntArray(2), buffer, count = 3) }
        assertThrows(IllegalArgumentException::class.java) { encoder.setSampleRate(0, buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.ack(65_536, AckStatus.OK, 0, buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.ack(0, AckStatus.OK, 256, buffer) }
        assertThrows(IllegalArgumentException::class.java) { encoder.ack(0, AckStatus.UNKNOWN, 0, buffer) }
        assertThrows(IllegalArgumentException::class.java) { FramedEncoder(65_536) }
        assertEquals(0, encoder.nextSequence)
    }

    @Test
    fun anyFrame_destinationShorterThanMaxEncodedLength_throws() {
        assertThrows(IndexOutOfBoundsException::class.java) { FramedEncoder().requestInfo(ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH - 1)) }
        assertThrows(IndexOutOfBoundsException::class.java) { FramedEncoder().requestInfo(buffer, 1) }
    }

    @Test
    fun encode_largestFrames_fitAndRoundTrip() {
        val encoder = FramedEncoder()
        val info = DeviceInfo(255, 255, 255, 16, Int.MAX_VALUE, FramedProtocol.MAX_OUTPUTS, List(FramedProtocol.MAX_CHANNELS) { ChannelUnit.MILLINEWTON },
            "~".repeat(FramedProtocol.MAX_NAME_LENGTH))
        val infoWire = buffer.copyOf(encoder.deviceInfo(info, buffer))
        val values = IntArray(FramedProtocol.MAX_CHANNELS) { 65_535 - it }
        val sampleWire = buffer.copyOf(encoder.sample(0xFFFF_FFFFL, values, buffer))
        assertTrue(infoWire.size <= FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val got = ArrayList<String>()
        FramedDecoder(object : FramedDecoder.Listener {
            override fun onSample(frame: SampleFrame) {
                got += frame.values.copyOf(frame.channelCount).joinToString()
            }

            override fun onDeviceInfo(info: DeviceInfo) {
                got += info.toString()
            }
        }).feed(infoWire + sampleWire)
        assertEquals(listOf(info.toString(), values.joinToString()), got)
    }

    @Test
    fun deviceInfo_invalidValues_throw() {
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 12, 1000, 0, emptyList(), "") }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 12, 1000, 0, listOf(ChannelUnit.RAW), "é") }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 12, 1000, 0, listOf(ChannelUnit.RAW), "x".repeat(33)) }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 256, 12, 1000, 0, listOf(ChannelUnit.RAW), "") }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 0, 1000, 0, listOf(ChannelUnit.RAW), "") }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 12, 0, 0, listOf(ChannelUnit.RAW), "") }
        assertThrows(IllegalArgumentException::class.java) { DeviceInfo(0, 0, 0, 12, 1000, 17, listOf(ChannelUnit.RAW), "") }
    }
}
