package org.hapticon.core.pattern

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.double
import kotlinx.serialization.json.jsonPrimitive
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.abs

class AhapTest {
    // Shaped like Apple's "Boing" sample from its Haptic Sampler, including the trailing commas Apple's files have.
    private val boing = """
        {
          "Version": 1.0,
          "Metadata": { "Project": "Haptic Sampler", },
          "Pattern": [
            { "Event": { "Time": 0.0, "EventType": "HapticTransient",
                "EventParameters": [ { "ParameterID": "HapticIntensity", "ParameterValue": 0.8 },
                                     { "ParameterID": "HapticSharpness", "ParameterValue": 0.4 }, ] } },
            { "Event": { "Time": 0.015, "EventType": "HapticContinuous", "EventDuration": 0.25,
                "EventParameters": [ { "ParameterID": "HapticIntensity", "ParameterValue": 0.8 },
                                     { "ParameterID": "HapticSharpness", "ParameterValue": 0.4 } ] } },
            { "ParameterCurve": { "ParameterID": "HapticIntensityControl", "Time": 0.015,
                "ParameterCurveControlPoints": [ { "Time": 0, "ParameterValue": 1 },
                                                 { "Time": 0.1, "ParameterValue": 0.5 },
                                                 { "Time": 0.25, "ParameterValue": 0.0 } ] } },
            { "ParameterCurve": { "ParameterID": "HapticSharpnessControl", "Time": 0.015,
                "ParameterCurveControlPoints": [ { "Time": 0, "ParameterValue": 0.0 },
                                                 { "Time": 0.25, "ParameterValue": -0.3 } ] } },
            { "Event": { "Time": 0.3, "EventType": "AudioCustom", "EventWaveformPath": "boing.wav" } },
          ]
        }
    """.trimIndent().toByteArray()

    @Test
    fun read_appleSample_flattensEventsAndCurves() {
        val (pattern, notes) = Ahap.read(boing, "boing")
        assertEquals(listOf(Transient(0.0, 0.8, 0.4)), pattern.transients)
        // amplitude = (intensity · control)²: 0.64 at the start, (0.8·0.5)² = 0.16 at 0.115 s, 0 at the end.
        assertEquals(0.0, pattern.amplitudeAt(0.01), 0.0)
        assertEquals(0.64, pattern.amplitudeAt(0.015), 1e-12)
        assertEquals(0.16, pattern.amplitudeAt(0.115), 1e-12)
        assertEquals(0.0, pattern.amplitudeAt(0.265), 1e-12)
        // Between control points the squared curve is kept within the 0.002 tolerance.
        for (i in 0..100) {
            val t = 0.015 + 0.1 * i / 100
            val intensity = 0.8 * (1.0 - 0.5 * (t - 0.015) / 0.1)
            assertEquals(intensity * intensity, pattern.amplitudeAt(t), 0.0021)
        }
        // Sharpness 0.4 + control: 0.4 at the start, 0.1 at the end.
        assertEquals(FrequencyMapping.DEFAULT.hertzOfSharpness(0.4), pattern.frequencyAt(0.015), 1e-9)
        assertEquals(FrequencyMapping.DEFAULT.hertzOfSharpness(0.1), pattern.frequencyAt(0.265), 1e-9)
        assertEquals(listOf("AudioCustom event at 0.300 s dropped: Hapticon plays haptics only"), notes)
    }

    @Test
    fun read_trailingCommas_onlyAcceptedForAhap() {
        assertThrows(JsonException::class.java) { MetaHaptic.read("""{"version": {"major": 1, "minor": 0, "patch": 0,}}""".toByteArray(), "x") }
    }

    @Test
    fun read_problems_nameTheMember() {
        fun error(pattern: String) = assertThrows(PatternException::class.java) {
            Ahap.read("""{"Pattern": [$pattern]}""".toByteArray(), "x")
        }.message
        assertEquals("Pattern[0].Event.EventDuration: missing", error("""{"Event": {"Time": 0, "EventType": "HapticContinuous"}}"""))
        assertEquals("Pattern[0].Event.EventType: unknown event type \"HapticBuzz\"", error("""{"Event": {"Time": 0, "EventType": "HapticBuzz"}}"""))
        assertEquals("Pattern[0].Event.Time: must be >= 0 seconds, was -1.0", error("""{"Event": {"Time": -1, "EventType": "HapticTransient"}}"""))
        assertTrue(error("""{"Parameter": {"ParameterID": "HapticIntensityControl", "Time": 0, "ParameterValue": 2}}""")!!
            .startsWith("Pattern[0].Parameter.ParameterValue: HapticIntensityControl must be in"))
        assertEquals("AHAP: expected an object, got [1]", assertThrows(PatternException::class.java) { Ahap.read("[1]".toByteArray(), "x") }.message)
    }

    @Test
    fun read_parameterStep_andAttackRelease() {
        val (pattern, _) = Ahap.read("""{"Pattern": [
            {"Event": {"Time": 0, "EventType": "HapticContinuous", "EventDuration": 1.0, "EventParameters": [
                {"ParameterID": "HapticIntensity", "ParameterValue": 1.0}, {"ParameterID": "AttackTime", "ParameterValue": 0.2},
                {"ParameterID": "ReleaseTime", "ParameterValue": 0.4}]}},
            {"Parameter": {"ParameterID": "HapticIntensityControl", "Time": 0.5, "ParameterValue": 0.5}}
        ]}""".toByteArray(), "x")
        assertEquals(0.25, pattern.amplitudeAt(0.1), 0.002)
        assertEquals(1.0, pattern.amplitudeAt(0.4), 1e-12)
        assertEquals(0.25, pattern.amplitudeAt(0.5), 1e-12) // the step to 0.5 intensity at 0.5 s
        assertEquals(1.0, pattern.amplitudeAt(0.4999), 1e-3)
        assertEquals(0.0625, pattern.amplitudeAt(0.8), 1e-12) // (0.5 · 0.5)²
    }

    @Test
    fun roundTrip_everyPreset_keepsTiming1msAndAmplitude1Percent() {
        for (icon in HapticIcon.PRESETS) {
            val original = icon.toPattern()
            val export = Ahap.write(original)
            val back = Ahap.read(export.text.toByteArray(), icon.name).pattern
            assertEquals(icon.name, emptyList<String>(), export.notes)
            assertSameShape(original, back)
        }
    }

    @Test
    fun write_longCurve_splitsIntoCurvesOf16PointsThatJoin() {
        val keys = (0..40).map { AmplitudeKey(it * 0.01, (it % 5) / 5.0) }
        val pattern = HapticPattern("saw", keys, listOf(FrequencyKey(0.0, 200.0)))
        val text = Ahap.write(pattern).text
        val curves = (Json.decode(text) as JsonObject)["Pattern"].let { it as JsonArray }
            .mapNotNull { (it as JsonObject)["ParameterCurve"] as JsonObject? }
        assertTrue(curves.size > 2)
        var previousEnd: Double? = null
        for (curve in curves.filter { it["ParameterID"] == JsonPrimitive("HapticIntensityControl") }) {
            val points = curve["ParameterCurveControlPoints"] as JsonArray
            assertTrue(points.size in 2..Ahap.MAX_CURVE_POINTS)
            val start = curve["Time"]!!.jsonPrimitive.double
            previousEnd?.let { assertEquals(it, start, 1e-12) } // each curve starts where the last one ended
            previousEnd = start + (points.last() as JsonObject)["Time"]!!.jsonPrimitive.double
        }
        assertSameShape(pattern, Ahap.read(text.toByteArray(), "saw").pattern)
    }

    companion object {
        fun assertSameShape(expected: HapticPattern, actual: HapticPattern) {
            val end = maxOf(expected.duration, actual.duration)
            for (i in 0..2000) {
                val t = end * i / 2000
                // Timing within 1 ms: the value must be matched by the other curve somewhere within ±1 ms.
                val a = expected.amplitudeAt(t)
                val near = (-10..10).map { actual.amplitudeAt(maxOf(0.0, t + it * 1e-4)) }
                assertTrue("${expected.name} amplitude at $t: $a, got ${actual.amplitudeAt(t)}", near.any { abs(it - a) <= 0.01 })
                if (a > 0) assertEquals("${expected.name} frequency at $t", expected.frequencyAt(t), actual.frequencyAt(t), expected.frequencyAt(t) * 0.01)
            }
            assertEquals(expected.transients.size, actual.transients.size)
            expected.transients.zip(actual.transients).forEach { (e, a) ->
                assertEquals(e.time, a.time, 0.001)
                assertEquals(e.intensity, a.intensity, 0.01)
                assertEquals(e.sharpness, a.sharpness, 0.01)
            }
        }
    }
}
