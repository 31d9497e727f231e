package org.hapticon.sensor.electrotactile

/** One pulse of a scan: [electrode] (0..8) starts a pulse at [onsetMicros] after the grain's start. */
public data class ScanPulse(val electrode: Int, val onsetMicros: Long)

/**
 * Time-division scanning, as Shaping Compliance drove several electrodes from one current source: within
 * each pulse of the train the active electrodes are pulsed one after another, each [PULSE_MICROS] µs pulse
 * followed by [GAP_MICROS] µs before the next electrode, so one electrode slot is 250 µs (a 4 kHz scan). Pulse p
 * of the train starts at p/f; electrode j (in [ElectrodePattern.electrodes] order) at p/f + j·250 µs.
 */
public object TimeDivisionScan {
    /** Each electrode's pulse: 200 µs. */
    public const val PULSE_MICROS: Long = 200

    /** The pause after each pulse before the next electrode: 50 µs. */
    public const val GAP_MICROS: Long = 50

    /** One electrode slot: 250 µs. */
    public const val SLOT_MICROS: Long = PULSE_MICROS + GAP_MICROS

    /** The scan rate: 1/250 µs = 4000 Hz. */
    public const val SCAN_HZ: Double = 1e6 / SLOT_MICROS

    /**
     * The pulses of one grain on [pattern] with [train]'s pulse count and rate, in time order.
     * @throws IllegalArgumentException when [train]'s width is not 200 µs or the scan of all electrodes does not
     *   fit in one period (9 × 250 µs = 2.25 ms fits the grain's 8 ms).
     */
    public fun schedule(pattern: ElectrodePattern, train: PulseTrain = PulseTrain.GRAIN): List<ScanPulse> {
        require(train.pulseWidthMicros == PULSE_MICROS.toDouble()) { "the scan drives ${PULSE_MICROS} µs pulses, the train has ${train.pulseWidthMicros} µs" }
        val electrodes = pattern.electrodes()
        val periodMicros = 1e6 / train.frequencyHz
        require(electrodes.size * SLOT_MICROS <= periodMicros) {
            "${electrodes.size} electrodes × $SLOT_MICROS µs do not fit in a $periodMicros µs period"
        }
        return (0 until train.pulseCount).flatMap { p ->
            val start = Math.round(p * periodMicros)
            electrodes.mapIndexed { j, e -> ScanPulse(e, start + j * SLOT_MICROS) }
        }
    }
}
