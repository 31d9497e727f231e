package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * The tele-handshake loop on the plain JVM: glove volts in; angles, the 30.9° start on the middle finger, the
 * regional pressures of the flex-sensor glove paper, the phone amplitude, LucidGloves servo commands and the
 * wearer's pose out. Expected values are docs/sensor-models.md's, computed by hand there.
 */
class HandshakeLoopTest {
    private val divider = FlexDivider()
    private val servoCommands = mutableListOf<List<Int>>()
    private val loop = HandshakeLoop(divider, { values -> servoCommands += values.toList(); true })
    private val partner = FixedPartner()

    /** A partner holding still at the given angles. */
    private class FixedPartner(var thumb: Double = 0.0, var middle: Double = 0.0) : PartnerHand {
        override val label = "fixed"
        override fun readAngles(nowNanos: Long, out: DoubleArray) {
            out[0] = thumb
            out[1] = middle
        }
    }

    /** The wearer's hand at [thumb]°/[middle]°, as the default calibrations' divider volts, at [millis]. */
    private fun sample(thumb: Double, middle: Double, millis: Long): Int = loop.onSample(
        divider.voltsFor(FlexCalibration.THUMB_DEFAULT.resistanceAt(thumb)),
        divider.voltsFor(FlexCalibration.MIDDLE_DEFAULT.resistanceAt(middle)),
        millis * 1_000_000,
    )

    @Test
    fun workedExample_givesThePapersRegionalPressuresServosAndTheLargestAmplitude() {
        loop.partner = partner.apply { thumb = 0.0; middle = 67.95 }

        val phone = sample(50.0, 105.0, 0)

        assertTrue(loop.active)
        assertEquals(50.0, loop.selfThumbDegrees, 1e-9)
        assertEquals(105.0, loop.selfMiddleDegrees, 1e-9)
        assertEquals(67.95, loop.partnerMiddleDegrees, 0.0)
        // (0.085·0.5 + 0.085·1 + 0.415·0 + 0.415·0.5)·2.87 + 1.23
        assertEquals(2.19145, loop.pressureVolts(HandRegion.PALM), 1e-9)
        // 0.635·1.64 + 0.93
        assertEquals(1.9714, loop.pressureVolts(HandRegion.THUMB), 1e-9)
        // Middle: n = 0.66 → 40 + 215·0.66 = 181.9 → 182, the largest of the six regions.
        assertEquals(182, loop.amplitude(HandRegion.MIDDLE))
        assertEquals(182, phone)
        assertEquals(listOf(listOf(635, 600, 660, 595, 585)), servoCommands)
        assertEquals(1L, loop.samples)
    }

    @Test
    fun handshakeStartsAboveTheMiddleFingers30_9Degrees_andEndsTwoDegreesBelow() {
        assertEquals(0, sample(0.0, 30.8, 0))
        assertFalse(loop.active)
        assertEquals(0.0, loop.pressureVolts(HandRegion.MIDDLE), 0.0)

        // 0.1° above the start: the middle region gets 0.41·(0.1/74.1)·1.68 + 0.62 V; the phone plays the floor of 40.
        assertEquals(40, sample(0.0, 31.0, 10))
        assertTrue(loop.active)
        assertEquals(0.62092955465587, loop.pressureVolts(HandRegion.MIDDLE), 1e-9)

        // Hysteresis: still on at 29°, off at or below 28.9°.
        assertEquals(40, sample(0.0, 29.0, 20))
        assertTrue(loop.active)
        assertEquals(0, sample(0.0, 28.8, 30))
        assertFalse(loop.active)
    }

    @Test
    fun partnerGripping_wearersOwnFingerOpen_nothingIsPresented() {
        loop.partner = partner.apply { thumb = 60.0; middle = 105.0 }
        assertEquals(0, sample(20.0, 25.0, 0))
        assertFalse(loop.active)
        assertEquals(0.0, loop.pressureVolts(HandRegion.PALM), 0.0)
        // The glove's first command is a release: no finger is held.
        assertEquals(listOf(listOf(0, 0, 0, 0, 0)), servoCommands)
    }

    @Test
    fun forceFeedback_changesOnlyAtMost20PerSecond_andReleasedAtOnce() {
        loop.partner = partner.apply { thumb = 0.0; middle = 67.95 }
        sample(50.0, 105.0, 0)
        partner.middle = 105.0
        sample(50.0, 105.0, 10)
        assertEquals(1, servoCommands.size)
        sample(50.0, 105.0, 50)
        assertEquals(2, servoCommands.size)
        sample(50.0, 105.0, 200)
        assertEquals("an unchanged set is not resent", 2, servoCommands.size)

        partner.middle = 0.0
        assertEquals(0, sample(0.0, 0.0, 201))
        assertEquals(listOf(0, 0, 0, 0, 0), servoCommands.last())
        assertEquals(3L, loop.forceFeedbackCommands)

        loop.forceFeedbackOn = false
        partner.middle = 105.0
        sample(50.0, 105.0, 400)
        assertEquals(3, servoCommands.size)
    }

    @Test
    fun releaseForceFeedback_freesAHeldGlove() {
        loop.partner = partner.apply { thumb = 0.0; middle = 67.95 }
        sample(50.0, 105.0, 0)
        loop.releaseForceFeedback(1_000_000)
        assertEquals(listOf(listOf(635, 600, 660, 595, 585), listOf(0, 0, 0, 0, 0)), servoCommands)
        assertEquals(listOf(0, 0, 0, 0, 0), loop.servoValues().toList())
    }

    @Test
    fun faultyFinger_countsAsOpen() {
        loop.partner = partner.apply { thumb = 0.0; middle = 0.0 }
        assertEquals(0, loop.onSample(Double.NaN, divider.supplyVolts, 0))
        assertTrue(loop.thumbFault)
        assertTrue(loop.middleFault)
        assertEquals(0.0, loop.selfThumbDegrees, 0.0)
        assertEquals(0.0, loop.selfMiddleDegrees, 0.0)
        assertFalse(loop.active)
    }

    @Test
    fun ownPose_goesToThePoseSinkAtMost30TimesASecond() {
        val sent = mutableListOf<Pair<Long, Long>>()
        loop.poseSink = HandPoseSink { thumb, middle -> sent += Math.round(thumb * 1e6) to Math.round(middle * 1e6) }
        sample(50.0, 105.0, 0)
        sample(50.0, 105.0, 10)
        sample(50.0, 105.0, 32)
        sample(50.0, 105.0, 33)
        assertEquals(listOf(50_000_000L to 105_000_000L, 50_000_000L to 105_000_000L), sent)
        loop.poseSink = null
        sample(50.0, 105.0, 100)
        assertEquals(2, sent.size)
    }

    @Test
    fun usersCalibration_turnsVoltsIntoTheirAngles() {
        val mine = FlexCalibration(0.02, 14.0)
        loop.thumbCalibration = mine
        loop.onSample(divider.voltsFor(mine.resistanceAt(40.0)), divider.voltsFor(FlexCalibration.MIDDLE_DEFAULT.resistanceAt(0.0)), 0)
        assertEquals(40.0, loop.selfThumbDegrees, 1e-9)
    }
}
