package org.hapticon.companion

import org.hapticon.companion.cli.UsageException
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class CliTest {
    @Test
    fun help_word_printsUsageToStdoutAndExitsZero() {
        val result = cli("help")
        assertEquals(0, result.exitCode)
        assertEquals(USAGE, result.stdout)
        assertEquals("", result.stderr)
        assertTrue(result.stdout.startsWith("hapticon - render, plot and benchmark haptic icons\n"))
    }

    @Test
    fun help_dashDashHelpAloneOrAfterACommand_printsUsage() {
        assertEquals(USAGE, cli("--help").stdout)
        val afterCommand = cli("render", "--help")
        assertEquals(0, afterCommand.exitCode)
        assertEquals(USAGE, afterCommand.stdout)
    }

    @Test
    fun noArguments_exitsTwoWithOneLine() {
        val result = cli()
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: no command given; try 'hapticon help'"), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun unknownCommand_exitsTwoNamingIt() {
        val result = cli("frobnicate")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: unknown command 'frobnicate'; try 'hapticon help'"), result.stderrLines)
    }

    @Test
    fun icons_printsThePresetsAsIconJson() {
        val result = cli("icons")
        assertEquals(0, result.exitCode)
        assertEquals("", result.stderr)
        assertEquals(EXPECTED_ICONS_JSON, result.stdout)
        assertEquals(HapticIcon.PRESETS, IconJson.decodeList(result.stdout))
    }

    @Test
    fun icons_withAnArgument_exitsTwo() {
        val result = cli("icons", "extra")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: unexpected argument 'extra' for icons"), result.stderrLines)
    }

    @Test
    fun reportFailure_usageMessageWithLineBreak_staysOnOneLine() {
        val err = ByteArrayOutputStream()
        val code = reportFailure(UsageException("cannot write a\nb.wav: oops"), PrintStream(err, true, "UTF-8"), debug = false)
        assertEquals(2, code)
        assertEquals("hapticon: cannot write a b.wav: oops\n", err.toString("UTF-8"))
    }

    @Test
    fun reportFailure_internalError_exitsOneWithOneLineAndNoTrace() {
        val err = ByteArrayOutputStream()
        val code = reportFailure(IllegalStateException("stream ended early\nsecond line"), PrintStream(err, true, "UTF-8"), debug = false)
        assertEquals(1, code)
        assertEquals("hapticon: internal error: IllegalStateException: stream ended early\n", err.toString("UTF-8"))
    }

    @Test
    fun reportFailure_internalErrorInDebug_addsTheStackTrace() {
        val err = ByteArrayOutputStream()
        val code = reportFailure(IllegalStateException("boom"), PrintStream(err, true, "UTF-8"), debug = true)
        assertEquals(1, code)
        val lines = err.toString("UTF-8").lines()
        assertEquals("hapticon: internal error: IllegalStateException: boom", lines[0])
        assertEquals("java.lang.IllegalStateException: boom", lines[1])
        assertTrue(lines[2].trimStart().startsWith("at org.hapticon.companion.CliTest."))
    }

    @Test
    fun reportFailure_exceptionWithoutMessage_namesItsClass() {
        val err = ByteArrayOutputStream()
        reportFailure(NullPointerException(), PrintStream(err, true, "UTF-8"), debug = false)
        assertEquals("hapticon: internal error: java.lang.NullPointerException\n", err.toString("UTF-8"))
    }

    private companion object {
        val EXPECTED_ICONS_JSON = """
            |[
            |  {
            |    "schema": "hapticon.icon",
            |    "version": 1,
            |    "name": "stroke",
            |    "attack": 1,
            |    "sustain": 1,
            |    "level": 0.3,
            |    "release": 1,
            |    "note": 65,
            |    "period": 2.6,
            |    "count": 4
            |  },
            |  {
            |    "schema": "hapticon.icon",
            |    "version": 1,
            |    "name": "hit",
            |    "attack": 0.01,
            |    "sustain": 0.1,
            |    "level": 1,
            |    "release": 0.03,
            |    "note": 57,
            |    "period": 0.2,
            |    "count": 8
            |  },
            |  {
            |    "schema": "hapticon.icon",
            |    "version": 1,
            |    "name": "knock",
            |    "attack": 0.005,
            |    "sustain": 0.01,
            |    "level": 0.5,
            |    "release": 0.005,
            |    "note": 57,
            |    "period": 0.27,
            |    "count": 3
            |  },
            |  {
            |    "schema": "hapticon.icon",
            |    "version": 1,
            |    "name": "hug",
            |    "attack": 1.5,
            |    "sustain": 1,
            |    "level": 0.5,
            |    "release": 0.5,
            |    "note": 50,
            |    "period": 0,
            |    "count": 1
            |  }
            |]
            |""".trimMargin()
    }
}
