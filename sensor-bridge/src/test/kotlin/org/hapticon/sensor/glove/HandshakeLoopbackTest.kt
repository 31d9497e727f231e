package org.hapticon.sensor.glove

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * Two simulated gloves, A and B, shaking hands over a loopback link at 100 Hz. Each glove's flex sensors are
 * read as divider voltages and turned into angles with that person's calibration; each phone sends its angles
 * to the other, and each phone computes the commands for the *other* side's actuators: A's phone drives B
 * (self = B, partner = A) and B's phone drives A.
 *
 * Trajectories (step i = 10 ms), piecewise linear:
 * - A: approach 0–1 s to thumb 20°, middle 25°; grip 1–2 s to 60°, 90°; hold to 3 s; release 3–4 s to 0°.
 * - B: approach 0–1.2 s to 20°, 25°; grip 1.2–2.2 s to 50°, 80°; hold to 3.2 s; release 3.2–4.2 s to 0°.
 *
 * Expected pressures were computed by hand from the formula, P = (α/2·(nT + nM)self + β/2·(nT + nM)partner)·
 * (Pmax − Pmin) + Pmin, outside the code under test.
 */
class HandshakeLoopbackTest {
    private fun ramp(i: Int, from: Int, to: Int, start: Double, end: Double): Double =
        start + (end - start) * (i - from) / (to - from)

    private fun aThumb(i: Int) = when {
        i <= 100 -> ramp(i, 0, 100, 0.0, 20.0)
        i <= 200 -> ramp(i, 100, 200, 20.0, 60.0)
        i <= 300 -> 60.0
        i <= 400 -> ramp(i, 300, 400, 60.0, 0.0)
        else -> 0.0
    }

    private fun aMiddle(i: Int) = when {
        i <= 100 -> ramp(i, 0, 100, 0.0, 25.0)
        i <= 200 -> ramp(i, 100, 200, 25.0, 90.0)
        i <= 300 -> 90.0
        i <= 400 -> ramp(i, 300, 400, 90.0, 0.0)
        else -> 0.0
    }

    private fun bThumb(i: Int) = when {
        i <= 120 -> ramp(i, 0, 120, 0.0, 20.0)
        i <= 220 -> ramp(i, 120, 220, 20.0, 50.0)
        i <= 320 -> 50.0
        i <= 420 -> ramp(i, 320, 420, 50.0, 0.0)
        else -> 0.0
    }

    private fun bMiddle(i: Int) = when {
        i <= 120 -> ramp(i, 0, 120, 0.0, 25.0)
        i <= 220 -> ramp(i, 120, 220, 25.0, 80.0)
        i <= 320 -> 80.0
        i <= 420 -> ramp(i, 320, 420, 80.0, 0.0)
        else -> 0.0
    }

    /** One glove: the true angles become divider voltages, which the phone turns back into angles. */
    private class Glove(
        val thumbDegrees: (Int) -> Double,
        val middleDegrees: (Int) -> Double,
        thumbCalibration: FlexCalibration,
        middleCalibration: FlexCalibration,
    ) {
        private val divider = FlexDivider()
        private val thumb = FlexSensorChannel(thumbCalibration, divider)
        private val middle = FlexSensorChannel(middleCalibration, divider)
        private val thumbTruth = thumbCalibration
        private val middleTruth = middleCalibration

        fun read(i: Int): Pair<Double, Double> {
            val thumbVolts = divider.voltsFor(thumbTruth.resistanceAt(thumbDegrees(i)))
            val middleVolts = divider.voltsFor(middleTruth.resistanceAt(middleDegrees(i)))
            return ((thumb.angleOfVolts(thumbVolts) as AngleReading.Angle).degrees) to
                ((middle.angleOfVolts(middleVolts) as AngleReading.Angle).degrees)
        }
    }

    /** Runs the whole handshake; frame i of each list is what that side's actuators got at step i. */
    private fun run(): Pair<List<HandshakeFrame>, List<HandshakeFrame>> {
        val gloveA = Glove(::aThumb, ::aMiddle, FlexCalibration.THUMB_DEFAULT, FlexCalibration.MIDDLE_DEFAULT)
        // B has a personal calibration.
        val gloveB = Glove(::bThumb, ::bMiddle, FlexCalibration(0.018, 14.0), FlexCalibration(0.021, 18.5))
        val phoneA = HandshakeSession()
        val phoneB = HandshakeSession()
        val toA = ArrayList<HandshakeFrame>()
        val toB = ArrayList<HandshakeFrame>()
        for (i in 0..500) {
            val (aT, aM) = gloveA.read(i)
            val (bT, bM) = gloveB.read(i)
            toB += phoneA.step(bT, bM, aT, aM)
            toA += phoneB.step(aT, aM, bT, bM)
        }
        return toA to toB
    }

    private val frames = run()
    private val toA = frames.first
    private val toB = frames.second

    private fun assertFrame(
        frame: HandshakeFrame,
        pressures: List<Double>,
        servos: IntArray,
        amplitudes: List<Int>,
        thumbDegrees: Double,
        palmDegrees: Double,
    ) {
        assertTrue(frame.active)
        pressures.forEachIndexed { i, p -> assertEquals(HandRegion.ALL[i].name, p, frame.commands[i].pressureVolts, 1e-9) }
        assertArrayEquals(servos, frame.lucidGlovesServoValues())
        assertEquals(amplitudes, frame.commands.map { it.vibrationAmplitude })
        assertEquals(thumbDegrees, frame.command(HandRegion.THUMB).actuatorDegrees, 1e-7)
        assertEquals(palmDegrees, frame.command(HandRegion.PALM).actuatorDegrees, 1e-7)
        assertEquals(null, frame.command(HandRegion.PALM).servoValue)
    }

    @Test
    fun approach_bothMiddleFingersBelowThreshold_everyActuatorRests() {
        for (frame in listOf(toA[50], toB[50])) {
            assertFalse(frame.active)
            assertEquals(HandRegion.ALL.map { RegionCommand.rest(it) }, frame.commands)
        }
    }

    @Test
    fun aGripStart_onlyAAboveThreshold_onlyAFeelsPressure() {
        // t = 1.10 s: A at 24°, 31.5° (just past 30.9°); B still approaching at 18.33°, 22.92°. Pressure starts on
        // one's own middle finger (002_12aacdd60a14fec1.txt:138, :169-170): A's actuators start, B's rest.
        assertEquals(HandshakeEvent.STARTED, toA[110].selfEvent)
        assertEquals(HandshakeEvent.STARTED, toB[110].partnerEvent)
        assertFalse(toA[109].active)
        assertFalse(toB[110].active)
        assertEquals(HandRegion.ALL.map { RegionCommand.rest(it) }, toB[110].commands)
        assertFrame(
            toA[110],
            listOf(1.121225217273954, 0.4751872874493927, 0.8186093279352227, 0.3085705964912281, 0.4807721923076923, 1.5088824703103914),
            intArrayOf(117, 114, 118, 114, 113), listOf(65, 65, 65, 65, 64, 61),
            thumbDegrees = 22.15414102564102, palmDegrees = 30.12319365721998,
        )
    }

    @Test
    fun bGripStart_startsBsPressure_andIsReportedOnceOnEachPhone() {
        // B's middle finger passes 30.9° at t = 1.31 s (25 + 55·0.11 = 31.05°): only then do B's actuators start.
        assertEquals(HandshakeEvent.STARTED, toB[131].selfEvent)
        assertEquals(HandshakeEvent.STARTED, toA[131].partnerEvent)
        assertFalse(toB[130].active)
        assertTrue(toB[131].active)
        assertEquals(1, toA.count { it.selfEvent == HandshakeEvent.STARTED })
        assertEquals(1, toA.count { it.partnerEvent == HandshakeEvent.STARTED })
    }

    @Test
    fun fullGrip_bothHolding_matchesTheFormula() {
        // t = 2.5 s: A at 60°, 90°; B at 50°, 80°.
        assertFrame(
            toB[250],
            listOf(1.9276589203778676, 0.9372278002699055, 1.6321240485829955, 0.8324357894736842, 1.1547014102564104, 3.1781974426450743),
            intArrayOf(608, 617, 602, 618, 620), listOf(171, 173, 170, 173, 173, 186),
            thumbDegrees = 115.5824358974359, palmDegrees = 210.43247638326588,
        )
        assertFrame(
            toA[250],
            listOf(2.0316960053981106, 0.980459109311741, 1.758434655870445, 0.8788624561403509, 1.2078242307692306, 2.955673677462888),
            intArrayOf(672, 664, 678, 662, 660), listOf(184, 183, 186, 182, 182, 169),
            thumbDegrees = 127.6355128205128, palmDegrees = 186.39680836707154,
        )
    }

    @Test
    fun release_halfwayOpen_pressureFallsAccordingly() {
        // t = 3.5 s: A at 30°, 45°; B at 35°, 56°.
        assertFrame(
            toB[350],
            listOf(1.457332483130904, 0.6594306342780027, 1.168529068825911, 0.5161505263157895, 0.7444569871794872, 1.981968080296896),
            intArrayOf(322, 315, 327, 314, 312), listOf(109, 108, 110, 107, 107, 96),
            thumbDegrees = 61.09339743589743, palmDegrees = 81.2230330634278,
        )
        assertFrame(
            toA[350],
            listOf(1.3694596896086368, 0.6229161943319839, 1.0618434008097166, 0.4769371929824562, 0.6995878846153847, 2.1699182219973006),
            intArrayOf(268, 275, 263, 276, 278), listOf(98, 99, 97, 99, 100, 110),
            thumbDegrees = 50.91301282051281, palmDegrees = 101.52426788124154,
        )
    }

    @Test
    fun release_eachSideEndsWhenItsOwnMiddleFingerFallsBelowTheHysteresis() {
        // A falls to 28.8° ≤ 28.9° at t = 3.68 s: A's actuators rest from then; B (80·0.36 = 28.8°) at t = 3.84 s.
        assertEquals(HandshakeEvent.ENDED, toA[368].selfEvent)
        assertTrue(toA[367].active)
        assertFalse(toA[368].active)
        assertEquals(HandshakeEvent.ENDED, toA[384].partnerEvent)
        assertEquals(HandshakeEvent.ENDED, toB[384].selfEvent)
        assertTrue(toB[383].active)
        assertFalse(toB[384].active)
        assertEquals(1, toB.count { it.selfEvent == HandshakeEvent.ENDED })
    }

    @Test
    fun released_bothHandsOpen_everyActuatorRestsAgain() {
        for (frame in listOf(toA[450], toB[450])) {
            assertFalse(frame.active)
            assertArrayEquals(IntArray(5), frame.lucidGlovesServoValues())
            assertEquals(0, frame.phoneAmplitude)
        }
    }

    @Test
    fun wholeRun_neverCommandsBeyondTheSafetyLimits() {
        for (frame in toA + toB) {
            for (command in frame.commands) {
                assertTrue(command.actuatorDegrees in 0.0..command.region.actuatorLimitDegrees)
                assertTrue(command.vibrationAmplitude in 0..255)
                command.servoValue?.let { assertTrue(it in 0..1000) }
            }
        }
    }
}
