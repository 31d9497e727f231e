package org.hapticon.companion.board

import java.io.ByteArrayOutputStream
import java.io.PrintStream
import java.util.concurrent.CopyOnWriteArrayList
import org.hapticon.companion.CliResult
import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.cli.Console
import org.hapticon.companion.reportFailure
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol

/** One host command as the board double received it: its type, sequence number and payload. */
data class ReceivedCommand(val type: Int, val sequence: Int, val payload: List<Int>)

/**
 * A scripted reference board behind a [FakeSerialPort]: every frame the host writes is COBS-decoded and answered as
 * hapticon_ref.ino answers (docs/protocols.md): REQUEST_INFO (0x11) with [info], SET_GRAINS (0x13) and STIMULATE
 * (0x14) with the ack [answer] picks (OK by default; null = no answer at all, as after a CRC error). Its answers are
 * encoded by its own [FramedEncoder], the device's side. The fake records the exact bytes written.
 */
class BoardDouble(
    private val info: DeviceInfo? = DeviceInfo(1, 0, 0, 10, 1000, 0, listOf(ChannelUnit.RAW), "hapticon-ref"),
    private val answer: (ReceivedCommand) -> Pair<AckStatus, Int>? = { AckStatus.OK to 0 },
) : SerialPort {
    /** The port underneath: its [FakeSerialPort.writtenBytes] are exactly what the CLI wrote. */
    val fake = FakeSerialPort()
    private val device = FramedEncoder()
    private val pending = ByteArrayOutputStream()

    /** Every command received, in order. */
    val received: MutableList<ReceivedCommand> = CopyOnWriteArrayList()

    override val isOpen: Boolean get() = fake.isOpen

    override fun configure(settings: LineSettings) = fake.configure(settings)

    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int = fake.read(buffer, offset, length, timeoutMillis)

    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        fake.write(buffer, offset, length, timeoutMillis)
        for (i in offset until offset + length) {
            val b = buffer[i]
            if (b.toInt() != 0) {
                pending.write(b.toInt())
                continue
            }
            val frame = cobsDecode(pending.toByteArray())
            pending.reset()
            val command = ReceivedCommand(frame[1].toInt() and 0xFF, (frame[2].toInt() and 0xFF) or ((frame[3].toInt() and 0xFF) shl 8), frame.copyOfRange(4, frame.size - 2).map { it.toInt() and 0xFF })
            received += command
            respond(command)
        }
    }

    private fun respond(command: ReceivedCommand) {
        val out = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        when (command.type) {
            0x11 -> info?.let { fake.enqueue(out.copyOf(device.deviceInfo(it, out))) }
            else -> answer(command)?.let { (status, detail) -> fake.enqueue(out.copyOf(device.ack(command.sequence, status, detail, out))) }
        }
    }

    override fun close() = fake.close()

    companion object {
        /** COBS decoding of one frame without its delimiter (Cheshire and Baker), for the double's side only. */
        fun cobsDecode(encoded: ByteArray): ByteArray {
            val out = ByteArrayOutputStream()
            var i = 0
            while (i < encoded.size) {
                val code = encoded[i].toInt() and 0xFF
                for (j in 1 until code) out.write(encoded[i + j].toInt())
                i += code
                if (code < 0xFF && i < encoded.size) out.write(0)
            }
            return out.toByteArray()
        }

        /** The STIMULATE payloads among [commands] as (electrode, step, duration ms). */
        fun stimuli(commands: List<ReceivedCommand>): List<Triple<Int, Int, Int>> =
            commands.filter { it.type == 0x14 }.map { Triple(it.payload[0], it.payload[1], it.payload[2] or (it.payload[3] shl 8)) }
    }
}

/** Runs `hapticon board ARGS` with [io] in place of the machine's ports and keys, as `runCli` reports its outcome. */
fun boardCli(io: BoardIo, vararg args: String): CliResult {
    val out = ByteArrayOutputStream()
    val err = ByteArrayOutputStream()
    val code = PrintStream(out, true, "UTF-8").use { stdout ->
        PrintStream(err, true, "UTF-8").use { stderr ->
            try {
                runBoard(args.toList(), Console(stdout, stderr), io)
                EXIT_OK
            } catch (e: Throwable) {
                reportFailure(e, stderr, debug = false)
            }
        }
    }
    return CliResult(code, out.toString("UTF-8"), err.toString("UTF-8"))
}
