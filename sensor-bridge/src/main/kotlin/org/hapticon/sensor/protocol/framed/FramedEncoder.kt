package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.stream.checkRange
import org.hapticon.sensor.protocol.framed.FramedProtocol.HEADER_LENGTH
import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.sensor.safety.SafetyLimits

/**
 * Encodes frames of the Hapticon framed protocol onto the wire: COBS-encoded, followed by the 0x00
 * delimiter, ready to write to a port. Each method writes one frame into `destination` from
 * `offset`, returns the number of bytes written, and does not allocate.
 *
 * Each encoder numbers its frames with its own 16-bit sequence counter (wrapping to 0 after 65535),
 * so use one per direction. The host needs only the command methods; the device-side methods
 * ([deviceInfo], [sample], [ack]) serve simulators, tests and benchmarks.
 *
 * All methods throw [IndexOutOfBoundsException] if fewer than
 * [FramedProtocol.MAX_ENCODED_FRAME_LENGTH] bytes are left from `offset`.
 *
 * @param firstSequence the sequence number of the first frame.
 * @throws IllegalArgumentException if [firstSequence] is not in 0..65535.
 */
public class FramedEncoder(firstSequence: Int = 0) {
    init {
        require(firstSequence in 0..0xFFFF) { "firstSequence must be in 0..65535, was $firstSequence" }
    }

    private val frame = ByteArray(FramedProtocol.MAX_FRAME_LENGTH)
    private var length = 0

    /** The sequence number the next frame will carry. */
    public var nextSequence: Int = firstSequence
        private set

    /** The sequence number of the last frame encoded (to match its [AckStatus] answer), or -1 before the first. */
    public var lastSequence: Int = -1
        private set

    /**
     * A command setting outputs `firstOutput until firstOutput + values.size` to [values], each in
     * [SafetyLimits.SERVO_MIN]..[SafetyLimits.SERVO_MAX]. The device checks the range again, applies
     * all values or none, and answers with an ack.
     * @throws SafetyLimitException if a value is outside the servo range.
     * @throws IllegalArgumentException unless 1..[FramedProtocol.MAX_OUTPUTS] values are given and
     *   the outputs lie within 0 until [FramedProtocol.MAX_OUTPUTS].
     */
    public fun setOutputs(firstOutput: Int, values: IntArray, destination: ByteArray, offset: Int = 0): Int {
        require(values.size in 1..FramedProtocol.MAX_OUTPUTS) { "need 1..${FramedProtocol.MAX_OUTPUTS} values, got ${values.size}" }
        require(firstOutput >= 0 && firstOutput + values.size <= FramedProtocol.MAX_OUTPUTS) {
            "outputs $firstOutput until ${firstOutput + values.size} exceed 0 until ${FramedProtocol.MAX_OUTPUTS}"
        }
        for (v in values) SafetyLimits.requireServoValue(v)
        begin(FramedProtocol.TYPE_SET_OUTPUTS)
        u8(firstOutput)
        for (v in values) u16(v)
        return finish(destination, offset)
    }

    /** A command asking the device to send its device-info frame. */
    public fun requestInfo(destination: ByteArray, offset: Int = 0): Int {
        begin(FramedProtocol.TYPE_REQUEST_INFO)
        return finish(destination, offset)
    }

    /**
     * A command setting the sample rate to [rateHz]; the device rejects rates it cannot do with
     * [AckStatus.OUT_OF_RANGE].
     * @throws IllegalArgumentException if [rateHz] is not positive.
     */
    public fun setSampleRate(rateHz: Int, destination: ByteArray, offset: Int = 0): Int {
        require(rateHz >= 1) { "rateHz must be positive, was $rateHz" }
        begin(FramedProtocol.TYPE_SET_SAMPLE_RATE)
        u32(rateHz.toLong())
        return finish(destination, offset)
    }

    /**
     * A command giving the firmware's stand-alone grain renderer new parameters: [payload] as
     * `FirmwareGrainParams.payload()` makes it (callers use the typed `FramedEncoder.setGrains(params, …)` of
     * sensor-bridge's grains package, so the protocol does not depend on the grain model; the device checks
     * the values again and NACKs with [AckStatus.OUT_OF_RANGE] and grains.h's reason as detail).
     */
    internal fun setGrainsPayload(payload: ByteArray, destination: ByteArray, offset: Int): Int {
        begin(FramedProtocol.TYPE_SET_GRAINS)
        for (b in payload) u8(b.toInt() and 0xFF)
        return finish(destination, offset)
    }

    /**
     * A command giving one calibration stimulus: [payload] as `FirmwareStimulus.payload()` makes it (callers use the
     * typed `FramedEncoder.stimulate(stimulus, …)` of sensor-bridge's grains package; the device checks the values
     * again and NACKs with [AckStatus.OUT_OF_RANGE] and grains.h's reason as detail).
     */
    internal fun stimulatePayload(payload: ByteArray, destination: ByteArray, offset: Int): Int {
        begin(FramedProtocol.TYPE_STIMULATE)
        for (b in payload) u8(b.toInt() and 0xFF)
        return finish(destination, offset)
    }

    /** A device-info frame describing [info]. */
    public fun deviceInfo(info: DeviceInfo, destination: ByteArray, offset: Int = 0): Int {
        begin(FramedProtocol.TYPE_DEVICE_INFO)
        u8(info.firmwareMajor)
        u8(info.firmwareMinor)
        u8(info.firmwarePatch)
        u8(info.adcBits)
        u32(info.sampleRateHz.toLong())
        u8(info.channelCount)
        u8(info.outputCount)
        for (unit in info.channelUnits) u8(unit.code)
        for (c in info.name) u8(c.code)
        return finish(destination, offset)
    }

    /**
     * A sample frame with the first [count] of [values] (each 0..65535) read at device time
     * [timestampMicros], of which the low 32 bits are sent.
     * @throws IllegalArgumentException unless [count] is in 1..[FramedProtocol.MAX_CHANNELS] and
     *   within [values], and each value is in 0..65535.
     */
    public fun sample(timestampMicros: Long, values: IntArray, destination: ByteArray, offset: Int = 0, count: Int = values.size): Int {
        require(count in 1..FramedProtocol.MAX_CHANNELS && count <= values.size) { "count must be in 1..${FramedProtocol.MAX_CHANNELS} and within values, was $count" }
        begin(FramedProtocol.TYPE_SAMPLE)
        u32(timestampMicros and 0xFFFF_FFFFL)
        for (c in 0 until count) {
            val v = values[c]
            require(v in 0..0xFFFF) { "value $v of channel $c is outside 0..65535" }
            u16(v)
        }
        return finish(destination, offset)
    }

    /**
     * An acknowledgement of the command with sequence number [sequence]: [status] [AckStatus.OK]
     * accepts it, anything else rejects it; [detail] (0..255) narrows the reason down.
     * @throws IllegalArgumentException if [sequence] is not in 0..65535, [detail] not in 0..255,
     *   or [status] is [AckStatus.UNKNOWN].
     */
    public fun ack(sequence: Int, status: AckStatus, detail: Int, destination: ByteArray, offset: Int = 0): Int {
        require(sequence in 0..0xFFFF) { "sequence must be in 0..65535, was $sequence" }
        require(detail in 0..0xFF) { "detail must be in 0..255, was $detail" }
        require(status != AckStatus.UNKNOWN) { "UNKNOWN is not sent" }
        begin(FramedProtocol.TYPE_ACK)
        u16(sequence)
        u8(status.code)
        u8(detail)
        return finish(destination, offset)
    }

    private fun begin(type: Int) {
        frame[0] = FramedProtocol.VERSION.toByte()
        frame[1] = type.toByte()
        frame[2] = nextSequence.toByte()
        frame[3] = (nextSequence ushr 8).toByte()
        length = HEADER_LENGTH
    }

    private fun finish(destination: ByteArray, offset: Int): Int {
        checkRange(destination.size, offset, FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val crc = Crc16.compute(frame, 0, length)
        frame[length++] = (crc ushr 8).toByte()
        frame[length++] = crc.toByte()
        val written = Cobs.encode(frame, 0, length, destination, offset)
        destination[offset + written] = 0
        lastSequence = nextSequence
        nextSequence = (nextSequence + 1) and 0xFFFF
        return written + 1
    }

    private fun u8(value: Int) {
        frame[length++] = value.toByte()
    }

    private fun u16(value: Int) {
        frame[length++] = value.toByte()
        frame[length++] = (value ushr 8).toByte()
    }

    private fun u32(value: Long) {
        u16((value and 0xFFFF).toInt())
        u16(((value ushr 16) and 0xFFFF).toInt())
    }
}
