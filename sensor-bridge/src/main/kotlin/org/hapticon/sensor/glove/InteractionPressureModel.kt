package org.hapticon.sensor.glove

/**
 * The tele-handshake paper's interaction pressure per hand region (its Eq. 6, 002_12aacdd60a14fec1.txt:127):
 *
 * P = [α/2·nT(θself,T) + α/2·nM(θself,M) + β/2·nT(θpartner,T) + β/2·nM(θpartner,M)]·(Pmax − Pmin) + Pmin
 *
 * with α, β, Pmin, Pmax from [HandRegion], nT(θ) = (θ − θT0)/(θTmax − θT0) and nM(θ) = (θ − θM0)/(θMmax − θM0),
 * each clamped to [0, 1]. Because α + β = 1 the bracket is in [0, 1] and P in [Pmin, Pmax] (volts). "Self" is
 * the hand whose actuators receive P; "partner" is the other hand.
 *
 * Allocation-free; angles must be finite (a faulty sensor should be fed as 0°, see [AngleReading.Fault]).
 */
public data class InteractionPressureModel(
    /**
     * θT0: thumb angle at which its contribution starts, in degrees. Paper silent on a value: it sets "no handshake
     * initiation angle" for the thumb (002_12aacdd60a14fec1.txt:167) yet Eq. 6 normalises from θT0 (:127), and
     * Table 7 prints one value, 30.9°, under θT0 and θM0 (:295-296) that :168-170 give the middle finger. Ours: 0°,
     * the thumb contributing from straight, which is what "no initiation angle" leaves.
     */
    val thumbZeroDegrees: Double = DEFAULT_THUMB_ZERO_DEGREES,
    /** θTmax: thumb angle of full contribution, in degrees: 100° (002_12aacdd60a14fec1.txt:126). */
    val thumbMaxDegrees: Double = DEFAULT_THUMB_MAX_DEGREES,
    /** θM0: middle-finger angle at which its contribution starts: 30.9°, the initiation angle (002_12aacdd60a14fec1.txt:168-170). */
    val middleZeroDegrees: Double = DEFAULT_MIDDLE_ZERO_DEGREES,
    /** θMmax: middle-finger angle of full contribution, in degrees: 105° (002_12aacdd60a14fec1.txt:126). */
    val middleMaxDegrees: Double = DEFAULT_MIDDLE_MAX_DEGREES,
) {
    init {
        require(thumbZeroDegrees.isFinite() && thumbMaxDegrees.isFinite() && thumbZeroDegrees < thumbMaxDegrees) {
            "need finite thumbZeroDegrees < thumbMaxDegrees, were $thumbZeroDegrees and $thumbMaxDegrees"
        }
        require(middleZeroDegrees.isFinite() && middleMaxDegrees.isFinite() && middleZeroDegrees < middleMaxDegrees) {
            "need finite middleZeroDegrees < middleMaxDegrees, were $middleZeroDegrees and $middleMaxDegrees"
        }
    }

    private val thumbSpan = thumbMaxDegrees - thumbZeroDegrees
    private val middleSpan = middleMaxDegrees - middleZeroDegrees

    /**
     * nT(θ) = (θ − θT0)/(θTmax − θT0) clamped to [0, 1].
     * @throws IllegalArgumentException when [degrees] is not finite.
     */
    public fun normalizedThumb(degrees: Double): Double {
        require(degrees.isFinite()) { "thumb angle must be finite, was $degrees" }
        return ((degrees - thumbZeroDegrees) / thumbSpan).coerceIn(0.0, 1.0)
    }

    /**
     * nM(θ) = (θ − θM0)/(θMmax − θM0) clamped to [0, 1].
     * @throws IllegalArgumentException when [degrees] is not finite.
     */
    public fun normalizedMiddle(degrees: Double): Double {
        require(degrees.isFinite()) { "middle angle must be finite, was $degrees" }
        return ((degrees - middleZeroDegrees) / middleSpan).coerceIn(0.0, 1.0)
    }

    /**
     * P for [region] in volts, from the receiving hand's ("self") and the other hand's ("partner") thumb and
     * middle angles in degrees.
     * @throws IllegalArgumentException when an angle is not finite.
     */
    public fun pressureVolts(
        region: HandRegion,
        selfThumbDegrees: Double,
        selfMiddleDegrees: Double,
        partnerThumbDegrees: Double,
        partnerMiddleDegrees: Double,
    ): Double {
        val self = normalizedThumb(selfThumbDegrees) + normalizedMiddle(selfMiddleDegrees)
        val partner = normalizedThumb(partnerThumbDegrees) + normalizedMiddle(partnerMiddleDegrees)
        return pressureOf(region, self, partner)
    }

    /**
     * Writes P for every region into [out] in [HandRegion.ALL] order (thumb … palm); the allocation-free form
     * of [pressureVolts].
     * @throws IllegalArgumentException when an angle is not finite or [out] has fewer than 6 slots.
     */
    public fun pressuresInto(
        selfThumbDegrees: Double,
        selfMiddleDegrees: Double,
        partnerThumbDegrees: Double,
        partnerMiddleDegrees: Double,
        out: DoubleArray,
    ) {
        require(out.size >= REGIONS.size) { "out needs ${REGIONS.size} slots, has ${out.size}" }
        val self = normalizedThumb(selfThumbDegrees) + normalizedMiddle(selfMiddleDegrees)
        val partner = normalizedThumb(partnerThumbDegrees) + normalizedMiddle(partnerMiddleDegrees)
        for (i in REGIONS.indices) out[i] = pressureOf(REGIONS[i], self, partner)
    }

    /** [self] and [partner] are nT + nM of each hand; the α/2 and β/2 factors are applied here. */
    private fun pressureOf(region: HandRegion, self: Double, partner: Double): Double {
        val share = region.selfWeight / 2 * self + region.partnerWeight / 2 * partner
        return share * region.pressureRangeVolts + region.minPressureVolts
    }

    public companion object {
        /** Default θT0, 0°: paper silent (the thumb has "no handshake initiation angle", 002_12aacdd60a14fec1.txt:167). */
        public const val DEFAULT_THUMB_ZERO_DEGREES: Double = 0.0

        /** The paper's θTmax, 100° (002_12aacdd60a14fec1.txt:126). */
        public const val DEFAULT_THUMB_MAX_DEGREES: Double = 100.0

        /** The paper's θM0, 30.9° (002_12aacdd60a14fec1.txt:168-170, Table 7 :296), equal to the handshake threshold. */
        public const val DEFAULT_MIDDLE_ZERO_DEGREES: Double = 30.9

        /** The paper's θMmax, 105° (002_12aacdd60a14fec1.txt:126). */
        public const val DEFAULT_MIDDLE_MAX_DEGREES: Double = 105.0

        // A plain array for the per-sample loop (values() would copy on every call).
        private val REGIONS: Array<HandRegion> = HandRegion.entries.toTypedArray()
    }
}
