package org.hapticon.companion

import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.io.IOException

class OutputFilesTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun write_success_leavesTheBytes() {
        val file = File(temp.root, "a.bin")
        OutputFiles.write(file) { it.write(byteArrayOf(1, 2, 3)) }
        assertEquals(listOf<Byte>(1, 2, 3), file.readBytes().toList())
    }

    @Test
    fun write_ioErrorPartWay_reportsTheFileAndDeletesIt() {
        val file = File(temp.root, "partial.wav")
        try {
            OutputFiles.write(file) {
                it.write(ByteArray(100))
                throw IOException("No space left on device")
            }
            fail("expected a UsageException")
        } catch (e: UsageException) {
            assertEquals("cannot write $file: No space left on device", e.message)
        }
        assertFalse(file.exists())
    }

    @Test
    fun ensureDirectory_missingNestedDirectory_isCreated() {
        val dir = File(temp.root, "a/b/c")
        OutputFiles.ensureDirectory(dir)
        assertTrue(dir.isDirectory)
    }

    @Test
    fun ensureDirectory_pathIsAFile_isAUsageError() {
        val file = temp.newFile("plain")
        try {
            OutputFiles.ensureDirectory(file)
            fail("expected a UsageException")
        } catch (e: UsageException) {
            assertEquals("cannot write into $file: it is not a directory", e.message)
        }
    }
}
