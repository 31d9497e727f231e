package org.hapticon.sensor.grains

/**
 * The parameters of compliance grains that do not depend on the sensor's sample rate.
 *
 * [grainCount] grains over [[minNewtons], [maxNewtons]]: the range is cut into [binCount] = [grainCount] + 1 bins
 * placed by [distribution] (see [GrainBins]), so a slow press across the whole range crosses exactly
 * [grainCount] inner edges and fires [grainCount] grains. Shaping Compliance: "(number of grains) = (number of
 * bins) − 1", its 9–39 grains are 10–40 bins (003_8ca1dc8f53472543.txt:95, :97). Grain count 0 is one bin, nothing
 * fires: the reference the paper adds to its analysis (:161).
 * The FSR force is smoothed by a first-order low-pass at [cutoffHz] (see [LowPassFilter]; the paper low-passes the FSR,
 * :123, and gives no cutoff: paper silent, ours 20 Hz), and each grain takes [grainSeconds] to deliver, during which
 * no other grain starts ("We did not trigger a new grain while a previous one was still being delivered", :97).
 */
public data class GrainSettings(
    val grainCount: Int = DEFAULT_GRAIN_COUNT,
    val distribution: BinDistribution = BinDistribution.LINEAR,
    val minNewtons: Double = 0.0,
    val maxNewtons: Double = DEFAULT_MAX_NEWTONS,
    val cutoffHz: Double = DEFAULT_CUTOFF_HZ,
    val grainSeconds: Double = DEFAULT_GRAIN_SECONDS,
) {
    init {
        require(grainSeconds > 0.0 && grainSeconds <= MAX_GRAIN_SECONDS) { "grainSeconds must be in (0, $MAX_GRAIN_SECONDS], was $grainSeconds" }
        require(cutoffHz > 0.0 && cutoffHz.isFinite()) { "cutoffHz must be finite and > 0, was $cutoffHz" }
    }

    init {
        require(grainCount in MIN_GRAIN_COUNT..MAX_GRAIN_COUNT) { "grain count must be in $MIN_GRAIN_COUNT..$MAX_GRAIN_COUNT, was $grainCount" }
    }

    /** Number of force bins: [grainCount] + 1 (grains = bins − 1, Shaping Compliance, 003_8ca1dc8f53472543.txt:95). */
    val binCount: Int get() = grainCount + 1

    /** The [binCount] bins; throws from the constructor like [GrainBins] when the range is invalid. */
    val bins: GrainBins = GrainBins(minNewtons, maxNewtons, grainCount + 1, distribution)

    public companion object {
        /** Fewest grains: 0, the study's no-grain condition (one bin, nothing ever fires). */
        public const val MIN_GRAIN_COUNT: Int = 0

        /** Most grains: one fewer than [GrainBins.MAX_COUNT] bins. */
        public const val MAX_GRAIN_COUNT: Int = GrainBins.MAX_COUNT - 1

        /** Default number of grains: the middle of the study's 9–39 range. */
        public const val DEFAULT_GRAIN_COUNT: Int = 24

        /** Fewest grains the study used. */
        public const val STUDY_MIN_GRAIN_COUNT: Int = 9

        /** Most grains the study used. */
        public const val STUDY_MAX_GRAIN_COUNT: Int = 39

        /** Default top of the force range: 10 N, a firm finger press and the Interlink 402's useful range. */
        public const val DEFAULT_MAX_NEWTONS: Double = 10.0

        /** Default low-pass cutoff: 20 Hz passes a finger's pressing (< 10 Hz) and removes FSR and ADC noise. */
        public const val DEFAULT_CUTOFF_HZ: Double = 20.0

        /**
         * Default grain length on the phone's LRA: 20 ms. Paper silent (its grains are electrotactile, 8 ms + 250 µs per
         * electrode: [org.hapticon.sensor.electrotactile.TimeDivisionScan.deliveryMicros], which the board uses); ours is
         * a few periods of a phone LRA's resonance (about 175 Hz), and, as published, no grain starts while it plays.
         */
        public const val DEFAULT_GRAIN_SECONDS: Double = 0.020

        /** Longest grain accepted: 0.5 s (longer is no longer a grain). */
        public const val MAX_GRAIN_SECONDS: Double = 0.5
    }
}
