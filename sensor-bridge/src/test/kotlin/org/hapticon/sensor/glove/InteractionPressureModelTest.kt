package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class InteractionPressureModelTest {
    private val model = InteractionPressureModel()

    @Test
    fun regions_haveTheStudyParametersAndWeightsSummingToOne() {
        val expected = listOf(
            listOf(0.77, 0.23, 0.93, 2.57), listOf(0.70, 0.30, 0.37, 1.29), listOf(0.82, 0.18, 0.62, 2.30),
            listOf(0.69, 0.31, 0.19, 1.23), listOf(0.67, 0.33, 0.33, 1.66), listOf(0.17, 0.83, 1.23, 4.10),
        )
        assertEquals(expected, HandRegion.ALL.map { listOf(it.selfWeight, it.partnerWeight, it.minPressureVolts, it.maxPressureVolts) })
        HandRegion.ALL.forEach { assertEquals(it.name, 1.0, it.selfWeight + it.partnerWeight, 1e-15) }
        assertEquals(listOf(0, 1, 2, 3, 4, null), HandRegion.ALL.map { it.lucidGlovesIndex })
        assertEquals(listOf(190.0, 190.0, 190.0, 190.0, 190.0, 310.0), HandRegion.ALL.map { it.actuatorLimitDegrees })
    }

    @Test
    fun normalizedMiddle_atZeroMidAndMaxAngles_isZeroHalfOne() {
        assertEquals(0.0, model.normalizedMiddle(30.9), 0.0)
        // (67.95 − 30.9)/(105 − 30.9) = 37.05/74.1.
        assertEquals(0.5, model.normalizedMiddle(67.95), 1e-15)
        assertEquals(1.0, model.normalizedMiddle(105.0), 0.0)
    }

    @Test
    fun normalized_outsideTheRange_isClamped() {
        assertEquals(0.0, model.normalizedMiddle(10.0), 0.0)
        assertEquals(1.0, model.normalizedMiddle(180.0), 0.0)
        assertEquals(0.0, model.normalizedThumb(-20.0), 0.0)
        assertEquals(1.0, model.normalizedThumb(120.0), 0.0)
    }

    @Test
    fun normalizedThumb_withAConfiguredZero_startsThere() {
        assertEquals(0.5, model.normalizedThumb(50.0), 0.0)
        // θT0 = 10: (55 − 10)/(100 − 10).
        assertEquals(0.5, InteractionPressureModel(thumbZeroDegrees = 10.0).normalizedThumb(55.0), 1e-15)
        assertEquals(0.0, InteractionPressureModel(thumbZeroDegrees = 10.0).normalizedThumb(10.0), 0.0)
    }

    @Test
    fun pressureVolts_openHands_isPminAndClosedHandsIsPmax() {
        for (region in HandRegion.ALL) {
            assertEquals(region.name, region.minPressureVolts, model.pressureVolts(region, 0.0, 0.0, 0.0, 0.0), 1e-15)
            assertEquals(region.name, region.maxPressureVolts, model.pressureVolts(region, 100.0, 105.0, 100.0, 105.0), 1e-15)
        }
    }

    @Test
    fun pressureVolts_mixedGrip_matchesTheHandComputedFormula() {
        // Self nT 0.5, nM 1; partner nT 0, nM 0.5.
        // Palm: (0.085·0.5 + 0.085·1 + 0.415·0 + 0.415·0.5)·2.87 + 1.23 = 0.335·2.87 + 1.23 = 2.19145.
        assertEquals(2.19145, model.pressureVolts(HandRegion.PALM, 50.0, 105.0, 0.0, 67.95), 1e-12)
        // Thumb: (0.385·0.5 + 0.385 + 0.115·0.5)·1.64 + 0.93 = 0.635·1.64 + 0.93 = 1.9714.
        assertEquals(1.9714, model.pressureVolts(HandRegion.THUMB, 50.0, 105.0, 0.0, 67.95), 1e-12)
        // Index: (0.35·1.5 + 0.15·0.5)·0.92 + 0.37 = 0.6·0.92 + 0.37 = 0.922.
        assertEquals(0.922, model.pressureVolts(HandRegion.INDEX, 50.0, 105.0, 0.0, 67.95), 1e-12)
        // Middle: (0.41·1.5 + 0.09·0.5)·1.68 + 0.62 = 0.66·1.68 + 0.62 = 1.7288.
        assertEquals(1.7288, model.pressureVolts(HandRegion.MIDDLE, 50.0, 105.0, 0.0, 67.95), 1e-12)
        // Ring: (0.345·1.5 + 0.155·0.5)·1.04 + 0.19 = 0.595·1.04 + 0.19 = 0.8088.
        assertEquals(0.8088, model.pressureVolts(HandRegion.RING, 50.0, 105.0, 0.0, 67.95), 1e-12)
        // Pinky: (0.335·1.5 + 0.165·0.5)·1.33 + 0.33 = 0.585·1.33 + 0.33 = 1.10805.
        assertEquals(1.10805, model.pressureVolts(HandRegion.PINKY, 50.0, 105.0, 0.0, 67.95), 1e-12)
    }

    @Test
    fun pressureVolts_swappingSelfAndPartner_swapsTheWeights() {
        // Only the partner's thumb closed: β/2·(Pmax − Pmin) + Pmin; palm 0.415·2.87 + 1.23 = 2.42105.
        assertEquals(2.42105, model.pressureVolts(HandRegion.PALM, 0.0, 0.0, 100.0, 0.0), 1e-12)
        // Only the own thumb closed: α/2; palm 0.085·2.87 + 1.23 = 1.47395.
        assertEquals(1.47395, model.pressureVolts(HandRegion.PALM, 100.0, 0.0, 0.0, 0.0), 1e-12)
    }

    @Test
    fun pressuresInto_fillsEveryRegionLikePressureVolts() {
        val out = DoubleArray(6)
        model.pressuresInto(50.0, 105.0, 0.0, 67.95, out)
        assertEquals(listOf(1.9714, 0.922, 1.7288, 0.8088, 1.10805, 2.19145), out.map { Math.round(it * 1e9) / 1e9 })
    }

    @Test
    fun pressure_nonFiniteAngleOrShortArray_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { model.pressureVolts(HandRegion.THUMB, Double.NaN, 0.0, 0.0, 0.0) }
        assertThrows(IllegalArgumentException::class.java) { model.pressureVolts(HandRegion.THUMB, 0.0, 0.0, 0.0, Double.POSITIVE_INFINITY) }
        assertThrows(IllegalArgumentException::class.java) { model.pressuresInto(0.0, 0.0, 0.0, 0.0, DoubleArray(5)) }
    }

    @Test
    fun constructor_zeroNotBelowMax_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { InteractionPressureModel(thumbZeroDegrees = 100.0) }
        assertThrows(IllegalArgumentException::class.java) { InteractionPressureModel(middleZeroDegrees = 105.0) }
        assertThrows(IllegalArgumentException::class.java) { InteractionPressureModel(thumbZeroDegrees = Double.NaN) }
    }
}
