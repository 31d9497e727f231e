package org.hapticon.gesture.social

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class SocialTouchSyntheticPeopleTest {
    @Test
    fun classes_areThePapersSixEmotionsSixSocialMessagesAndNoTouch() {
        // 001_e790093bbd2e3cd3.txt:146 and :152, in the paper's order.
        assertEquals(listOf("anger", "fear", "happiness", "sadness", "disgust", "surprise"), SocialTouchClasses.EMOTIONS)
        assertEquals(listOf("attention-getting", "greeting", "acceptance", "rejection", "affection", "animosity"), SocialTouchClasses.SOCIAL_MESSAGES)
        assertEquals(13, SocialTouchClasses.ALL.toSet().size)
        assertEquals(7, SocialTouchClasses.EMOTION_SET.size)
        assertEquals(7, SocialTouchClasses.MESSAGE_SET.size)
        assertEquals(SocialTouchClasses.ALL.dropLast(1).toSet(), SocialTouchSyntheticPeople.PROTOTYPES.keys)
    }

    @Test
    fun experiment1_twoTransmitters_650TouchesEach_fiftyPerClass_shuffled() {
        val messages = SocialTouchSyntheticPeople.experiment1()
        assertEquals(1300, messages.size)
        for (person in listOf("A", "B")) {
            assertEquals(650, messages.count { it.person == person })
            for (label in SocialTouchClasses.ALL) assertEquals(50, messages.count { it.person == person && it.label == label })
        }
        assertNotEquals(SocialTouchClasses.ALL, messages.take(13).map { it.label })
    }

    @Test
    fun experiment2_fortyTwoTransmitters_2730Touches_fivePerClass() {
        val messages = SocialTouchSyntheticPeople.experiment2()
        assertEquals(2730, messages.size)
        assertEquals(42, messages.map { it.person }.distinct().size)
        assertTrue(messages.groupBy { it.person to it.label }.values.all { it.size == 5 })
    }

    @Test
    fun frames_are40HzOn729Elements_andRegenerateIdentically() {
        val m = SocialTouchSyntheticPeople.messages(1, 1, seed = 7).first()
        val a = m.frames().toList()
        val b = m.frames().toList()
        assertEquals(729, SocialTouchSyntheticPeople.LAYOUT.size)
        assertTrue(a.all { it.elements.size == 729 })
        assertEquals(a.map { it.timeSeconds }, a.indices.map { it / 40.0 })
        assertEquals(a.map { it.elements.toList() to it.joint }, b.map { it.elements.toList() to it.joint })
        val other = SocialTouchSyntheticPeople.messages(1, 1, seed = 8).first { it.label == m.label }
        assertNotEquals(a.map { it.elements.toList() }, other.frames().map { it.elements.toList() }.toList())
    }

    @Test
    fun features_noTouchIsBelowTheThreshold_everyOtherMessageHasATouch() {
        val rows = SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.messages(people = 3, takesPerClass = 2), SocialTouchClasses.ALL)
        val noTouch = SocialTouchClasses.ALL.indexOf(SocialTouchClasses.NO_TOUCH)
        for (i in 0 until rows.size) {
            if (rows.labels[i] == noTouch) assertArrayEquals(DoubleArray(13), rows.features[i], 0.0)
            else assertTrue("${SocialTouchClasses.ALL[rows.labels[i]]} ${rows.features[i][12]}", rows.features[i][12] >= 1.0)
        }
    }

    @Test
    fun features_followWhatThePaperSaysOfTheClasses() {
        val rows = SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.experiment2(), SocialTouchClasses.ALL)
        fun mean(label: String, feature: String): Double {
            val c = SocialTouchClasses.ALL.indexOf(label)
            val k = SocialTouchFeatures.NAMES.indexOf(feature)
            return rows.labels.indices.filter { rows.labels[it] == c }.map { rows.features[it][k] }.average()
        }
        // Highest pressures for anger and fear (:286); largest displacements for sadness and fear (:287).
        val emotions = SocialTouchClasses.EMOTIONS
        assertEquals(setOf("anger", "fear"), emotions.sortedByDescending { mean(it, "max_intensity") }.take(2).toSet())
        assertEquals(setOf("sadness", "fear"), emotions.sortedByDescending { mean(it, "displacement") }.take(2).toSet())
        // Shortest durations for surprise, disgust and anger (:289).
        assertEquals(setOf("surprise", "disgust", "anger"), emotions.sortedBy { mean(it, "duration_s") }.take(3).toSet())
        // Attention at the shoulder (x > 0), greeting and rejection near the hand (x < 0) (:290); all on the outside (:288).
        assertTrue(mean("attention-getting", "x") > 0.5)
        assertTrue(mean("greeting", "x") < -0.5 && mean("rejection", "x") < -0.5)
        assertTrue(SocialTouchClasses.ALL.dropLast(1).all { mean(it, "y") > 0.0 })
    }

    @Test
    fun features_labelsIndexTheGivenList_othersAreLeftOut_andAnUnknownClassIsRefused() {
        val rows = SocialTouchSyntheticPeople.features(SocialTouchSyntheticPeople.messages(2, 1), SocialTouchClasses.MESSAGE_SET)
        assertEquals(14, rows.size)
        assertEquals(7, rows.classCount)
        assertEquals(listOf("p1", "p2"), rows.people.distinct())
        try {
            SocialTouchSyntheticPeople.messages(1, 1, labels = listOf("tickle"))
            fail("accepted an unknown class")
        } catch (e: IllegalArgumentException) {
            assertEquals("unknown classes: [tickle]", e.message)
        }
    }
}
