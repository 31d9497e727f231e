package org.hapticon.companion.board

import java.io.ByteArrayInputStream
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.grains.stimulate
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * `hapticon board calibrate` with scripted keys against [BoardDouble]: Shaping Compliance's per-electrode walk (200 ms
 * from step 60 = 0.81 mA, one step per key), the whole-array check, the exact bytes on the wire, the 2.7 mA cap
 * (step 200 reached, one key past it sends nothing), refusals printed in one line, and stopping early.
 */
class BoardCalibrateTest {
    private fun io(board: BoardDouble, keys: String) = BoardIo(
        listPorts = { emptyList() },
        openPort = { _, _ -> board },
        keys = { TerminalKeys(ByteArrayInputStream(keys.toByteArray())) },
        infoTimeoutMillis = 2_000,
    )

    @Test
    fun walk_raisesOneStepPerKey_thenChecksTheWholeArray_withTheExactBytes() {
        val double = BoardDouble()
        // Electrode 1: two steps up, kept; 2..8 kept at the start; 9: one step down, kept; check: too strong, then fine.
        val keys = "uuy" + "y".repeat(7) + "dy" + "dy"
        val result = boardCli(io(double, keys), "calibrate", "--port", "/dev/ttyACM0")

        assertEquals(result.toString(), 0, result.exitCode)
        val expectedStimuli = listOf(60, 61, 62).map { Triple(0, it, 200) } + (1..7).map { Triple(it, 60, 200) } + listOf(Triple(8, 60, 200), Triple(8, 59, 200))
        assertEquals(expectedStimuli, BoardDouble.stimuli(double.received))
        // Every command the app's encoder would write, numbered 0 (REQUEST_INFO) onwards, byte for byte.
        val encoder = FramedEncoder()
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        var expected = buffer.copyOf(encoder.requestInfo(buffer))
        for ((electrode, step, millis) in expectedStimuli) expected += buffer.copyOf(encoder.stimulate(FirmwareStimulus(electrode, step, millis), buffer))
        val range = FirmwareForceRange(0, 1023)
        expected += buffer.copyOf(encoder.setGrains(FirmwareGrainParams.wholeArrayCheck(listOf(62) + List(7) { 60 } + listOf(59), range), buffer))
        expected += buffer.copyOf(encoder.setGrains(FirmwareGrainParams.wholeArrayCheck(listOf(61) + List(7) { 59 } + listOf(58), range), buffer))
        assertArrayEquals(expected, double.fake.writtenBytes())
        assertEquals((0..14).toList(), double.received.map { it.sequence })

        val lines = result.stdout.lines()
        assertTrue(result.stdout, "electrode 1: step 60 = 0.8100 mA: acknowledged" in lines)
        assertTrue(result.stdout, "electrode 1: step 62 = 0.8370 mA: acknowledged" in lines)
        assertTrue(result.stdout, "electrode 1: kept at 0.8370 mA (step 62)" in lines)
        assertEquals(2, lines.count { it == "whole-array check, 39 grains on all 9 electrodes: acknowledged" })
        assertTrue(result.stdout, "calibrated steps (electrodes 1-9): 61,59,59,59,59,59,59,59,58" in lines)
        assertTrue(result.stdout, "calibrated mA: 0.8235,0.7965,0.7965,0.7965,0.7965,0.7965,0.7965,0.7965,0.7830" in lines)
    }

    @Test
    fun wholeArrayCheck_oneElectrodeAdjusted_isSentAtItsNewStep() {
        val double = BoardDouble()
        // Every electrode kept at 60; in the check electrode 5 stands out (two steps weaker), electrode 1 is faint (one stronger).
        val keys = "y".repeat(9) + "w" + "5ww" + "1s" + "y"
        val result = boardCli(io(double, keys), "calibrate", "--port", "/dev/ttyACM0")

        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.lines()
        assertTrue(result.stdout, "pick the electrode that stands out first: 1-9" in lines)
        assertTrue(result.stdout, "electrode 5: step 58 = 0.7830 mA" in lines)
        assertTrue(result.stdout, "electrode 1: step 61 = 0.8235 mA" in lines)
        assertEquals(4, lines.count { it == "whole-array check, 39 grains on all 9 electrodes: acknowledged" })
        assertTrue(result.stdout, "calibrated steps (electrodes 1-9): 61,60,60,60,58,60,60,60,60" in lines)
        // REQUEST_INFO is sequence 0, the nine stimuli 1..9, the checks 10..13: the last one carries the adjusted steps.
        val encoder = FramedEncoder(13)
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val last = buffer.copyOf(encoder.setGrains(FirmwareGrainParams.wholeArrayCheck(listOf(61, 60, 60, 60, 58, 60, 60, 60, 60), FirmwareForceRange(0, 1023)), buffer))
        val written = double.fake.writtenBytes()
        assertArrayEquals(last, written.copyOfRange(written.size - last.size, written.size))
    }

    @Test
    fun walk_stopsAtTheCap_exactly2point7mA_andAKeyPastItSendsNothing() {
        val double = BoardDouble()
        // 140 steps from 60 reach 200 (2.7 mA); two keys more must not go past it.
        val keys = "u".repeat(140) + "u+" + "q"
        val result = boardCli(io(double, keys), "calibrate", "--port", "/dev/ttyACM0")

        val stimuli = BoardDouble.stimuli(double.received)
        assertEquals(141, stimuli.size)
        assertEquals((60..200).toList(), stimuli.map { it.second })
        val lines = result.stdout.lines()
        assertTrue(result.stdout, "electrode 1: step 199 = 2.6865 mA: acknowledged" in lines)
        assertTrue(result.stdout, "electrode 1: step 200 = 2.7000 mA: acknowledged" in lines)
        assertEquals(2, lines.count { it == "electrode 1: already at the 2.7 mA cap (step 200): it cannot go higher" })
        assertTrue(result.stdout, "stopped: calibration not finished, nothing kept" in lines)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: calibration stopped before the end"), result.stderrLines)
    }

    @Test
    fun walk_boardRefusesAStimulus_printsTheReasonInOneLine_andGoesOn() {
        val double = BoardDouble(answer = { if (it.type == 0x14 && it.payload[1] == 61) AckStatus.OUT_OF_RANGE to 5 else AckStatus.OK to 0 })
        val result = boardCli(io(double, "uu"), "calibrate", "--port", "/dev/ttyACM0")

        val lines = result.stdout.lines()
        assertTrue(result.stdout, "electrode 1: step 61 = 0.8235 mA: The board refused the 200 ms stimulus on electrode 1 at 0.824 mA: an amplitude step past 200 (2.7 mA)" in lines)
        assertTrue(result.stdout, "electrode 1: step 62 = 0.8370 mA: acknowledged" in lines)
        // The keys ran out before the end: nothing is kept.
        assertEquals(2, result.exitCode)
    }

    @Test
    fun walk_givenARange_needsNoDeviceInfo_andSendsTheCheckOverIt() {
        val double = BoardDouble(info = null)
        val result = boardCli(io(double, "y".repeat(10)), "calibrate", "--port", "/dev/ttyACM0", "--range", "0:4095")

        assertEquals(result.toString(), 0, result.exitCode)
        val check = double.received.last()
        assertEquals(0x13, check.type)
        assertEquals(listOf(39, 0, 0, 0, 0xFF, 0x0F, 0xFF, 0x01), check.payload.subList(0, 8))
        assertEquals(List(9) { 60 }, check.payload.subList(8, 17))
        assertEquals(9, BoardDouble.stimuli(double.received).size)
    }
}
