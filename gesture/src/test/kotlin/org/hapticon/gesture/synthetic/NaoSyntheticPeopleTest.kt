package org.hapticon.gesture.synthetic

import org.hapticon.gesture.recognition.NaoPreset
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class NaoSyntheticPeopleTest {
    private val people = NaoSyntheticPeople.sessions(count = 2, seed = 3)

    @Test
    fun eachPerson_performs120Gestures_twoIntensities_fourSensors_threeOfEach() {
        assertEquals(120, NaoSyntheticPeople.PERFORMANCES)
        for (person in people) {
            val spans = person.spans
            assertEquals(120, spans.size)
            // One intensity for the first 60 performances, the other for the next 60 (004_7d5078645d142b2a.txt:152).
            assertEquals(1, spans.take(60).map { it.intensity }.distinct().size)
            assertEquals(1, spans.drop(60).map { it.intensity }.distinct().size)
            assertTrue(spans[0].intensity != spans[60].intensity)
            // Within a half: one sensor at a time, 15 performances each, every sensor once; at a sensor, three rounds
            // of the five gestures, each round every gesture once.
            for (half in spans.chunked(60)) {
                val blocks = half.chunked(15)
                assertEquals(NaoPreset.LOCATIONS.toSet(), blocks.map { it.map { s -> s.location }.distinct().single() }.toSet())
                for (block in blocks) {
                    for (round in block.chunked(5)) assertEquals(NaoPreset.GESTURES.toSet(), round.map { it.gesture }.toSet())
                }
            }
        }
    }

    @Test
    fun eachGesture_touchesOnlyItsOwnSensor_forAtMost5s_with5sBreaks() {
        val rate = NaoPreset.SAMPLE_RATE
        for (person in people) {
            var previousEnd = 0
            for (span in person.spans) {
                assertTrue("$span", span.to - span.from <= (NaoSyntheticPeople.GESTURE_SECONDS * rate).toInt())
                assertTrue("$span", span.from - previousEnd >= (NaoSyntheticPeople.BREAK_SECONDS * rate).toInt())
                previousEnd = span.to
                val own = NaoPreset.LOCATIONS.indexOf(span.location)
                // The touched sensor's resistance falls below its resting level (its lowest tenth of samples, the
                // touches, even a gentle tickle on the tenfold less sensitive shoulder); the others stay within noise
                // and the slow return after their own last release.
                for (c in 0 until NaoPreset.CHANNELS) {
                    val values = person.channels[c].copyOfRange(span.from, span.to).sorted()
                    val rest = person.channels[c].copyOfRange(span.from - 20, span.from).average()
                    val low = values.take(values.size / 10).average() / rest
                    if (c == own) assertTrue("$span channel $c low $low", low < 0.98) else assertTrue("$span channel $c low $low", low > 0.96)
                }
            }
        }
    }

    @Test
    fun restingResistances_followThePapersSensors_shoulderTheLowest() {
        for (person in people) {
            val resting = (0 until NaoPreset.CHANNELS).map { c -> person.channels[c].copyOfRange(0, 100).average() }
            NaoSyntheticPeople.INITIAL_KILOOHMS.forEachIndexed { c, r0 -> assertEquals(r0, resting[c], 0.11 * r0) }
        }
    }

    @Test
    fun sessions_areRepeatableForASeed() {
        val again = NaoSyntheticPeople.sessions(count = 2, seed = 3)
        assertEquals(people.map { it.spans.toString() }, again.map { it.spans.toString() })
        assertTrue(people[0].channels[1].contentEquals(again[0].channels[1]))
    }
}
