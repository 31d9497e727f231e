package org.hapticon.sensor.protocol.framed

/** The device's answer to a command: [OK] acknowledges it, anything else rejects it (NACK) and says why. */
public enum class AckStatus(
    /** The code on the wire. */
    public val code: Int,
) {
    /** Accepted and applied. */
    OK(0),

    /** A value outside its range: a servo value outside 0..1000, a sample rate the board cannot do. */
    OUT_OF_RANGE(1),

    /** An output index the device does not have. */
    BAD_OUTPUT(2),

    /** The payload has the wrong length for the command. */
    MALFORMED(3),

    /** A command type the device does not know. */
    UNKNOWN_COMMAND(4),

    /** A protocol version the device does not speak. */
    UNSUPPORTED_VERSION(5),

    /** A code this version does not know, from a newer firmware. */
    UNKNOWN(255),
    ;

    /** Lookup by wire code. */
    public companion object {
        /** The status with [code], or [UNKNOWN]. */
        public fun of(code: Int): AckStatus = entries.firstOrNull { it.code == code } ?: UNKNOWN
    }
}
