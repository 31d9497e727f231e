package org.hapticon.sensor.protocol.framed

/**
 * Constants of the Hapticon framed protocol, version 1 (docs/protocols.md has the byte layout).
 *
 * A frame is `version:u8 type:u8 sequence:u16le payload crc:u16be`, COBS-encoded and followed by a
 * 0x00 delimiter. The CRC is CRC-16/CCITT-FALSE over everything before it, sent high byte first, so
 * the CRC of a whole good frame is 0.
 */
public object FramedProtocol {
    internal const val HEADER_LENGTH = 4
    internal const val CRC_LENGTH = 2

    /** The version this code speaks, in the first byte of every frame. */
    public const val VERSION: Int = 1

    /** Most analog channels in a sample frame. */
    public const val MAX_CHANNELS: Int = 32

    /** Most outputs (servos, PWM) a device may have. */
    public const val MAX_OUTPUTS: Int = 16

    /** Longest device name, in ASCII bytes. */
    public const val MAX_NAME_LENGTH: Int = 32

    /** Longest payload. */
    public const val MAX_PAYLOAD_LENGTH: Int = 128

    /** Longest frame before COBS: header, payload and CRC. */
    public const val MAX_FRAME_LENGTH: Int = HEADER_LENGTH + MAX_PAYLOAD_LENGTH + CRC_LENGTH

    /** Longest frame on the wire: COBS adds one byte per started 254, plus the delimiter. */
    public const val MAX_ENCODED_FRAME_LENGTH: Int = MAX_FRAME_LENGTH + (MAX_FRAME_LENGTH + 253) / 254 + 1

    // Device to host.
    internal const val TYPE_DEVICE_INFO = 0x01
    internal const val TYPE_SAMPLE = 0x02
    internal const val TYPE_ACK = 0x03

    // Host to device.
    internal const val TYPE_SET_OUTPUTS = 0x10
    internal const val TYPE_REQUEST_INFO = 0x11
    internal const val TYPE_SET_SAMPLE_RATE = 0x12
    internal const val TYPE_SET_GRAINS = 0x13
    internal const val TYPE_STIMULATE = 0x14

    internal const val DEVICE_INFO_FIXED_LENGTH = 10
    internal const val SAMPLE_TIMESTAMP_LENGTH = 4
    internal const val ACK_LENGTH = 4
}
