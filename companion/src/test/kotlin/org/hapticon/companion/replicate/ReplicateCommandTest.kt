package org.hapticon.companion.replicate

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli
import org.hapticon.companion.EXIT_OK
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class ReplicateCommandTest {
    /** A replication that prints a fixed line, to test the dispatch alone. */
    private class TestReplication(override val id: String, override val names: List<String> = emptyList()) : Replication {
        override val title: String = "test $id"
        override fun run(out: PrintStream) = out.println("ran $id")
    }

    private fun run(vararg args: String): String {
        val bytes = ByteArrayOutputStream()
        val out = PrintStream(bytes, true, "UTF-8")
        runReplicate(args.toList(), Console(out, out), listOf(TestReplication("001"), TestReplication("002", listOf("glove", "handshake"))))
        return bytes.toString("UTF-8")
    }

    @Test
    fun replicate_byId_runsThatOneWithItsTitle() {
        assertEquals("002 test 002\nran 002\n", run("002"))
    }

    @Test
    fun replicate_byShortName_runsThatOne() {
        assertEquals("002 test 002\nran 002\n", run("handshake"))
        assertEquals("002 test 002\nran 002\n", run("Glove"))
    }

    @Test
    fun replicate_optionsToAReplicationWithoutAny_isAUsageErrorBeforeAnyOutput() {
        try {
            run("001", "--fast")
            fail("accepted")
        } catch (e: UsageException) {
            assertEquals("replicate 001 takes no options, got --fast", e.message)
        }
    }

    @Test
    fun replicate_noId_listsThemWithTheirNames() {
        assertEquals("001  test 001\n002  test 002 (glove, handshake)\n", run())
    }

    @Test
    fun replicate_unknownId_isAUsageError() {
        try {
            run("009")
            fail("accepted")
        } catch (e: UsageException) {
            assertEquals("no replication '009'; try 001, 002|glove|handshake", e.message)
        }
        val result = cli("replicate", "009")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: no replication '009'; try 000|haptic-icons, 001|eit-skin, 002|handshake|glove, 003|shaping-compliance, 004|nao"), result.stderrLines)
    }

    @Test
    fun allReplications_areTheSeedFilesNumbersInOrder() {
        assertEquals(listOf("000", "001", "002", "003", "004"), allReplications.map { it.id })
        assertEquals(
            listOf(HapticIconsReplication::class, SocialTouchReplication::class, HandshakeCalibrationReplication::class, ComplianceGrainsReplication::class, NaoGesturesReplication::class),
            allReplications.map { it::class },
        )
        assertEquals(listOf("haptic-icons", "eit-skin", "handshake", "shaping-compliance", "nao"), allReplications.map { it.names.first() })
    }

    @Test
    fun replicate_shortName_isTheSameAsTheId() {
        val byName = cli("replicate", "shaping-compliance")
        assertEquals(byName.toString(), EXIT_OK, byName.exitCode)
        assertEquals(cli("replicate", "003").stdout, byName.stdout)
        assertTrue(byName.stdout, byName.stdout.startsWith("003 Shaping Compliance"))
    }

    @Test
    fun replicate_withoutId_listsTheReplications() {
        val result = cli("replicate")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        assertTrue(result.stdout, result.stdout.startsWith("000  Haptic icons (Wei et al.)"))
        assertTrue(result.stdout, result.stdout.contains("\n003  Shaping Compliance"))
        assertTrue(result.stdout, result.stdout.contains("\n001  EIT-skin social touch"))
    }
}
