package org.hapticon.study.log

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonPrimitive
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * `recorded/study-log-v1.txt` was written by the hand-written JSON writer (before the move to kotlinx-serialization):
 * one line per entry, its canonical form, a tab, its hash (each re-checked with Python's hashlib). Logs already on
 * phones and in exports must keep verifying, and new entries must be spelled as before.
 */
class RecordedLogTest {
    private val lines: List<Pair<String, String>> =
        javaClass.getResource(RecordedLogFixture.RESOURCE)!!.readText(Charsets.UTF_8).lines().filter { it.isNotEmpty() }
            .map { it.substringBefore('\t') to it.substringAfter('\t') }

    private fun stored(): List<LogEntry> = lines.map { (canonical, hash) ->
        val f = Json.parseToJsonElement(canonical).jsonArray.map { it.jsonPrimitive.content }
        LogEntry(f[0].toLong(), f[1].toLong(), f[2], f[3], f[4], f[5], hash)
    }

    @Test
    fun recordedLog_verifiesAndDecodesToTheSameEvents() {
        val entries = stored()
        assertEquals(RecordedLogFixture.EVENTS.size, entries.size)
        assertEquals(ChainVerification.Intact, entries.verifyChain())
        assertEquals(RecordedLogFixture.EVENTS.map { it.first }, entries.map { it.event })
        assertEquals(List(entries.size) { RecordedLogFixture.PARTICIPANT }, entries.map { it.participantId })
    }

    @Test
    fun thisBuild_writesTheRecordedBytes() {
        val written = RecordedLogFixture.write()
        for ((index, entry) in written.withIndex()) {
            val canonical = LogEntry.canonicalForm(entry.sequence, entry.timestampMillis, entry.participantId, entry.type, entry.payload, entry.previousHash)
            assertEquals("entry $index", lines[index].first, canonical)
            assertEquals("entry $index", lines[index].second, entry.hash)
        }
        assertEquals(stored(), written)
    }

    @Test
    fun recordedLine_spellsTheEscapesOfTheOldWriter() {
        // Pinned so that a regenerated fixture cannot silently drop them: U+2028 escaped, DEL and '/' raw.
        assertEquals(
            "[\"2\",\"1700000000200\",\"P\\u2028\\\"07\\\\E\",\"stimulus_shown\"," +
                "\"{\\\"task\\\":\\\"t\\\\u2028ä\\\\t\\\\n\\\",\\\"stimulus\\\":\\\"s\\\\u0001\\\\u001f\u007f\\\\b\\\\f\\\\r😀\\\"}\"," +
                "\"f697ea712d91e576e936f884cb744250ad21b9e1b3572c73a366c6749898de38\"]",
            lines[2].first,
        )
    }
}

/** [LogEntry.canonicalJson] spells strings exactly as the hand-written writer of earlier builds did. */
class CanonicalJsonTest {
    @Test
    fun everySpecialCharacter_isEscapedAsTheOldWriterDid() {
        // The old writer's own test (JsonTest.encode_specialCharacters_areEscaped) pinned this spelling.
        val text = "\"\\\b\u000C\n\r\t\u0001\u001f\u007F\u2028\u2029/é😀"
        assertEquals(
            "[\"\\\"\\\\\\b\\f\\n\\r\\t\\u0001\\u001f\u007F\\u2028\\u2029/é😀\"]",
            LogEntry.canonicalJson(kotlinx.serialization.json.JsonArray(listOf(kotlinx.serialization.json.JsonPrimitive(text)))),
        )
    }

    @Test
    fun integersAndNesting_areCompact() {
        val payload = StudyEvent.payload(StudyEvent.SessionStarted("p\u2028", -2, Int.MAX_VALUE, 5))
        assertEquals("""{"protocol":"p\u2028","revision":-2,"participantIndex":2147483647,"seed":"5"}""", LogEntry.canonicalJson(payload))
    }

    @Test
    fun unpairedSurrogate_isRefusedAsBefore() {
        for (text in listOf("a\uD83D", "\uDE00b", "\uDE00\uD83D")) {
            val e = org.junit.Assert.assertThrows(IllegalArgumentException::class.java) {
                LogEntry.canonicalForm(0, 0, text, "t", "{}", LogEntry.GENESIS_HASH)
            }
            assertTrue(e.message!!.startsWith("unpaired surrogate at index"))
        }
    }
}
