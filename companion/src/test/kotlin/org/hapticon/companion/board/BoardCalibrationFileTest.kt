package org.hapticon.companion.board

import java.io.ByteArrayInputStream
import java.io.File
import java.time.Instant
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.sensor.port.SerialPort
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

/**
 * `hapticon board calibrate --save FILE` and `board set --calibration FILE` against [BoardDouble]: the file holds
 * exactly the steps the walk reached, written whole or not at all (stopped with q: nothing; an existing file: refused
 * before the port opens unless --force), and `set --calibration` writes the same bytes as `set --steps` with those
 * steps, while a bad file (step 201, a tampered current, another schema or version, unknown members, eight
 * electrodes, NaN) is one line naming the file and the member, with nothing opened.
 */
class BoardCalibrationFileTest {
    @get:Rule
    val temp = TemporaryFolder()

    private var opened = 0

    private fun io(board: SerialPort?, keys: String = "") = BoardIo(
        listPorts = { emptyList() },
        openPort = { _, _ ->
            opened++
            board ?: throw AssertionError("nothing may be opened")
        },
        keys = { TerminalKeys(ByteArrayInputStream(keys.toByteArray())) },
        infoTimeoutMillis = 2_000,
        clock = { Instant.parse("2026-11-27T00:12:03.456Z") },
    )

    // Electrode 1: two steps up; 2..8 kept at 60; 9: one down; whole-array check: too strong once (all one down), then fine.
    private val walkKeys = "uuy" + "y".repeat(7) + "dy" + "dy"
    private val walkSteps = listOf(61) + List(7) { 59 } + listOf(58)

    private fun saved(steps: List<Int>, participant: String? = "P07") =
        CalibrationFile.encode(StoredCalibration(ElectrotactileCalibrationResult(steps), Instant.parse("2026-11-27T00:12:03Z"), participant))

    @Test
    fun calibrateSave_writesExactlyTheStepsTheWalkReached_withParticipantAndTime() {
        val file = File(temp.root, "p07.json")
        val result = boardCli(io(BoardDouble(), walkKeys), "calibrate", "--port", "/dev/ttyACM0", "--save", file.path, "--participant", "P07")

        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(saved(walkSteps), file.readText())
        assertEquals(walkSteps, CalibrationFile.decode(file.readBytes()).result.steps)
        assertTrue(file.readText(), "      \"step\": 61,\n      \"milliamps\": 0.8235\n" in file.readText())
        val lines = result.stdout.lines()
        assertTrue(result.stdout, "calibrated steps (electrodes 1-9): 61,59,59,59,59,59,59,59,58" in lines)
        assertTrue(result.stdout, "saved ${file.path}: participant P07, calibrated 2026-11-27T00:12:03Z, steps 61,59,59,59,59,59,59,59,58" in lines)
        assertTrue(result.stdout, "use it: hapticon board set --port /dev/ttyACM0 --grains N --shape SHAPE --calibration ${file.path}" in lines)
        // Only the file: the temporary it was written to is gone.
        assertEquals(listOf("p07.json"), temp.root.list()!!.toList())
    }

    @Test
    fun calibrateSave_stoppedWithQ_writesNothing_andSaysSo() {
        val file = File(temp.root, "p07.json")
        val result = boardCli(io(BoardDouble(), "uuyq"), "calibrate", "--port", "/dev/ttyACM0", "--save", file.path)

        assertEquals(2, result.exitCode)
        assertTrue(result.stdout, "stopped: calibration not finished, nothing kept" in result.stdout.lines())
        assertEquals(listOf("hapticon: calibration stopped before the end: nothing written to ${file.path}"), result.stderrLines)
        assertFalse(file.exists())
        assertEquals(emptyList<String>(), temp.root.list()!!.toList())
    }

    @Test
    fun calibrateSave_existingFile_isRefusedBeforeThePortOpens_unlessForce() {
        val file = File(temp.root, "p07.json")
        file.writeText("an earlier calibration\n")
        val refused = boardCli(io(null, walkKeys), "calibrate", "--port", "/dev/ttyACM0", "--save", file.path)

        assertEquals(2, refused.exitCode)
        assertEquals(listOf("hapticon: ${file.path} already exists: nothing written (give --force to replace it, or another file name)"), refused.stderrLines)
        assertEquals("", refused.stdout)
        assertEquals(0, opened)
        assertEquals("an earlier calibration\n", file.readText())

        val forced = boardCli(io(BoardDouble(), walkKeys), "calibrate", "--port", "/dev/ttyACM0", "--save", file.path, "--force")
        assertEquals(forced.toString(), 0, forced.exitCode)
        assertEquals(saved(walkSteps, participant = null), file.readText())
        assertEquals(listOf("p07.json"), temp.root.list()!!.toList())
    }

    @Test
    fun calibrateSave_fileAppearingDuringTheWalk_isNotReplaced() {
        val file = File(temp.root, "p07.json")
        // The keys are read after the check: the file appears while the person is being calibrated.
        val io = BoardIo(
            listPorts = { emptyList() },
            openPort = { _, _ -> BoardDouble() },
            keys = {
                file.writeText("written meanwhile\n")
                TerminalKeys(ByteArrayInputStream(walkKeys.toByteArray()))
            },
            infoTimeoutMillis = 2_000,
        )
        val result = boardCli(io, "calibrate", "--port", "/dev/ttyACM0", "--save", file.path)

        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: ${file.path} already exists: nothing written (give --force to replace it, or another file name)"), result.stderrLines)
        // The steps are still on the screen, and the other file is untouched, with no temporary left beside it.
        assertTrue(result.stdout, "calibrated steps (electrodes 1-9): 61,59,59,59,59,59,59,59,58" in result.stdout.lines())
        assertEquals("written meanwhile\n", file.readText())
        assertEquals(listOf("p07.json"), temp.root.list()!!.toList())
    }

    @Test
    fun calibrate_optionsOnlyWithSave_andABadParticipant_areOneLineErrors() {
        val file = File(temp.root, "x.json").path
        val cases = mapOf(
            listOf("--force") to "hapticon: --force only goes with --save FILE",
            listOf("--participant", "P07") to "hapticon: --participant only goes with --save FILE",
            listOf("--save", file, "--participant", "x".repeat(65)) to "hapticon: --participant: at most 64 characters, has 65",
            listOf("--save", temp.root.path) to "hapticon: --save ${temp.root.path} is a directory: give a file name",
            listOf("--save", File(temp.root, "no/such/dir.json").path) to "hapticon: --save ${File(temp.root, "no/such/dir.json").path}: the directory ${File(temp.root, "no/such").path} does not exist",
        )
        for ((options, line) in cases) {
            val result = boardCli(io(null), "calibrate", "--port", "/dev/ttyACM0", *options.toTypedArray())
            assertEquals(result.toString(), listOf(line), result.stderrLines)
            assertEquals(2, result.exitCode)
        }
        assertEquals(0, opened)
    }

    @Test
    fun setCalibration_sendsExactlyTheBytesOfSetSteps() {
        val steps = listOf(61, 59, 0, 200, 60, 60, 148, 1, 58)
        val file = File(temp.root, "p07.json").apply { writeText(saved(steps)) }
        val fromFile = BoardDouble()
        val viaFile = boardCli(io(fromFile), "set", "--port", "/dev/ttyACM0", "--grains", "19", "--shape", "triangle", "--calibration", file.path)
        val fromSteps = BoardDouble()
        val viaSteps = boardCli(io(fromSteps), "set", "--port", "/dev/ttyACM0", "--grains", "19", "--shape", "triangle", "--steps", steps.joinToString(","))

        assertEquals(viaFile.toString(), 0, viaFile.exitCode)
        assertEquals(0, viaSteps.exitCode)
        assertArrayEquals(fromSteps.fake.writtenBytes(), fromFile.fake.writtenBytes())
        assertEquals(steps, fromFile.received.last().payload.subList(8, 17))
        assertEquals(
            "calibration ${file.path}: participant P07, calibrated 2026-11-27T00:12:03Z, steps 61,59,0,200,60,60,148,1,58\n" +
                "acknowledged: the grain settings (19 grains on 6 electrodes)\n",
            viaFile.stdout,
        )
    }

    @Test
    fun setCalibration_badFile_isOneLineNamingFileAndMember_andNothingIsOpened() {
        val good = saved(List(9) { 60 })
        val cases = listOf(
            good.replaceFirst("\"step\": 60", "\"step\": 201") to "electrodes[0].step: must be in 0..200 (2.7 mA), was 201",
            // A tampered current: past the cap, and below it but not the step's.
            good.replaceFirst("\"milliamps\": 0.81", "\"milliamps\": 3.0") to "electrodes[0].milliamps: 3.0 is not the current of step 60 (0.81 mA)",
            good.replaceFirst("\"milliamps\": 0.81", "\"milliamps\": 0.5") to "electrodes[0].milliamps: 0.5 is not the current of step 60 (0.81 mA)",
            good.replace("hapticon.electrotactile-calibration", "hapticon.icon") to "schema: must be \"hapticon.electrotactile-calibration\", was \"hapticon.icon\": not a calibration file",
            good.replace("\"version\": 1", "\"version\": 2") to "version: must be 1, was 2: newer than this build reads",
            good.replace("\"participant\": \"P07\",", "\"participant\": \"P07\", \"maxMilliamps\": 9,") to "maxMilliamps: unknown member (version 1 has schema, version, participant, calibratedAt, electrodes)",
            good.replaceFirst("    {\n      \"electrode\": 1,\n      \"step\": 60,\n      \"milliamps\": 0.81\n    },\n", "") to "electrodes: needs 9 electrodes (1..9), has 8",
            good.replaceFirst("\"milliamps\": 0.81", "\"milliamps\": \"NaN\"") to "electrodes[0].milliamps: must be a finite number, was \"NaN\"",
        )
        for ((text, problem) in cases) {
            val file = File(temp.root, "bad.json").apply { writeText(text) }
            val result = boardCli(io(null), "set", "--port", "/dev/ttyACM0", "--grains", "9", "--calibration", file.path)
            assertEquals(text, listOf("hapticon: ${file.path}: $problem"), result.stderrLines)
            assertEquals(2, result.exitCode)
            assertEquals("", result.stdout)
        }
        val nan = File(temp.root, "nan.json").apply { writeText(good.replaceFirst("\"milliamps\": 0.81", "\"milliamps\": NaN")) }
        val nanResult = boardCli(io(null), "set", "--port", "/dev/ttyACM0", "--grains", "9", "--calibration", nan.path)
        assertEquals(2, nanResult.exitCode)
        assertTrue(nanResult.stderr, nanResult.stderrLines.single().startsWith("hapticon: ${nan.path}: not valid JSON: "))
        assertEquals(0, opened)
    }

    @Test
    fun setCalibration_withStepsOrMa_missingOrHugeFile_areOneLineErrors() {
        val file = File(temp.root, "p07.json").apply { writeText(saved(List(9) { 60 })) }
        val huge = File(temp.root, "huge.json").apply { writeText(" ".repeat(CalibrationFile.MAX_BYTES + 1)) }
        val missing = File(temp.root, "missing.json").path
        val cases = mapOf(
            listOf("--calibration", file.path, "--steps", "60") to "hapticon: give --calibration FILE or --ma/--steps, not both",
            listOf("--calibration", file.path, "--ma", "1") to "hapticon: give --calibration FILE or --ma/--steps, not both",
            listOf("--calibration", missing) to "hapticon: $missing: no such file",
            listOf("--calibration", huge.path) to "hapticon: ${huge.path}: larger than 16384 bytes: not a calibration file",
        )
        for ((options, line) in cases) {
            val result = boardCli(io(null), "set", "--port", "/dev/ttyACM0", "--grains", "9", *options.toTypedArray())
            assertEquals(result.toString(), listOf(line), result.stderrLines)
            assertEquals(2, result.exitCode)
        }
        assertEquals(0, opened)
    }
}
