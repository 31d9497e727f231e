package org.hapticon.companion

import org.hapticon.companion.cli.IconSource
import org.hapticon.companion.cli.UsageException
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.testing.TestIcons
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

class IconSourceTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun usageError(spec: String): String {
        try {
            IconSource.load(spec)
        } catch (e: UsageException) {
            return e.message!!
        }
        fail("expected a UsageException for $spec")
        throw AssertionError()
    }

    @Test
    fun load_presetName_isThePreset() {
        assertEquals(HapticIcon.HUG, IconSource.load("hug"))
    }

    @Test
    fun load_iconFile_isTheDecodedIcon() {
        for (icon in TestIcons.EDGE_CASES) {
            val file = temp.newFile("${icon.name}.json").also { it.writeText(IconJson.encode(icon, "  ")) }
            assertEquals(icon, IconSource.load(file.path))
        }
    }

    @Test
    fun load_directory_isNotAnIconFile() {
        assertEquals("icon file ${temp.root} is not a regular file", usageError(temp.root.path))
    }

    @Test
    fun load_invalidUtf8_isReportedAsInvalidJson() {
        val file = temp.newFile("bad.json").also { it.writeBytes(byteArrayOf('{'.code.toByte(), 0xC3.toByte(), '}'.code.toByte())) }
        assertEquals("icon file $file is not valid JSON: malformed UTF-8 at offset 1", usageError(file.path))
    }

    @Test
    fun load_fileOverOneMebibyte_isRefusedUnread() {
        val file = temp.newFile("huge.json").also { it.writeBytes(ByteArray((1 shl 20) + 1) { ' '.code.toByte() }) }
        assertEquals("icon file $file is larger than 1048576 bytes", usageError(file.path))
    }

    @Test
    fun load_validJsonButNewerSchemaVersion_namesVersion() {
        val file = temp.newFile("v2.json").also { it.writeText(IconJson.encode(HapticIcon.HIT).replace("\"version\":1", "\"version\":2")) }
        assertEquals(
            "icon file $file is not a valid icon: version: unsupported icon schema version 2 (this build reads version 1)",
            usageError(file.path),
        )
    }
}
