package org.hapticon.core.pattern

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * Files written by the hand-written JSON writer before the pattern formats moved to kotlinx-serialization
 * (`src/test/resources/recorded/`, written by that build from the two patterns below): this build must read
 * them to the exact values, and write them byte for byte, so files exchanged with earlier builds keep working
 * both ways.
 */
class RecordedPatternFilesTest {
    private val boing = HapticPattern(
        "boing",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.05, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 220.0), FrequencyKey(0.4, 110.0)),
        listOf(Transient(0.1, 0.8, 0.4)),
    )
    private val taps = HapticPattern("taps", emptyList(), listOf(FrequencyKey(0.0, 150.0)), listOf(Transient(0.0, 1.0, 0.5), Transient(0.25, 0.5, 1.0)))

    private fun recorded(name: String): String =
        javaClass.getResourceAsStream("/recorded/$name")!!.use { String(it.readBytes(), Charsets.UTF_8) }

    @Test
    fun write_everyFormat_isByteIdenticalToTheRecordedFiles() {
        for (pattern in listOf(boing, taps)) {
            for (format in PatternFormat.entries) {
                val name = "${pattern.name}.${format.extension}"
                assertEquals(name, recorded(name), PatternFiles.write(pattern, format).text)
            }
        }
    }

    @Test
    fun read_recordedPatternJson_givesTheExactPattern() {
        for (pattern in listOf(boing, taps)) {
            val read = PatternFiles.read(recorded("${pattern.name}.json").toByteArray(), PatternFormat.JSON, "ignored")
            assertEquals(emptyList<String>(), read.notes)
            assertEquals(pattern.name, read.pattern.name)
            assertEquals(pattern.amplitude, read.pattern.amplitude)
            assertEquals(pattern.frequency, read.pattern.frequency)
            assertEquals(pattern.transients, read.pattern.transients)
        }
    }

    @Test
    fun read_recordedAhapAndHaptic_keepTiming1msAndAmplitude1Percent() {
        for (format in listOf(PatternFormat.AHAP, PatternFormat.HAPTIC)) {
            val back = PatternFiles.read(recorded("boing.${format.extension}").toByteArray(), format, "boing").pattern
            for (t in (0..40).map { it * 0.01 }) {
                assertEquals("$format amplitude at $t s", boing.amplitudeAt(t), back.amplitudeAt(t), 0.01)
            }
            assertEquals("$format transients", 1, back.transients.size)
            assertEquals(format.name, 0.1, back.transients.single().time, 0.001)
            // .haptic cannot hold an emphasis weaker than its breakpoint, so the writer raised it to the curve (and noted so).
            val intensity = if (format == PatternFormat.AHAP) 0.8 else kotlin.math.sqrt(boing.amplitudeAt(0.1))
            assertEquals(format.name, intensity, back.transients.single().intensity, 0.01)
        }
        // The recorded AHAP's first curve point, spelled 7.8125E-4 by Double.toString, reads as that exact double.
        assertTrue(recorded("boing.ahap").contains("\"Time\": 7.8125E-4"))
    }
}
