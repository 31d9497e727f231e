package org.hapticon.sensor.protocol.framed

/** What a sample channel's 16-bit value measures, as announced in [DeviceInfo]. */
public enum class ChannelUnit(
    /** The code on the wire. */
    public val code: Int,
) {
    /** Raw ADC counts, 0..2^adcBits − 1. */
    RAW(0),

    /** Millivolts at the ADC pin. */
    MILLIVOLT(1),

    /** Force in grams (a calibrated FSR or load cell). */
    GRAM(2),

    /** Force in millinewtons. */
    MILLINEWTON(3),

    /** Angle in hundredths of a degree (a calibrated flex sensor). */
    CENTIDEGREE(4),

    /** A code this version does not know, from a newer firmware. */
    UNKNOWN(255),
    ;

    /** Lookup by wire code. */
    public companion object {
        /** The unit with [code], or [UNKNOWN]. */
        public fun of(code: Int): ChannelUnit = entries.firstOrNull { it.code == code } ?: UNKNOWN
    }
}

/** A short unit label for a framed channel. */
public val ChannelUnit.symbol: String
    get() = when (this) {
        ChannelUnit.RAW -> "raw"
        ChannelUnit.MILLIVOLT -> "mV"
        ChannelUnit.GRAM -> "g"
        ChannelUnit.MILLINEWTON -> "mN"
        ChannelUnit.CENTIDEGREE -> "°"
        ChannelUnit.UNKNOWN -> "?"
    }
