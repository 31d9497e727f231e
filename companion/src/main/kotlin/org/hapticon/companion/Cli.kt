package org.hapticon.companion

import org.hapticon.companion.board.runBoard
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.chat.runBroker
import org.hapticon.companion.chat.runChat
import org.hapticon.companion.gesture.runClassify
import org.hapticon.companion.gesture.runClassifyBench
import org.hapticon.companion.gesture.runTrain
import org.hapticon.companion.gesture.runFit
import org.hapticon.companion.gesture.runFitBench
import org.hapticon.companion.replicate.runReplicate
import org.hapticon.companion.sensors.runDecode
import org.hapticon.companion.sensors.runGrains
import org.hapticon.companion.sensors.runHandshake
import org.hapticon.companion.study.runSchedule
import org.hapticon.companion.study.runStudyProtocol
import org.hapticon.companion.study.runAnalyze
import org.hapticon.companion.study.runCollect
import java.io.PrintStream

/** Exit status for success. */
const val EXIT_OK: Int = 0

/** Exit status for an unexpected internal error. */
const val EXIT_INTERNAL_ERROR: Int = 1

/** Exit status for a usage or validation error: the user can fix the command line or the input. */
const val EXIT_USAGE: Int = 2

/**
 * Runs one `hapticon` command in-process and returns its exit status: [EXIT_OK], [EXIT_USAGE] with one line
 * on [stderr] for a user mistake, or [EXIT_INTERNAL_ERROR] with one line (and the stack trace when [debug])
 * for anything unexpected. Never throws and never exits the JVM, so tests can call it directly.
 */
fun runCli(
    args: Array<String>,
    stdout: PrintStream,
    stderr: PrintStream,
    debug: Boolean = System.getenv("HAPTICON_DEBUG") == "1",
): Int {
    return try {
        dispatch(args.toList(), Console(stdout, stderr))
        EXIT_OK
    } catch (e: Throwable) {
        // Catch everything: a tool must report, not die with a raw trace, even on an Error.
        reportFailure(e, stderr, debug)
    } finally {
        stdout.flush()
        stderr.flush()
    }
}

/**
 * Prints one line about [failure] on [stderr] and returns the exit status: [EXIT_USAGE] for a
 * [UsageException], else [EXIT_INTERNAL_ERROR], followed by the stack trace when [debug].
 */
fun reportFailure(failure: Throwable, stderr: PrintStream, debug: Boolean): Int {
    if (failure is UsageException) {
        // One line even if a message quotes input holding a line break (a file name, say).
        stderr.println("hapticon: ${failure.message.orEmpty().replace(Regex("[\\r\\n]+"), " ")}")
        return EXIT_USAGE
    }
    stderr.println("hapticon: internal error: ${oneLine(failure)}")
    if (debug) failure.printStackTrace(stderr)
    return EXIT_INTERNAL_ERROR
}

private fun dispatch(args: List<String>, console: Console) {
    val command = args.firstOrNull() ?: throw UsageException("no command given; try 'hapticon help'")
    val rest = args.drop(1)
    // --help anywhere asks for help rather than running the command.
    if (command in HELP_WORDS || rest.any { it == "--help" || it == "-h" }) {
        console.out.print(USAGE)
        return
    }
    when (command) {
        "icons" -> runIcons(rest, console)
        "replicate" -> runReplicate(rest, console)
        "render" -> runRender(rest, console)
        "convert" -> runConvert(rest, console)
        "plot" -> runPlot(rest, console)
        "bench" -> runBench(rest, console)
        "demo" -> runDemo(rest, console)
        "decode" -> runDecode(rest, console)
        "grains" -> runGrains(rest, console)
        "handshake" -> runHandshake(rest, console)
        "board" -> runBoard(rest, console)
        "chat" -> runChat(rest, console)
        "broker" -> runBroker(rest, console)
        "schedule" -> runSchedule(rest, console)
        "study-protocol" -> runStudyProtocol(rest, console)
        "analyze" -> runAnalyze(rest, console)
        "collect" -> runCollect(rest, console)
        "classify-bench" -> runClassifyBench(rest, console)
        "train" -> runTrain(rest, console)
        "classify" -> runClassify(rest, console)
        "fit" -> runFit(rest, console)
        "fit-bench" -> runFitBench(rest, console)
        "replicate" -> org.hapticon.companion.replicate.runReplicate(rest, console)
        "compliance-schedule" -> org.hapticon.companion.study.runComplianceSchedule(rest, console)
        "compliance-analysis" -> org.hapticon.companion.study.runComplianceAnalysis(rest, console)
        else -> throw UsageException("unknown command '$command'; try 'hapticon help'")
    }
}

private val HELP_WORDS = setOf("help", "--help", "-h")

/** The exception's class and message on one line. */
private fun oneLine(e: Throwable): String {
    val message = e.message?.lineSequence()?.firstOrNull()?.trim()
    return if (message.isNullOrEmpty()) e.javaClass.name else "${e.javaClass.simpleName}: $message"
}
