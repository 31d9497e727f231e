package org.hapticon.companion.board

import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import java.io.File
import java.time.Instant
import java.util.concurrent.TimeUnit
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.junit.After
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assume.assumeTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

/**
 * `hapticon board set`, and `calibrate --save` then `set --calibration`, through jSerialComm on a real pseudo-terminal (Linux only; skipped elsewhere or without
 * python3): a small Python relay joins two pty pairs like a null-modem cable, the CLI opens one end with
 * [DesktopSerialPort] exactly as it opens `/dev/ttyACM0`, and this test plays the board on the other end, also
 * through [DesktopSerialPort], answering with the device's own encoder.
 */
class PtyBoardTest {
    @get:Rule
    val temp = TemporaryFolder()

    private var relay: Process? = null
    private lateinit var hostEnd: String
    private lateinit var boardEnd: String

    @Before
    fun startRelay() {
        assumeTrue("Linux only", System.getProperty("os.name").orEmpty() == "Linux")
        assumeTrue("python3 needed for the pty pair", File("/usr/bin/python3").canExecute())
        val process = ProcessBuilder("/usr/bin/python3", "-c", RELAY).start()
        relay = process
        val names = process.inputStream.bufferedReader()
        hostEnd = names.readLine() ?: error("relay gave no pty: " + process.errorStream.bufferedReader().readText())
        boardEnd = names.readLine()!!
    }

    @After
    fun stopRelay() {
        relay?.let {
            it.outputStream.close() // EOF on stdin ends the relay
            if (!it.waitFor(2, TimeUnit.SECONDS)) it.destroyForcibly()
        }
    }

    /**
     * Plays the board on its end of the pty in a thread: answers REQUEST_INFO with device info and each of the next
     * commands with OK, as hapticon_ref.ino does, until [answers] frames were answered; every byte received goes to
     * the returned stream.
     */
    private fun playBoard(board: DesktopSerialPort, answers: Int): Pair<Thread, ByteArrayOutputStream> {
        val received = ByteArrayOutputStream()
        val boardThread = Thread {
            val device = FramedEncoder()
            val out = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
            val frame = ByteArrayOutputStream()
            val buffer = ByteArray(256)
            var answered = 0
            while (answered < answers) {
                val n = board.read(buffer, 0, buffer.size, 5_000)
                if (n <= 0) return@Thread
                for (i in 0 until n) {
                    received.write(buffer[i].toInt())
                    if (buffer[i].toInt() != 0) {
                        frame.write(buffer[i].toInt())
                        continue
                    }
                    val decoded = BoardDouble.cobsDecode(frame.toByteArray())
                    frame.reset()
                    val sequence = (decoded[2].toInt() and 0xFF) or ((decoded[3].toInt() and 0xFF) shl 8)
                    val length = if (decoded[1].toInt() == 0x11) {
                        device.deviceInfo(DeviceInfo(1, 0, 0, 10, 1000, 0, listOf(ChannelUnit.RAW), "pty-board"), out)
                    } else {
                        device.ack(sequence, AckStatus.OK, 0, out)
                    }
                    board.write(out, 0, length, 1_000)
                    answered++
                }
            }
        }
        boardThread.start()
        return boardThread to received
    }

    @Test
    fun set_overARealPty_writesTheCommandsAndPrintsTheBoardsAck() {
        val board = DesktopSerialPort.open(boardEnd, LineSettings())
        val (boardThread, received) = playBoard(board, answers = 2)
        try {
            val result = boardCli(BoardIo.desktop(), "set", "--port", hostEnd, "--grains", "39", "--shape", "triangle", "--steps", "80")
            boardThread.join(5_000)

            assertEquals(result.toString(), 0, result.exitCode)
            assertEquals("acknowledged: the grain settings (39 grains on 6 electrodes)\n", result.stdout)
            val encoder = FramedEncoder()
            val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
            val expected = buffer.copyOf(encoder.requestInfo(buffer)) +
                buffer.copyOf(encoder.setGrains(FirmwareGrainParams(39, BinDistribution.LINEAR, 0, 1023, ElectrodeMask.TRIANGLE.pattern, List(9) { 80 }), buffer))
            assertArrayEquals(expected, received.toByteArray())
        } finally {
            board.close()
        }
    }

    @Test
    fun calibrateSave_thenSetCalibration_overARealPty_sendTheSavedSteps() {
        val file = File(temp.root, "p07.json")
        val io = BoardIo(
            listPorts = DesktopSerialPort::list,
            openPort = DesktopSerialPort::open,
            // Electrode 1 two steps up, the rest kept at 60, the whole-array check fine.
            keys = { TerminalKeys(ByteArrayInputStream(("uuy" + "y".repeat(9)).toByteArray())) },
            clock = { Instant.parse("2026-11-27T00:12:03Z") },
        )
        val board = DesktopSerialPort.open(boardEnd, LineSettings())
        try {
            // REQUEST_INFO, 11 stimuli (electrode 1 three times), one whole-array check.
            val (calibrating, _) = playBoard(board, answers = 13)
            val calibrated = boardCli(io, "calibrate", "--port", hostEnd, "--save", file.path, "--participant", "P07")
            calibrating.join(5_000)
            assertEquals(calibrated.toString(), 0, calibrated.exitCode)
            val steps = listOf(62) + List(8) { 60 }
            assertEquals(CalibrationFile.encode(StoredCalibration(ElectrotactileCalibrationResult(steps), Instant.parse("2026-11-27T00:12:03Z"), "P07")), file.readText())

            val (setting, received) = playBoard(board, answers = 2)
            val set = boardCli(io, "set", "--port", hostEnd, "--grains", "19", "--shape", "triangle", "--calibration", file.path)
            setting.join(5_000)
            assertEquals(set.toString(), 0, set.exitCode)
            val encoder = FramedEncoder()
            val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
            val expected = buffer.copyOf(encoder.requestInfo(buffer)) +
                buffer.copyOf(encoder.setGrains(FirmwareGrainParams(19, BinDistribution.LINEAR, 0, 1023, ElectrodeMask.TRIANGLE.pattern, steps), buffer))
            assertArrayEquals(expected, received.toByteArray())
        } finally {
            board.close()
        }
    }

    private companion object {
        /** Two raw pty pairs joined master to master; prints the two slave paths; ends at EOF on stdin. */
        const val RELAY = """
import os, pty, select, sys, tty
m1, s1 = pty.openpty()
m2, s2 = pty.openpty()
tty.setraw(s1); tty.setraw(s2)
print(os.ttyname(s1)); print(os.ttyname(s2)); sys.stdout.flush()
peer = {m1: m2, m2: m1}
while True:
    ready, _, _ = select.select([m1, m2, 0], [], [])
    if 0 in ready and not os.read(0, 1):
        break
    for fd in ready:
        if fd in peer:
            try:
                os.write(peer[fd], os.read(fd, 4096))
            except OSError:
                pass
"""
    }
}
