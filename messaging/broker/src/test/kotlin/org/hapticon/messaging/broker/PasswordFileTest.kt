package org.hapticon.messaging.broker

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.nio.file.Files
import java.nio.file.attribute.PosixFilePermissions

class PasswordFileTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun matches_lineWrittenByMosquittoPasswd_acceptsOnlyItsPassword() {
        // `mosquitto_passwd -c -b pw alice secret`, Mosquitto 2.0.11 (Debian 12): PBKDF2-SHA512, 101 rounds.
        val hash = "\$7\$101\$5sjkkXotgL1CUtY/\$T4q6Z3YDWFhdWOvYC/IqfiNKU1P/KOPs/NDq9mHqhj2cAvCnLbRX4MP1JWIhDT9LtOE5q1JNF5/XDk/ezzTsAA=="
        assertTrue(PasswordFile.matches(hash, "secret".toByteArray()))
        assertFalse(PasswordFile.matches(hash, "secreT".toByteArray()))
        assertFalse(PasswordFile.matches(hash, ByteArray(0)))
    }

    @Test
    fun matches_mosquittoSha512Line_acceptsItsPassword() {
        // Mosquitto 1.x "$6$": SHA-512(password ‖ salt); this salt is base64 of "saltsalt12ab".
        val salt = "saltsalt12ab".toByteArray()
        val digest = java.security.MessageDigest.getInstance("SHA-512").apply { update("pw".toByteArray()); update(salt) }.digest()
        val b64 = java.util.Base64.getEncoder()
        val hash = "\$6\$${b64.encodeToString(salt)}\$${b64.encodeToString(digest)}"
        assertTrue(PasswordFile.matches(hash, "pw".toByteArray()))
        assertFalse(PasswordFile.matches(hash, "pW".toByteArray()))
    }

    @Test
    fun matches_garbageAndUnknownFormats_letNobodyIn() {
        val garbage = listOf("", "plain", "\$7\$x\$a\$b", "\$7\$101\$!!!\$!!!", "\$7\$0\$AAAA\$AAAA", "\$7\$999999999\$AAAA\$AAAA", "\$argon2id\$v=19\$m=65536,t=3,p=4\$abc\$def", "\$6\$only")
        assertEquals(emptyList<String>(), garbage.filter { PasswordFile.matches(it, "".toByteArray()) || PasswordFile.matches(it, "x".toByteArray()) })
    }

    @Test
    fun add_thenVerify_writesAMode600FileThatAnotherInstanceReads() {
        val file = File(temp.root, "sub/passwd")
        val writer = PasswordFile(file)
        writer.add("alice", "a-secret".toCharArray(), iterations = 1_000)
        writer.add("bob", "b-secret".toCharArray(), iterations = 1_000)
        writer.add("alice", "new-secret".toCharArray(), iterations = 1_000) // replaces alice's line
        val reader = PasswordFile(file)
        assertEquals(listOf("alice", "bob"), reader.users())
        assertTrue(reader.verify("alice", "new-secret".toByteArray()))
        assertFalse(reader.verify("alice", "a-secret".toByteArray()))
        assertTrue(reader.verify("bob", "b-secret".toByteArray()))
        assertFalse(reader.verify("carol", "b-secret".toByteArray()))
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file.toPath())))
        assertEquals(2, file.readLines().size)
        assertTrue(file.readLines()[1].startsWith("alice:\$7\$1000\$"))
    }

    @Test
    fun verify_fileChangedOnDisk_seesTheNewUserWithoutARestart() {
        val file = File(temp.root, "passwd")
        val broker = PasswordFile(file)
        assertFalse(broker.verify("carol", "c".toByteArray()))
        PasswordFile(file).add("carol", "c".toCharArray(), iterations = 1_000)
        assertTrue(broker.verify("carol", "c".toByteArray()))
        // A new password of the same length, at once: the old one stops working.
        PasswordFile(file).add("carol", "d".toCharArray(), iterations = 1_000)
        assertFalse(broker.verify("carol", "c".toByteArray()))
        assertTrue(broker.verify("carol", "d".toByteArray()))
    }

    @Test
    fun hash_defaultIterations_areOwaspsFigureAndSaltIsRandom() {
        val a = PasswordFile.hash("pw".toCharArray(), iterations = 5)
        val b = PasswordFile.hash("pw".toCharArray(), iterations = 5)
        assertTrue(a != b)
        assertTrue(PasswordFile.matches(a, "pw".toByteArray()) && PasswordFile.matches(b, "pw".toByteArray()))
        assertEquals(16, a.split('$')[3].length) // 12 salt bytes in base64, as Mosquitto's SALT_LEN
        assertEquals(210_000, PasswordFile.DEFAULT_ITERATIONS)
    }
}
