package org.hapticon.sensor.protocol.stream

/** Why a decoder rejected a frame or line; [StreamStats.badFrames] counts each kind separately. */
public enum class FrameError {
    /** Longer than the decoder's bounded buffer; skipped up to the next delimiter. */
    OVERLONG,

    /** Wrong number of fields or values for the format, or a required field is missing. */
    FIELD_COUNT,

    /** A field is not a number, or the line holds a character the format does not allow. */
    SYNTAX,

    /** Broken framing (invalid COBS) or shorter than a header and checksum. */
    MALFORMED,

    /** The checksum does not match. */
    CRC,

    /** A protocol version this decoder does not speak. */
    VERSION,

    /** A frame type this decoder does not know or does not expect in this direction. */
    UNKNOWN_TYPE,

    /** The stream ended (end of recording, unplug) in the middle of a frame. */
    TRUNCATED,
}
