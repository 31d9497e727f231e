package org.hapticon.core.pattern

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class PatternImporterTest {
    private fun error(text: String, fileName: String) =
        assertThrows(PatternImportException::class.java) { PatternImporter.read(text.toByteArray(), fileName) }.message!!

    private fun patternJson(amplitude: String, frequency: String = """[{"time":0,"hertz":150}]""") =
        """{"schema":"hapticon.pattern","version":1,"name":"p","amplitude":$amplitude,"frequency":$frequency}"""

    @Test
    fun read_millionBreakpoints_refusedBySizeBeforeParsing() {
        val keys = (0 until 1_000_000).joinToString(",") { """{"time":$it,"amplitude":0.5}""" }
        val message = error(patternJson("[$keys]"), "huge.json")
        assertTrue(message, message.matches(Regex("huge\\.json: \\d+ bytes is larger than a pattern file may be \\(1048576 bytes\\)")))
    }

    @Test
    fun read_moreKeysThanAPatternMayHold_oneLineNamingTheCurve() {
        val keys = (0 until 5000).joinToString(",") { """{"time":${it * 0.001},"amplitude":0.5}""" }
        assertEquals("many.json: amplitude: has 5000 keys; at most 4096", error(patternJson("[$keys]"), "many.json"))
    }

    @Test
    fun read_overflowingInfiniteAndNegativeNumbers_oneLineNamingTheMember() {
        assertTrue(error(patternJson("""[{"time":0,"amplitude":1e999}]"""), "inf.json").startsWith("inf.json: amplitude[0].amplitude: "))
        assertTrue(error(patternJson("""[{"time":-1,"amplitude":0.5}]"""), "neg.json").startsWith("neg.json: amplitude[0].time: "))
        assertTrue(error(patternJson("""[{"time":0,"amplitude":2}]"""), "loud.json").startsWith("loud.json: amplitude[0].amplitude: must be in [0, 1]"))
        // JSON has no NaN: the parser's own error, still one line naming the file.
        val nan = error(patternJson("""[{"time":NaN,"amplitude":0.5}]"""), "nan.json")
        assertTrue(nan, nan.startsWith("nan.json: ") && '\n' !in nan)
    }

    @Test
    fun read_hostileNestingDuplicatesAndInfinity_inEveryFormat_oneLineNamingFileAndPlace() {
        // The strict reader stays in front of kotlinx-serialization for these (docs/json.md): depth 64, no duplicates.
        val deep = """{"Pattern": """ + "[".repeat(70) + "]".repeat(70) + "}"
        assertEquals("deep.ahap: nesting deeper than 64 levels at offset 75", error(deep, "deep.ahap"))
        assertEquals("dup.ahap: duplicate member name \"Pattern\" at offset 16", error("""{"Pattern": [], "Pattern": []}""", "dup.ahap"))
        assertEquals("inf.json: amplitude[0].amplitude: must be finite", error(patternJson("""[{"time":0,"amplitude":1e999}]"""), "inf.json"))
        assertEquals(
            "inf.ahap: Pattern[0].Event.Time: must be finite",
            error("""{"Pattern": [{"Event": {"Time": 1e999, "EventType": "HapticTransient"}}]}""", "inf.ahap"),
        )
        assertEquals(
            "inf.haptic: version.major: must be finite",
            error("""{"version": {"major": 1e999, "minor": 0, "patch": 0}}""", "inf.haptic"),
        )
        assertEquals("deep.json: nesting deeper than 64 levels at offset 64", error("[".repeat(65) + "]".repeat(65), "deep.json"))
    }

    @Test
    fun read_hugeDurationInAnAhap_refusedByTheSafetyCap() {
        val ahap = """{"Pattern":[{"Event":{"Time":0,"EventType":"HapticContinuous","EventDuration":1e9,"EventParameters":[]}}]}"""
        val message = error(ahap, "long.ahap")
        assertTrue(message, message.startsWith("long.ahap: ") && "30" in message && '\n' !in message)
    }

    @Test
    fun read_noExtension_recognisedByContent() {
        val haptic = """{"version":{"major":1,"minor":0,"patch":0},"signals":{"continuous":{"envelopes":{"amplitude":[""" +
            """{"time":0,"amplitude":0.5},{"time":0.2,"amplitude":0}]}}}}"""
        assertEquals(PatternFormat.HAPTIC, PatternImporter.formatOf("content-1234", haptic.toByteArray()))
        assertEquals(PatternFormat.AHAP, PatternImporter.formatOf("shared", """{"Version":1,"Pattern":[]}""".toByteArray()))
        val imported = PatternImporter.read(haptic.toByteArray(), "content-1234")
        assertEquals("content-1234", imported.pattern.name)
        assertEquals(0.2, imported.pattern.duration, 0.0)
    }

    @Test
    fun read_nameWithLineBreaks_messageStaysOneLine() {
        val message = error("{", "evil\nname.json")
        assertTrue(message, message.startsWith("evil name.json: ") && '\n' !in message)
    }
}
