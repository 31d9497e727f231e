package org.hapticon.sensor.grains

import kotlin.math.ceil

/**
 * Decides, sample by sample, when a compliance grain starts.
 *
 * Each finite force sample (newtons) is low-pass filtered and binned. The first sample only sets the
 * reference bin. After that a grain fires at a sample when no grain is playing and the filtered force's bin
 * differs from the reference bin (the bin of the last grain); the reference then becomes the current bin. A
 * grain started at sample n plays during samples n … n + D − 1 with D = [grainSamples], so the next grain can
 * start at sample n + D at the earliest. A bin change during a grain is not lost: if the bin still differs
 * from the reference when the grain ends, the next grain fires then (several crossings during one grain give
 * one grain).
 *
 * NaN or ±∞ samples are skipped ([rejectedSamples] counts them): they leave the filter and bins untouched
 * and fire nothing, but the time they take still counts towards the playing grain.
 *
 * [offer] uses only primitive fields, allocates nothing and costs one filter step plus a binary search.
 * Not thread-safe.
 */
public class GrainDecider(
    /** The grain parameters. */
    public val settings: GrainSettings,
    /** The force sensor's sample rate in Hz. */
    public val sampleRateHz: Double,
) {
    private val filter = LowPassFilter(settings.cutoffHz, sampleRateHz)
    private val bins = settings.bins

    /**
     * Samples per grain: ⌈grainSeconds·fs⌉, at least 1, so the next grain's sample is never inside the grain being
     * delivered (Shaping Compliance, 003_8ca1dc8f53472543.txt:97): a 10.25 ms grain at 1 kHz holds 11 samples, not 10.
     * The tolerance keeps an exact multiple (20 ms at 1 kHz = 20) from rounding up on binary error.
     */
    public val grainSamples: Int = maxOf(1, ceil(settings.grainSeconds * sampleRateHz - 1e-9).toInt())

    private var referenceBin = NO_BIN
    private var busySamples = 0

    /** The bin of the last grain (or of the first sample), or −1 before any sample. */
    public val currentReferenceBin: Int get() = referenceBin

    /** The last filtered force in newtons (0 before any sample). */
    public val filteredNewtons: Double get() = filter.value

    /** Whether a grain started at one of the last [grainSamples] samples is still playing. */
    public val isPlaying: Boolean get() = busySamples > 0

    /** How many samples were skipped for being NaN or infinite. */
    public var rejectedSamples: Long = 0
        private set

    /** Feeds one force sample in newtons; returns true when a grain starts at this sample. */
    public fun offer(newtons: Double): Boolean {
        if (busySamples > 0) busySamples--
        if (newtons.isNaN() || newtons.isInfinite()) {
            rejectedSamples++
            return false
        }
        val bin = bins.binOf(filter.filter(newtons))
        if (referenceBin == NO_BIN) {
            referenceBin = bin
            return false
        }
        if (busySamples == 0 && bin != referenceBin) {
            referenceBin = bin
            busySamples = grainSamples
            return true
        }
        return false
    }

    /** Forgets everything: filter, reference bin, playing grain and the rejected count. */
    public fun reset() {
        filter.reset()
        referenceBin = NO_BIN
        busySamples = 0
        rejectedSamples = 0
    }

    private companion object {
        const val NO_BIN = -1
    }
}
