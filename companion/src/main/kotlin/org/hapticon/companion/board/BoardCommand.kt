package org.hapticon.companion.board

import java.io.Closeable
import java.io.IOException
import java.io.InputStream
import java.nio.file.InvalidPathException
import java.nio.file.Path
import java.time.Instant
import java.time.temporal.ChronoUnit
import java.util.concurrent.TimeUnit
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.safety.SafetyLimitException

/**
 * What `hapticon board` reaches outside the process, so tests can put a board double and scripted keys in its place:
 * how ports are listed and opened (jSerialComm on a desktop), where keys come from, how long device info may take,
 * and the clock that dates a saved calibration.
 */
class BoardIo(
    /** Lists the serial ports. */
    val listPorts: () -> List<PortListing>,
    /** Opens a port by path with line settings. */
    val openPort: (String, LineSettings) -> SerialPort,
    /** The key source for `calibrate`; closed afterwards (the terminal goes back to line mode). */
    val keys: () -> TerminalKeys,
    /** How long to wait for the board's device info. */
    val infoTimeoutMillis: Long = BoardLink.INFO_TIMEOUT_MILLIS,
    /** The time written into a saved calibration (`calibratedAt`). */
    val clock: () -> Instant = Instant::now,
) {
    companion object {
        /** The real machine: jSerialComm's ports and the terminal's keys. */
        fun desktop(): BoardIo = BoardIo(DesktopSerialPort::list, DesktopSerialPort::open, { TerminalKeys.stdin() })
    }
}

/**
 * Keys from [input], one byte each. [stdin] switches an interactive terminal to one-key mode (`stty -icanon -echo
 * min 1`, restored on [close]) so a key counts without Enter; piped input is read as it is.
 */
class TerminalKeys(private val input: InputStream, private val restore: () -> Unit = {}) : KeyInput, Closeable {
    override fun next(): Int = input.read()

    override fun close() = restore()

    companion object {
        /** System.in, in one-key mode when it is a terminal. */
        fun stdin(): TerminalKeys {
            if (System.console() == null || System.getProperty("os.name").orEmpty().startsWith("Windows")) return TerminalKeys(System.`in`)
            val saved = stty("-g")?.trim().orEmpty()
            if (saved.isEmpty() || stty("-icanon -echo min 1") == null) return TerminalKeys(System.`in`)
            return TerminalKeys(System.`in`) { stty(saved) }
        }

        /** Runs `stty ARGS < /dev/tty`; its output, or null when it failed. */
        private fun stty(args: String): String? = try {
            val process = ProcessBuilder("sh", "-c", "stty $args < /dev/tty").redirectErrorStream(true).start()
            val text = process.inputStream.bufferedReader().readText()
            if (process.waitFor(5, TimeUnit.SECONDS) && process.exitValue() == 0) text else null
        } catch (e: IOException) {
            null
        }
    }
}

/** `hapticon board ports|info|set|calibrate …`: a Hapticon electrotactile board on this computer's serial port. */
fun runBoard(args: List<String>, console: Console, io: BoardIo = BoardIo.desktop()) {
    val sub = args.firstOrNull() ?: throw UsageException("board needs ports, info, set or calibrate")
    val rest = args.drop(1)
    when (sub) {
        "ports" -> listPorts(rest, console, io)
        "info" -> info(rest, console, io)
        "set" -> set(rest, console, io)
        "calibrate" -> calibrate(rest, console, io)
        else -> throw UsageException("unknown board command '$sub': use ports, info, set or calibrate")
    }
}

private fun listPorts(args: List<String>, console: Console, io: BoardIo) {
    Arguments.parse("board ports", args).requireNoPositionals()
    val ports = io.listPorts()
    if (ports.isEmpty()) {
        console.err.println("no serial ports found")
        return
    }
    for (port in ports) console.out.println(port.line())
}

private fun info(args: List<String>, console: Console, io: BoardIo) {
    val arguments = Arguments.parse("board info", args, valueOptions = setOf("port", "baud"))
    arguments.requireNoPositionals()
    val portName = arguments.required("port")
    val baud = baud(arguments)
    connect(io, portName, baud).use { link ->
        val info = link.requestInfo(io.infoTimeoutMillis) ?: throw noInfo(portName, io)
        console.out.println("port: $portName at $baud baud")
        console.out.println("board: ${info.deviceDescription ?: "(no name)"}")
        console.out.println("adc: ${info.adcBits} bits, ${info.sampleRateHz} Hz, ${info.channelCount} channels (${info.channelNames.joinToString(", ")})")
        val range = link.forceRange()
        console.out.println("grain force range: " + (range?.let { "${it.min}..${it.max} (channel ${FirmwareForceRange.GRAIN_CHANNEL}, raw counts)" } ?: "none announced (channel ${FirmwareForceRange.GRAIN_CHANNEL} is not in raw counts): give --range to board set"))
    }
}

private fun set(args: List<String>, console: Console, io: BoardIo) {
    val arguments = Arguments.parse(
        "board set", args,
        valueOptions = setOf("port", "baud", "grains", "shape", "electrodes", "distribution", "ma", "steps", "calibration", "range"),
    )
    arguments.requireNoPositionals()
    val portName = arguments.required("port")
    val baud = baud(arguments)
    // Everything is checked before the port is opened: a refused value never reaches the wire.
    val grains = arguments.value("grains")?.let { it.toIntOrNull() ?: throw UsageException("--grains must be a whole number, got '$it'") }
        ?: throw UsageException("board set needs --grains N (0..99; bins = grains + 1)")
    val pattern = pattern(arguments)
    val stored = arguments.value("calibration")?.let { file ->
        if (arguments.value("ma") != null || arguments.value("steps") != null) throw UsageException("give --calibration FILE or --ma/--steps, not both")
        CalibrationFiles.read(path("calibration", file))
    }
    val steps = stored?.result?.steps ?: steps(arguments)
    val distribution = arguments.choice("distribution", DISTRIBUTIONS, BinDistribution.LINEAR)
    val range = arguments.value("range")?.let(::parseRange)
    // The range is the board's own (its device info) unless given; the full 16-bit span stands in until then, so
    // every other field is checked now, as the firmware will check it.
    val checked = validated { FirmwareGrainParams(grains, distribution, 0, 0xFFFF, pattern, steps) }
    if (stored != null) console.out.println("calibration ${arguments.value("calibration")}: ${describe(stored)}")
    connect(io, portName, baud).use { link ->
        val boardRange = range ?: run {
            link.requestInfo(io.infoTimeoutMillis) ?: throw noInfo(portName, io)
            link.forceRange() ?: throw UsageException("the board announced no raw force range for its grain channel: give --range MIN:MAX")
        }
        val params = validated { checked.copy(minForce = boardRange.min, maxForce = boardRange.max) }
        val outcome = link.send(params)
        console.out.println(outcome.line())
        if (!outcome.accepted) throw UsageException("the board did not take the grain settings")
    }
}

private fun calibrate(args: List<String>, console: Console, io: BoardIo) {
    val arguments = Arguments.parse(
        "board calibrate", args,
        valueOptions = setOf("port", "baud", "range", "save", "participant"), flagOptions = setOf("force"),
    )
    arguments.requireNoPositionals()
    val portName = arguments.required("port")
    val baud = baud(arguments)
    val range = arguments.value("range")?.let(::parseRange)
    val save = arguments.value("save")?.let { path("save", it) }
    val force = arguments.flag("force")
    val participant = arguments.value("participant")
    if (save == null && (force || participant != null)) throw UsageException("--${if (force) "force" else "participant"} only goes with --save FILE")
    participant?.let { CalibrationFile.participantProblem(it) }?.let { throw UsageException("--participant: $it") }
    // Refused before the port is opened: a participant never sits through a calibration that cannot be saved.
    save?.let { CalibrationFiles.checkCanSave(it, force) }
    connect(io, portName, baud).use { link ->
        if (range == null) link.requestInfo(io.infoTimeoutMillis) ?: throw noInfo(portName, io)
        val result = io.keys().use { keys -> CalibrationWalk(link, keys, console.out, range).run() }
            ?: throw UsageException("calibration stopped before the end" + (save?.let { ": nothing written to $it" } ?: ""))
        if (save != null) {
            val stored = StoredCalibration(result, io.clock().truncatedTo(ChronoUnit.SECONDS), participant)
            CalibrationFiles.save(save, stored, force)
            console.out.println("saved $save: ${describe(stored)}")
            console.out.println("use it: hapticon board set --port $portName --grains N --shape SHAPE --calibration $save")
        }
    }
}

/** One line about a stored calibration: who, when, and its steps. */
private fun describe(stored: StoredCalibration): String =
    (stored.participant?.let { "participant $it, " } ?: "") + "calibrated ${stored.calibratedAt}, steps ${stored.result.steps.joinToString(",")}"

private fun path(option: String, text: String): Path = try {
    Path.of(text)
} catch (e: InvalidPathException) {
    throw UsageException("--$option: not a file name: ${e.message}")
}

private fun connect(io: BoardIo, portName: String, baud: Int): BoardLink {
    val port = try {
        io.openPort(portName, LineSettings(baudRate = baud))
    } catch (e: IOException) {
        throw UsageException(e.message ?: "cannot open $portName")
    }
    return BoardLink(port, portName, baud)
}

private fun noInfo(portName: String, io: BoardIo) =
    UsageException("no device info from $portName within ${io.infoTimeoutMillis} ms: not a Hapticon framed board, or another baud rate (--baud)")

private fun baud(arguments: Arguments): Int {
    val baud = arguments.int("baud", DEFAULT_BAUD)
    if (baud !in 300..12_000_000) throw UsageException("--baud must be in 300..12000000, got $baud")
    return baud
}

private fun pattern(arguments: Arguments): ElectrodePattern {
    val shape = arguments.value("shape")
    val electrodes = arguments.value("electrodes")
    if (shape != null && electrodes != null) throw UsageException("give --shape or --electrodes, not both")
    if (electrodes != null) {
        return validated { ElectrodePattern.of(*electrodes.split('/').toTypedArray()) }
    }
    return arguments.choice("shape", SHAPES, ElectrodeMask.LARGE_SQUARE).pattern
}

/** `--ma` (one current for all nine electrodes, or nine) or `--steps` (the same in hardware steps), checked against the cap. */
private fun steps(arguments: Arguments): List<Int> {
    val ma = arguments.value("ma")
    val steps = arguments.value("steps")
    if ((ma == null) == (steps == null)) throw UsageException("board set needs --ma MILLIAMPS or --steps STEPS (one value for all nine electrodes, or nine), or --calibration FILE")
    val values = (ma ?: steps)!!.split(',').map { it.trim() }
    if (values.size != 1 && values.size != NINE) throw UsageException("--${if (ma != null) "ma" else "steps"} needs 1 or 9 values, got ${values.size}")
    val parsed = values.map { text ->
        validated {
            if (ma != null) {
                val milliamps = text.toDoubleOrNull() ?: throw UsageException("--ma values must be numbers, got '$text'")
                AmplitudeSteps.stepAtLeast(milliamps)
            } else {
                AmplitudeSteps.requireStep(text.toIntOrNull() ?: throw UsageException("--steps values must be whole numbers, got '$text'"))
            }
        }
    }
    return if (parsed.size == 1) List(NINE) { parsed[0] } else parsed
}

private fun parseRange(text: String): FirmwareForceRange {
    val parts = text.split(':')
    val min = parts.getOrNull(0)?.toIntOrNull()
    val max = parts.getOrNull(1)?.toIntOrNull()
    if (parts.size != 2 || min == null || max == null) throw UsageException("--range must be MIN:MAX in the force channel's units, got '$text'")
    return validated { FirmwareForceRange(min, max) }
}

/** Runs [block], turning a refused value (a safety limit, a bad field) into the one-line usage error. */
private inline fun <T> validated(block: () -> T): T = try {
    block()
} catch (e: SafetyLimitException) {
    throw UsageException("refused, nothing sent: ${e.message}")
} catch (e: IllegalArgumentException) {
    throw UsageException("refused, nothing sent: ${e.message}")
}

private const val NINE = 9

/** The reference firmware's line speed (`HFP_BAUD` in hapticon_ref.ino). */
private const val DEFAULT_BAUD = 115_200

private val SHAPES: Map<String, ElectrodeMask> = ElectrodeMask.entries.associateBy { it.name.lowercase() }

private val DISTRIBUTIONS: Map<String, BinDistribution> = BinDistribution.entries.associateBy { it.name.lowercase() }
