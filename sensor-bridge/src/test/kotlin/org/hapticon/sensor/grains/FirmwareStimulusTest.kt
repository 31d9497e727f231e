package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.protocol.framed.Cobs
import org.hapticon.sensor.protocol.framed.Crc16
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

/** The per-electrode calibration stimulus as the reference firmware's STIMULATE command (grains.h `Stimulus`). */
class FirmwareStimulusTest {
    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    @Test
    fun payload_isTheBytesTheFirmwareSketchTestSends() {
        // sketch_test.cpp sends {2, 60, 0xc8, 0x00} and counts 25 pulses on electrode 2.
        val stimulus = FirmwareStimulus(electrode = 2, step = 60)
        assertArrayEquals(bytes(2, 60, 0xc8, 0x00), stimulus.payload())
        assertEquals(25, stimulus.pulseCount)
    }

    @Test
    fun stimulate_frame_isTypeOx14WithThePayloadAndAGoodCrc() {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val n = FramedEncoder(12).stimulate(FirmwareStimulus(8, 200, 1000), buffer)
        assertEquals(0, buffer[n - 1].toInt())
        val frame = Cobs.decode(buffer.copyOf(n - 1))!!
        assertEquals(4 + 4 + 2, frame.size)
        assertArrayEquals(bytes(0x01, 0x14, 0x0c, 0x00, 8, 200, 0xe8, 0x03), frame.copyOf(8))
        assertEquals(0, Crc16.compute(frame))
    }

    @Test
    fun limits_atTheCapAccepted_justPastAndNaNRefused() {
        assertEquals(200, FirmwareStimulus(0, AmplitudeSteps.STEPS).step)
        val pastCap = assertThrows(SafetyLimitException::class.java) { FirmwareStimulus(0, 201) }
        assertEquals("amplitude step must be in 0..200, was 201", pastCap.message)
        assertThrows(SafetyLimitException::class.java) { FirmwareStimulus(0, -1) }
        // A current asked in mA reaches a step only through stepAtLeast, which refuses just past 2.7 mA and NaN.
        assertEquals(200, FirmwareStimulus(0, AmplitudeSteps.stepAtLeast(2.7)).step)
        assertThrows(SafetyLimitException::class.java) { FirmwareStimulus(0, AmplitudeSteps.stepAtLeast(Math.nextUp(2.7))) }
        assertThrows(SafetyLimitException::class.java) { FirmwareStimulus(0, AmplitudeSteps.stepAtLeast(Double.NaN)) }
        assertThrows(IllegalArgumentException::class.java) { FirmwareStimulus(9, 60) }
        assertThrows(IllegalArgumentException::class.java) { FirmwareStimulus(-1, 60) }
        assertEquals(1000, FirmwareStimulus(0, 60, 1000).durationMillis)
        assertThrows(IllegalArgumentException::class.java) { FirmwareStimulus(0, 60, 1001) }
        assertThrows(IllegalArgumentException::class.java) { FirmwareStimulus(0, 60, 0) }
    }

    @Test
    fun of_calibration_isEachElectrodeAloneAtItsStep_andRefusesTheWholeArrayCheck() {
        val calibration = ElectrotactileCalibration()
        assertEquals(FirmwareStimulus(0, 60, 200), FirmwareStimulus.of(calibration.stimulus()!!))
        calibration.notYet()
        assertEquals(FirmwareStimulus(0, 61, 200), FirmwareStimulus.of(calibration.stimulus()!!))
        calibration.clearAndPainFree()
        repeat(3) { calibration.notYet() }
        assertEquals(FirmwareStimulus(1, 63, 200), FirmwareStimulus.of(calibration.stimulus()!!))
        repeat(8) { calibration.clearAndPainFree() }
        assertThrows(IllegalArgumentException::class.java) { FirmwareStimulus.of(calibration.stimulus()!!) }
    }
}
