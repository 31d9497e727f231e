package org.hapticon.companion.board

import java.io.IOException
import org.hapticon.companion.CliResult
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.protocol.framed.symbol
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

/**
 * `hapticon board` against a scripted reference board ([BoardDouble]) speaking the real framed protocol: the exact
 * bytes written, the acks and refusals printed one line each, values past the 2.7 mA cap or NaN refused before the
 * port is even opened, and the port listing's format.
 */
class BoardCommandTest {
    private var opened: LineSettings? = null

    private fun io(board: SerialPort?, ports: List<PortListing> = emptyList()) = BoardIo(
        listPorts = { ports },
        openPort = { path, settings ->
            opened = settings
            board ?: throw IOException("cannot open $path (error 2: missing, busy, or no permission: on Linux join the dialout group)")
        },
        keys = { throw AssertionError("set, info and ports read no keys") },
        infoTimeoutMillis = 2_000,
    )

    private fun board(io: BoardIo, vararg args: String): CliResult = boardCli(io, *args)

    /** The wire bytes of REQUEST_INFO then SET_GRAINS with [params], as a fresh encoder numbers them (0, 1). */
    private fun infoThenGrains(params: FirmwareGrainParams): ByteArray {
        val encoder = FramedEncoder()
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val info = buffer.copyOf(encoder.requestInfo(buffer))
        return info + buffer.copyOf(encoder.setGrains(params, buffer))
    }

    private val noPortExpected = object : SerialPort {
        override fun configure(settings: LineSettings) = throw AssertionError("nothing may be opened")
        override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int = throw AssertionError("nothing may be read")
        override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) = throw AssertionError("nothing may be written")
        override val isOpen: Boolean get() = false
        override fun close() = Unit
    }

    @Test
    fun set_writesRequestInfoThenSetGrainsOverTheBoardsRange_andPrintsTheAck() {
        val double = BoardDouble()
        val result = board(io(double), "set", "--port", "/dev/ttyACM0", "--grains", "19", "--shape", "vertical_line", "--ma", "0.81")

        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("acknowledged: the grain settings (19 grains on 6 electrodes)\n", result.stdout)
        // The board's 10-bit raw range from its device info, all nine steps 60 (0.81 mA).
        val expected = FirmwareGrainParams(19, BinDistribution.LINEAR, 0, 1023, ElectrodeMask.VERTICAL_LINE.pattern, List(9) { 60 })
        assertArrayEquals(infoThenGrains(expected), double.fake.writtenBytes())
        assertEquals(listOf(0x11, 0x13), double.received.map { it.type })
        assertEquals(115_200, opened!!.baudRate)
    }

    @Test
    fun set_nineCurrentsAndARange_sendsEachElectrodesStep_withoutAskingForInfo() {
        val double = BoardDouble(info = null)
        val result = board(
            io(double), "set", "--port", "COM3", "--grains", "0", "--electrodes", "XXX/X.X/XXX", "--distribution", "convex",
            "--ma", "0,0.0135,0.81,1,1.5,2,2.5,2.69,2.7", "--range", "100:3000", "--baud", "460800",
        )

        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("acknowledged: the grain settings (0 grains on 8 electrodes)\n", result.stdout)
        val grains = double.received.single()
        assertEquals(0x13, grains.type)
        assertEquals(0, grains.sequence)
        // grains, distribution, min, max, electrode bits 0x1ef, then the nine steps (2.7 mA is step 200 exactly).
        assertEquals(listOf(0, 1, 100, 0, 0xB8, 0x0B, 0xEF, 0x01), grains.payload.subList(0, 8))
        assertEquals(listOf(0, 1, 60, 75, 112, 149, 186, 200, 200), grains.payload.subList(8, 17))
        assertEquals(460_800, opened!!.baudRate)
    }

    @Test
    fun set_boardRefuses_printsTheFirmwaresReasonInOneLine_andExits2() {
        val double = BoardDouble(answer = { AckStatus.OUT_OF_RANGE to 5 })
        val result = board(io(double), "set", "--port", "/dev/ttyACM0", "--grains", "9", "--steps", "120")

        assertEquals(2, result.exitCode)
        assertEquals("The board refused the grain settings (9 grains on 9 electrodes): an amplitude step past 200 (2.7 mA)\n", result.stdout)
        assertEquals(listOf("hapticon: the board did not take the grain settings"), result.stderrLines)
    }

    @Test
    fun set_boardSilent_timesOutAfterTheAckDeadline() {
        val double = BoardDouble(answer = { null })
        val result = board(io(double), "set", "--port", "/dev/ttyACM0", "--grains", "9", "--steps", "120", "--range", "0:1023")

        assertEquals(2, result.exitCode)
        assertEquals("No answer from the board to the grain settings (9 grains on 9 electrodes): no acknowledgement within 500 ms\n", result.stdout)
    }

    @Test
    fun set_pastTheCapOrNaN_isRefusedBeforeThePortIsOpened() {
        val cases = mapOf(
            arrayOf("--ma", Math.nextUp(2.7).toString()) to "hapticon: refused, nothing sent: electrotactile current must be in [0, 2.7] mA, was 2.7000000000000006",
            arrayOf("--ma", "NaN") to "hapticon: refused, nothing sent: electrotactile current must be in [0, 2.7] mA, was NaN",
            arrayOf("--ma", "-0.1") to "hapticon: refused, nothing sent: electrotactile current must be in [0, 2.7] mA, was -0.1",
            arrayOf("--steps", "201") to "hapticon: refused, nothing sent: amplitude step must be in 0..200, was 201",
            arrayOf("--ma", "1,1,1,1,1,1,1,1,2.8") to "hapticon: refused, nothing sent: electrotactile current must be in [0, 2.7] mA, was 2.8",
        )
        for ((amplitude, line) in cases) {
            val result = board(io(noPortExpected), "set", "--port", "/dev/ttyACM0", "--grains", "9", *amplitude)
            assertEquals(result.toString(), 2, result.exitCode)
            assertEquals(listOf(line), result.stderrLines)
            assertEquals("", result.stdout)
        }
        assertEquals(null, opened)
    }

    @Test
    fun set_otherBadValues_areOneLineErrorsBeforeOpening() {
        val cases = mapOf(
            listOf("--grains", "100", "--ma", "1") to "hapticon: refused, nothing sent: grain count must be in 0..99, was 100",
            listOf("--grains", "9", "--electrodes", "XX./..,/...", "--ma", "1") to "hapticon: refused, nothing sent: row 1: ',' is neither X nor .",
            listOf("--grains", "9", "--electrodes", "XX./.../...", "--ma", "1") to "hapticon: refused, nothing sent: a compliance grain needs at least 4 electrodes, XX./.../... has 2",
            listOf("--grains", "9", "--ma", "1,1") to "hapticon: --ma needs 1 or 9 values, got 2",
            listOf("--grains", "9") to "hapticon: board set needs --ma MILLIAMPS or --steps STEPS (one value for all nine electrodes, or nine), or --calibration FILE",
            listOf("--grains", "9", "--ma", "1", "--range", "5:5") to "hapticon: refused, nothing sent: need 0 <= min < max <= 65535, were 5 and 5",
        )
        for ((options, line) in cases) {
            val result = board(io(noPortExpected), "set", "--port", "/dev/ttyACM0", *options.toTypedArray())
            assertEquals(result.toString(), listOf(line), result.stderrLines)
            assertEquals(2, result.exitCode)
        }
        assertEquals(null, opened)
    }

    @Test
    fun set_portThatCannotOpen_isOneLine() {
        val result = board(io(null), "set", "--port", "/dev/ttyUSB9", "--grains", "9", "--ma", "1")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: cannot open /dev/ttyUSB9 (error 2: missing, busy, or no permission: on Linux join the dialout group)"), result.stderrLines)
    }

    @Test
    fun info_printsWhatTheBoardAnnounced() {
        val double = BoardDouble(info = DeviceInfo(1, 2, 3, 12, 1000, 5, listOf(ChannelUnit.RAW, ChannelUnit.MILLIVOLT), "hapticon-ref"))
        val result = board(io(double), "info", "--port", "/dev/ttyACM0")

        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.lines()
        assertEquals("port: /dev/ttyACM0 at 115200 baud", lines[0])
        assertEquals("board: hapticon-ref · firmware 1.2.3 · 1000 Hz · 12-bit", lines[1])
        assertEquals("adc: 12 bits, 1000 Hz, 2 channels (ch0 (${ChannelUnit.RAW.symbol}), ch1 (${ChannelUnit.MILLIVOLT.symbol}))", lines[2])
        assertEquals("grain force range: 0..4095 (channel 0, raw counts)", lines[3])
    }

    @Test
    fun info_noAnswer_saysSoInOneLine() {
        val result = board(io(BoardDouble(info = null)), "info", "--port", "/dev/ttyACM0")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: no device info from /dev/ttyACM0 within 2000 ms: not a Hapticon framed board, or another baud rate (--baud)"), result.stderrLines)
    }

    @Test
    fun ports_oneTabSeparatedLinePerPort() {
        val ports = listOf(
            PortListing("/dev/ttyACM0", 0x2341, 0x0043, "Arduino Uno", "8573631383"),
            PortListing("/dev/ttyS0", null, null, "Physical Port S0", null),
        )
        val result = board(io(null, ports), "ports")
        assertEquals("/dev/ttyACM0\t2341:0043\tArduino Uno\t8573631383\n/dev/ttyS0\t-\tPhysical Port S0\t-\n", result.stdout)
        assertEquals(0, result.exitCode)

        val none = board(io(null), "ports")
        assertEquals("", none.stdout)
        assertEquals(listOf("no serial ports found"), none.stderrLines)
    }

    @Test
    fun unknownSubcommand_isAUsageError() {
        val result = board(io(null), "flash")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: unknown board command 'flash': use ports, info, set or calibrate"), result.stderrLines)
    }
}
