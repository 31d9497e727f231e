package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.stream.checkRange
import org.hapticon.sensor.protocol.framed.FramedProtocol.ACK_LENGTH
import org.hapticon.sensor.protocol.framed.FramedProtocol.CRC_LENGTH
import org.hapticon.sensor.protocol.framed.FramedProtocol.DEVICE_INFO_FIXED_LENGTH
import org.hapticon.sensor.protocol.framed.FramedProtocol.HEADER_LENGTH
import org.hapticon.sensor.protocol.framed.FramedProtocol.SAMPLE_TIMESTAMP_LENGTH
import org.hapticon.sensor.protocol.framed.FramedProtocol.TYPE_ACK
import org.hapticon.sensor.protocol.framed.FramedProtocol.TYPE_DEVICE_INFO
import org.hapticon.sensor.protocol.framed.FramedProtocol.TYPE_SAMPLE

/**
 * Decodes what a device sends in the Hapticon framed protocol (device info, samples,
 * acknowledgements) and hands it to [listener].
 *
 * COBS is undone byte by byte as data arrives, so a frame split across any number of reads decodes
 * the same. Every 0x00 ends a frame, which is how the decoder resynchronises after garbage: the
 * bytes since the last delimiter fail the COBS or CRC check and are dropped as one bad frame (so
 * garbage also costs the good frame it runs into). Frames longer than
 * [FramedProtocol.MAX_FRAME_LENGTH] are skipped ([FrameError.OVERLONG]) without growing a buffer.
 *
 * Sequence numbers are checked across all device-to-host frames with a good CRC; a device-info frame
 * restarts the check (the device rebooted or was asked). A sample frame whose channel count differs
 * from the last device info is [FrameError.FIELD_COUNT]; host-to-device frame types are
 * [FrameError.UNKNOWN_TYPE]. Empty frames (back-to-back delimiters, which devices send to flush the
 * line) count one dropped byte each and nothing else.
 */
public class FramedDecoder(private val listener: Listener) : StreamDecoder {
    /** Receives decoded frames, on the thread that calls [feed]. */
    public interface Listener {
        /** A sample frame; [frame] is reused and valid only during this call. */
        public fun onSample(frame: SampleFrame)

        /** A device-info frame. */
        public fun onDeviceInfo(info: DeviceInfo) {}

        /**
         * The device's answer to the command that had sequence number [sequence]: [status] is
         * [AckStatus.OK] or the reason for rejecting it; [detail] narrows it down (for
         * [AckStatus.OUT_OF_RANGE] and [AckStatus.BAD_OUTPUT], the offending output index).
         */
        public fun onAck(sequence: Int, status: AckStatus, detail: Int) {}
    }

    override val stats: StreamStats = StreamStats()

    /** The last device info received in this stream, or null. */
    public var deviceInfo: DeviceInfo? = null
        private set

    private val frame = ByteArray(FramedProtocol.MAX_FRAME_LENGTH)
    private val sample = SampleFrame()
    private var length = 0
    private var code = 0 // Current COBS block code; 0 while waiting for a frame's first byte.
    private var remaining = 0 // Data bytes left in the current block.
    private var encodedLength = 0 // Wire bytes of the current frame, delimiter excluded.
    private var overlong = false
    private var expectedSequence = NO_SEQUENCE
    private var lastRawTime = NO_TIME
    private var timeBase = 0L

    override fun feed(bytes: ByteArray, offset: Int, length: Int) {
        checkRange(bytes.size, offset, length)
        stats.bytes += length
        for (i in offset until offset + length) {
            val b = bytes[i].toInt() and 0xFF
            if (b == 0) {
                endFrame()
                continue
            }
            encodedLength++
            if (overlong) continue
            if (remaining == 0) {
                // A block shorter than 254 data bytes stands for a zero, unless the frame ends here.
                if (code != 0 && code != 0xFF) put(0)
                code = b
                remaining = b - 1
            } else {
                put(b)
                remaining--
            }
        }
    }

    override fun finish() {
        if (encodedLength > 0) stats.rejected(FrameError.TRUNCATED, encodedLength)
        resetFrame()
        expectedSequence = NO_SEQUENCE
        lastRawTime = NO_TIME
        timeBase = 0
        deviceInfo = null
    }

    private fun put(b: Int) {
        if (length == frame.size) overlong = true else frame[length++] = b.toByte()
    }

    private fun endFrame() {
        val wireBytes = encodedLength + 1
        when {
            encodedLength == 0 -> stats.droppedBytes++
            overlong -> stats.rejected(FrameError.OVERLONG, wireBytes)
            remaining != 0 -> stats.rejected(FrameError.MALFORMED, wireBytes)
            else -> decodeFrame(wireBytes)
        }
        resetFrame()
    }

    private fun resetFrame() {
        length = 0
        code = 0
        remaining = 0
        encodedLength = 0
        overlong = false
    }

    private fun decodeFrame(wireBytes: Int) {
        if (length < HEADER_LENGTH + CRC_LENGTH) return stats.rejected(FrameError.MALFORMED, wireBytes)
        if (Crc16.compute(frame, 0, length) != 0) return stats.rejected(FrameError.CRC, wireBytes)
        if (frame[0].toInt() != FramedProtocol.VERSION) return stats.rejected(FrameError.VERSION, wireBytes)
        val type = frame[1].toInt() and 0xFF
        val sequence = u16(2)
        val payloadLength = length - HEADER_LENGTH - CRC_LENGTH
        if (type == TYPE_DEVICE_INFO) {
            expectedSequence = NO_SEQUENCE
            lastRawTime = NO_TIME
            timeBase = 0
        }
        checkSequence(sequence)
        val error = when (type) {
            TYPE_SAMPLE -> decodeSample(sequence, payloadLength)
            TYPE_DEVICE_INFO -> decodeDeviceInfo(payloadLength)
            TYPE_ACK -> decodeAck(payloadLength)
            else -> FrameError.UNKNOWN_TYPE
        }
        if (error != null) stats.rejected(error, wireBytes)
    }

    private fun checkSequence(sequence: Int) {
        if (expectedSequence != NO_SEQUENCE && sequence != expectedSequence) {
            stats.sequenceGaps++
            // Serial links do not reorder: a jump of more than half the range is a step back (a
            // reboot without device info), not 60000 lost frames.
            val skipped = (sequence - expectedSequence) and 0xFFFF
            if (skipped < 0x8000) stats.lostFrames += skipped
        }
        expectedSequence = (sequence + 1) and 0xFFFF
    }

    private fun decodeSample(sequence: Int, payloadLength: Int): FrameError? {
        val valueBytes = payloadLength - SAMPLE_TIMESTAMP_LENGTH
        val channels = valueBytes / 2
        val expected = deviceInfo?.channelCount
        if (valueBytes <= 0 || valueBytes % 2 != 0 || channels > FramedProtocol.MAX_CHANNELS || (expected != null && channels != expected)) {
            return FrameError.FIELD_COUNT
        }
        val raw = u32(HEADER_LENGTH)
        if (lastRawTime != NO_TIME && raw < lastRawTime) timeBase += 1L shl 32
        lastRawTime = raw
        sample.sequence = sequence
        sample.timestampMicros = timeBase + raw
        sample.channelCount = channels
        var p = HEADER_LENGTH + SAMPLE_TIMESTAMP_LENGTH
        for (c in 0 until channels) {
            sample.values[c] = u16(p)
            p += 2
        }
        stats.frames++
        listener.onSample(sample)
        return null
    }

    private fun decodeDeviceInfo(payloadLength: Int): FrameError? {
        if (payloadLength < DEVICE_INFO_FIXED_LENGTH) return FrameError.FIELD_COUNT
        val p = HEADER_LENGTH
        val rate = u32(p + 4)
        val channels = frame[p + 8].toInt() and 0xFF
        val outputs = frame[p + 9].toInt() and 0xFF
        val adcBits = frame[p + 3].toInt() and 0xFF
        val nameLength = payloadLength - DEVICE_INFO_FIXED_LENGTH - channels
        if (channels !in 1..FramedProtocol.MAX_CHANNELS || outputs > FramedProtocol.MAX_OUTPUTS || nameLength !in 0..FramedProtocol.MAX_NAME_LENGTH) {
            return FrameError.FIELD_COUNT
        }
        if (adcBits !in 1..16 || rate !in 1..Int.MAX_VALUE.toLong()) return FrameError.SYNTAX
        val nameStart = p + DEVICE_INFO_FIXED_LENGTH + channels
        for (i in nameStart until nameStart + nameLength) if (frame[i] !in 0x20..0x7E) return FrameError.SYNTAX
        val info = DeviceInfo(
            firmwareMajor = frame[p].toInt() and 0xFF,
            firmwareMinor = frame[p + 1].toInt() and 0xFF,
            firmwarePatch = frame[p + 2].toInt() and 0xFF,
            adcBits = adcBits,
            sampleRateHz = rate.toInt(),
            outputCount = outputs,
            channelUnits = List(channels) { ChannelUnit.of(frame[p + DEVICE_INFO_FIXED_LENGTH + it].toInt() and 0xFF) },
            name = String(frame, nameStart, nameLength, Charsets.US_ASCII),
        )
        deviceInfo = info
        stats.frames++
        listener.onDeviceInfo(info)
        return null
    }

    private fun decodeAck(payloadLength: Int): FrameError? {
        if (payloadLength != ACK_LENGTH) {
            stats.malformedAcks++
            return FrameError.FIELD_COUNT
        }
        val p = HEADER_LENGTH
        stats.frames++
        listener.onAck(u16(p), AckStatus.of(frame[p + 2].toInt() and 0xFF), frame[p + 3].toInt() and 0xFF)
        return null
    }

    private fun u16(at: Int): Int = (frame[at].toInt() and 0xFF) or ((frame[at + 1].toInt() and 0xFF) shl 8)

    private fun u32(at: Int): Long = u16(at).toLong() or (u16(at + 2).toLong() shl 16)

    private companion object {
        const val NO_SEQUENCE = -1
        const val NO_TIME = -1L
    }
}
