package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class HandshakeSessionTest {
    @Test
    fun step_mixedGrip_usesTheDefaultTablesServoAndVibrationMappings() {
        // Self 50°, 105° and partner 0°, 67.95°: the pressures of InteractionPressureModelTest.
        val frame = HandshakeSession().step(50.0, 105.0, 0.0, 67.95)
        assertTrue(frame.active)
        assertEquals(HandshakeEvent.STARTED, frame.selfEvent)
        assertEquals(HandshakeEvent.STARTED, frame.partnerEvent)
        // Thumb: 190·(1.9714 − 0.93)/1.64 = 190·0.635 = 120.65°, servo 635, amplitude 40 + 215·0.635 = 176.525 → 177.
        val thumb = frame.command(HandRegion.THUMB)
        assertEquals(1.9714, thumb.pressureVolts, 1e-12)
        assertEquals(120.65, thumb.actuatorDegrees, 1e-9)
        assertEquals(635, thumb.servoValue)
        assertEquals(177, thumb.vibrationAmplitude)
        // Palm: n = 0.335 → 310·0.335 = 103.85°, no servo, amplitude 40 + 72.025 → 112.
        val palm = frame.command(HandRegion.PALM)
        assertEquals(103.85, palm.actuatorDegrees, 1e-9)
        assertEquals(null, palm.servoValue)
        assertEquals(112, palm.vibrationAmplitude)
        assertArrayEquals(intArrayOf(635, 600, 660, 595, 585), frame.lucidGlovesServoValues())
        // The largest region amplitude: middle, 40 + 215·0.66 = 181.9 → 182.
        assertEquals(182, frame.phoneAmplitude)
    }

    @Test
    fun step_partnerOnlyGripping_isRestUntilTheOwnMiddleFingerPasses30_9() {
        // The paper starts pressure on one's own middle finger (002_12aacdd60a14fec1.txt:138, :169-170): a partner
        // gripping at 90° does not start it while the wearer's middle finger is at 30.9° (not above it).
        val session = HandshakeSession()
        val open = session.step(0.0, 30.9, 60.0, 90.0)
        assertFalse(open.active)
        assertEquals(HandshakeEvent.NONE, open.selfEvent)
        assertEquals(HandshakeEvent.STARTED, open.partnerEvent)
        assertEquals(HandRegion.ALL.map { RegionCommand.rest(it) }, open.commands)
        // One step later the wearer's own finger is at 31°: started, and the partner's grip now weighs in through β.
        val own = session.step(0.0, 31.0, 60.0, 90.0)
        assertTrue(own.active)
        assertEquals(HandshakeEvent.STARTED, own.selfEvent)
        // Palm: (α/2·nM(31) + β/2·(nT(60) + nM(90)))·2.87 + 1.23 with α 0.17, β 0.83.
        val expected = (0.085 * 0.1 / 74.1 + 0.415 * (0.6 + 59.1 / 74.1)) * 2.87 + 1.23
        assertEquals(expected, own.command(HandRegion.PALM).pressureVolts, 1e-12)
    }

    @Test
    fun step_ownMiddleOnly_isActiveWithThePartnersHandOpen() {
        val frame = HandshakeSession().step(0.0, 40.0, 0.0, 0.0)
        assertTrue(frame.active)
        assertEquals(HandshakeEvent.STARTED, frame.selfEvent)
        assertEquals(HandshakeEvent.NONE, frame.partnerEvent)
        // Palm: α/2·nM(40) = 0.085·9.1/74.1 of 2.87 V above 1.23 V.
        assertEquals(0.085 * 9.1 / 74.1 * 2.87 + 1.23, frame.command(HandRegion.PALM).pressureVolts, 1e-12)
    }

    @Test
    fun step_partnerLetsGo_theHandshakeEndsOnlyWithTheOwnFinger() {
        val session = HandshakeSession()
        assertTrue(session.step(0.0, 50.0, 0.0, 50.0).active)
        val partnerOpen = session.step(0.0, 50.0, 0.0, 0.0)
        assertEquals(HandshakeEvent.ENDED, partnerOpen.partnerEvent)
        assertTrue(partnerOpen.active)
        // Own finger at 28.9° = 30.9° − the 2° hysteresis: ended.
        val ownOpen = session.step(0.0, 28.9, 0.0, 0.0)
        assertEquals(HandshakeEvent.ENDED, ownOpen.selfEvent)
        assertFalse(ownOpen.active)
    }

    @Test
    fun step_noGrip_isRestEverywhere() {
        val frame = HandshakeSession().step(90.0, 30.0, 90.0, 30.0)
        // Thumbs are bent but no middle finger passed 30.9°: no handshake, so no thumb pressure either.
        assertFalse(frame.active)
        assertEquals(HandRegion.ALL.map { RegionCommand.rest(it) }, frame.commands)
    }

    @Test
    fun computeInto_writesWhatStepReturns() {
        val pressures = DoubleArray(6)
        val angles = DoubleArray(6)
        val servos = IntArray(6)
        val amplitudes = IntArray(6)
        assertTrue(HandshakeSession().computeInto(50.0, 105.0, 0.0, 67.95, pressures, angles, servos, amplitudes))
        val frame = HandshakeSession().step(50.0, 105.0, 0.0, 67.95)
        assertArrayEquals(frame.commands.map { it.pressureVolts }.toDoubleArray(), pressures, 0.0)
        assertArrayEquals(frame.commands.map { it.actuatorDegrees }.toDoubleArray(), angles, 0.0)
        assertArrayEquals(intArrayOf(635, 600, 660, 595, 585, 0), servos)
        assertArrayEquals(frame.commands.map { it.vibrationAmplitude }.toIntArray(), amplitudes)
    }

    @Test
    fun step_nonFiniteAngle_isRejectedWithoutChangingTheSession() {
        val session = HandshakeSession()
        assertThrows(IllegalArgumentException::class.java) { session.step(0.0, Double.NaN, 0.0, 40.0) }
        assertFalse(session.isActive)
        assertThrows(IllegalArgumentException::class.java) { session.step(Double.POSITIVE_INFINITY, 40.0, 0.0, 0.0) }
        assertFalse(session.isActive)
    }

    @Test
    fun constructor_tablesOutOfOrder_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { HandshakeSession(tables = ActuatorTable.DEFAULTS.reversed()) }
    }

    @Test
    fun reset_endsTheHandshake() {
        val session = HandshakeSession()
        session.step(0.0, 40.0, 0.0, 40.0)
        session.reset()
        assertFalse(session.isActive)
        assertEquals(HandshakeEvent.STARTED, session.step(0.0, 40.0, 0.0, 0.0).selfEvent)
    }

    @Test
    fun regionCommand_overTheLimits_isRefused() {
        RegionCommand(HandRegion.THUMB, 1.0, 190.0, 1000, 255)
        for (make in listOf(
            { RegionCommand(HandRegion.THUMB, 1.0, Math.nextUp(190.0), 1000, 255) },
            { RegionCommand(HandRegion.THUMB, 1.0, 10.0, 1001, 255) },
            { RegionCommand(HandRegion.THUMB, 1.0, 10.0, 10, 256) },
            { RegionCommand(HandRegion.PALM, 1.0, 310.5, null, 0) },
            { RegionCommand(HandRegion.THUMB, 1.0, Double.NaN, 10, 0) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: SafetyLimitException) {
            }
        }
    }

    @Test
    fun regionCommand_servoPresenceMustMatchTheRegion() {
        assertThrows(IllegalArgumentException::class.java) { RegionCommand(HandRegion.PALM, 1.0, 10.0, 0, 0) }
        assertThrows(IllegalArgumentException::class.java) { RegionCommand(HandRegion.INDEX, 1.0, 10.0, null, 0) }
        assertThrows(IllegalArgumentException::class.java) { RegionCommand(HandRegion.INDEX, Double.NaN, 10.0, 0, 0) }
    }
}
