package org.hapticon.gesture.social

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class SocialTouchSyntheticPeopleTest {
    @Test
    fun classes_areSixEmotionsSixSocialMessagesAndNoTouch_eachWithAPrototypeButNoTouch() {
        assertEquals(6, SocialTouchClasses.EMOTIONS.size)
        assertEquals(6, SocialTouchClasses.SOCIAL_MESSAGES.size)
        assertEquals(13, SocialTouchClasses.ALL.toSet().size)
        assertEquals("no-touch", SocialTouchClasses.ALL.last())
        assertEquals(SocialTouchClasses.ALL.dropLast(1).toSet(), SocialTouchSyntheticPeople.PROTOTYPES.keys)
    }

    @Test
    fun messages_everyPersonGivesEveryClassTheRequestedTimes_inShuffledOrder() {
        val messages = SocialTouchSyntheticPeople.messages(people = 3, takesPerClass = 4)
        assertEquals(3 * 4 * 13, messages.size)
        for (person in listOf("p1", "p2", "p3")) for (label in SocialTouchClasses.ALL) {
            assertEquals("$person $label", 4, messages.count { it.person == person && it.label == label })
        }
        // Shuffled: p1's first 13 messages are not the classes in list order.
        assertNotEquals(SocialTouchClasses.ALL, messages.take(13).map { it.label })
        // Frames at 100 Hz, in time order.
        for (m in messages) assertTrue(m.frames.zipWithNext().all { (a, b) -> b.timeSeconds > a.timeSeconds })
    }

    @Test
    fun messages_sameSeed_sameFrames_otherSeed_otherFrames() {
        val a = SocialTouchSyntheticPeople.messages(2, 2, seed = 7)
        val b = SocialTouchSyntheticPeople.messages(2, 2, seed = 7)
        val c = SocialTouchSyntheticPeople.messages(2, 2, seed = 8)
        assertEquals(a.map { it.frames }, b.map { it.frames })
        assertNotEquals(a.map { it.frames }, c.map { it.frames })
    }

    @Test
    fun features_followThePrototypes_touchCountsAndNoTouchZeros() {
        val messages = SocialTouchSyntheticPeople.messages(people = 2, takesPerClass = 3)
        val touches = SocialTouchFeatures.NAMES.indexOf("touch_count")
        for (m in messages) {
            val f = SocialTouchFeatures.of(m.frames.asSequence())
            val prototype = SocialTouchSyntheticPeople.PROTOTYPES[m.label]
            if (prototype == null) {
                assertArrayEquals(m.label, DoubleArray(13), f, 0.0)
                assertEquals((SocialTouchSyntheticPeople.NO_TOUCH_SECONDS * 100).toInt(), m.frames.size)
            } else {
                // Every touch stays in contact (intensity floored above 0), so the count is the prototype's, give or take the slip.
                assertTrue("${m.label} ${f[touches]}", f[touches] in maxOf(1, prototype.touches - 1).toDouble()..(prototype.touches + 1).toDouble())
            }
        }
        // Most messages keep the prototype's count: 1 − TOUCH_COUNT_SLIP of them, and all of a one-touch class that slipped down.
        val kept = messages.filter { it.label != SocialTouchClasses.NO_TOUCH }
            .count { SocialTouchFeatures.of(it.frames.asSequence())[touches] == SocialTouchSyntheticPeople.PROTOTYPES[it.label]!!.touches.toDouble() }
        assertTrue("$kept of 72", kept in 40..64)
    }

    @Test
    fun features_labelsIndexTheGivenList_andAnUnknownClassIsRefused() {
        val labels = SocialTouchClasses.EMOTIONS
        val messages = SocialTouchSyntheticPeople.messages(2, 1, labels = labels)
        val rows = SocialTouchSyntheticPeople.features(messages, labels)
        assertEquals(12, rows.size)
        assertEquals(messages.map { labels.indexOf(it.label) }, rows.labels.toList())
        assertEquals(listOf("p1", "p2"), rows.people.distinct())
        try {
            SocialTouchSyntheticPeople.messages(1, 1, labels = listOf("tickle"))
            fail("accepted an unknown class")
        } catch (e: IllegalArgumentException) {
            assertEquals("unknown classes: [tickle]", e.message)
        }
    }

    @Test
    fun leaveOnePersonOut_thirteenClasses_isFarAboveChanceButNotPerfect() {
        // 4 people × 6 takes × 13 classes: people differ in force, tempo and position, so held-out people are harder.
        val rows = SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.messages(4, 6), SocialTouchClasses.ALL)
        val lopo = SocialTouchEvaluation.leaveOnePersonOut(rows)
        assertTrue("$lopo", lopo > 0.6 && lopo < 1.0)
    }
}
