package org.hapticon.companion.sensors

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.sensor.port.ReplayPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.SensorProtocols
import java.io.BufferedWriter
import java.io.FileInputStream
import java.io.IOException
import java.io.OutputStreamWriter

/**
 * `hapticon decode --protocol csv|lucid|framed --in FILE`: one JSON line per frame, then a stats line, to stdout.
 * The `--protocol` values are [protocols]' CLI names.
 */
fun runDecode(args: List<String>, console: Console, protocols: SensorProtocols = SensorProtocols.DEFAULT) {
    val arguments = Arguments.parse("decode", args, valueOptions = setOf("protocol", "in"))
    arguments.requireNoPositionals()
    val protocol = arguments.choice<SensorProtocol?>("protocol", protocols.cliChoices, null)
        ?: throw UsageException("decode needs --protocol ${protocols.cliChoices.keys.joinToString("|")}")
    val file = InputFiles.existing("in", arguments.required("in"))
    // Not closed: it wraps stdout, which belongs to the caller.
    val out = BufferedWriter(OutputStreamWriter(console.out, Charsets.UTF_8), StreamToJsonLines.READ_BYTES)
    try {
        ReplayPort(FileInputStream(file), intArrayOf(StreamToJsonLines.READ_BYTES)).use { port ->
            StreamToJsonLines.decode(port, protocol, out)
        }
    } catch (e: IOException) {
        // stdout never throws (PrintStream keeps its errors), so this is the input failing.
        throw UsageException("cannot read $file: ${e.message}")
    } finally {
        out.flush()
    }
}
