package org.hapticon.companion

import java.io.ByteArrayOutputStream
import java.io.PrintStream

/** What one in-process `hapticon` run printed and returned. */
class CliResult(val exitCode: Int, val stdout: String, val stderr: String) {
    /** stderr's lines, without the final line break. */
    val stderrLines: List<String> get() = stderr.lines().dropLastWhile { it.isEmpty() }

    override fun toString(): String = "exit $exitCode\n--- stdout\n$stdout--- stderr\n$stderr"
}

/** Runs `hapticon ARGS` through [runCli], capturing both streams as UTF-8. */
fun cli(vararg args: String, debug: Boolean = false): CliResult {
    val out = ByteArrayOutputStream()
    val err = ByteArrayOutputStream()
    val code = PrintStream(out, true, "UTF-8").use { stdout ->
        PrintStream(err, true, "UTF-8").use { stderr -> runCli(arrayOf(*args), stdout, stderr, debug) }
    }
    return CliResult(code, out.toString("UTF-8"), err.toString("UTF-8"))
}
