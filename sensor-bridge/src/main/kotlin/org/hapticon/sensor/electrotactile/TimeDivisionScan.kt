package org.hapticon.sensor.electrotactile

/** One pulse of a scan: [electrode] (0..8) starts a pulse at [onsetMicros] after the grain's start. */
public data class ScanPulse(val electrode: Int, val onsetMicros: Long)

/**
 * Time-division scanning, as Shaping Compliance drove several electrodes from one current source: within
 * each pulse of the train the active electrodes are pulsed one after another, each [PULSE_MICROS] µs pulse
 * followed by [GAP_MICROS] µs before the next electrode, so one electrode slot is 250 µs (a 4 kHz scan;
 * 003_8ca1dc8f53472543.txt:99, :105, :123). Pulse p of the train starts at p/f; electrode j (in
 * [ElectrodePattern.electrodes] order) at p/f + j·250 µs. The scan order within a pulse is paper silent: ours is
 * the electrodes' numbering.
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
     * How long one grain takes to deliver on [pattern], in µs: the train's last pulse starts (count − 1)/f after the
     * first and its scan of the n electrodes takes n × 250 µs, so 8 ms + n × 250 µs for the grain's 2 pulses at 125 Hz:
     * 9.0 ms on 4 electrodes, 9.5 ms on 6, 10.25 ms on 9. Shaping Compliance fires no grain "while a previous one was
     * still being delivered" (003_8ca1dc8f53472543.txt:97): this is the dead time after each grain, derived from the
     * published pulses (:99) and scan (:105, :123); the paper prints no duration of its own.
     */
    public fun deliveryMicros(pattern: ElectrodePattern, train: PulseTrain = PulseTrain.GRAIN): Long =
        Math.round((train.pulseCount - 1) * 1e6 / train.frequencyHz) + pattern.activeCount * SLOT_MICROS

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
