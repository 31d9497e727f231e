package org.hapticon.gesture.social

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class SocialTouchEvaluationTest {
    /** 3 classes told apart by feature 0 (0, 10, 20 + person offset), 4 people × 10 messages per class. */
    private fun messages(personOffset: Double): TouchMessages {
        val rows = ArrayList<DoubleArray>()
        val labels = ArrayList<Int>()
        val people = ArrayList<String>()
        for (p in 0 until 4) for (c in 0 until 3) for (k in 0 until 10) {
            rows += doubleArrayOf(10.0 * c + personOffset * p + k * 0.1, (k * 7 % 5).toDouble())
            labels += c
            people += "p$p"
        }
        return TouchMessages(rows, labels.toIntArray(), people, 3)
    }

    @Test
    fun crossValidate_tenRunsOfTenFolds_scoresEveryFoldAndEveryMessageTenTimes() {
        val cv = SocialTouchEvaluation.crossValidate(messages(personOffset = 0.0))
        assertEquals(100, cv.values.size)
        assertTrue(cv.values.all { it == 1.0 })
        assertEquals(0.0, cv.sd, 0.0)
        // 120 messages, 40 per class, each tested once per run.
        assertArrayEquals(intArrayOf(400, 0, 0), cv.confusion[0])
        assertArrayEquals(doubleArrayOf(1.0, 1.0, 1.0), cv.perClass(), 0.0)
    }

    @Test
    fun leaveOneTransmitterOut_givesOneAccuracyPerPerson_andPersonOffsetsHurtIt() {
        val clean = SocialTouchEvaluation.leaveOneTransmitterOut(messages(personOffset = 0.0))
        assertEquals(listOf(1.0, 1.0, 1.0, 1.0), clean.values)
        // Each person shifts feature 0 by 6: person 3's class 0 sits where person 1's class 1 is.
        val shifted = messages(personOffset = 6.0)
        val lopo = SocialTouchEvaluation.leaveOneTransmitterOut(shifted)
        val cv = SocialTouchEvaluation.crossValidate(shifted, runs = 2)
        assertEquals(4, lopo.values.size)
        assertTrue("cv ${cv.mean} lopo ${lopo.mean}", cv.mean > lopo.mean)
    }

    @Test
    fun accuracies_meanAndSampleStandardDeviation() {
        val a = Accuracies(listOf(0.5, 0.7, 0.9), arrayOf(intArrayOf(1)))
        assertEquals(0.7, a.mean, 1e-15)
        assertEquals(0.2, a.sd, 1e-15)
        assertEquals(0.0, Accuracies(listOf(0.4), arrayOf(intArrayOf(1))).sd, 0.0)
    }

    @Test
    fun trainTest_scoresOnePersonWithTheOthersModel() {
        val m = messages(personOffset = 0.0)
        assertEquals(1.0, SocialTouchEvaluation.trainTest(m.of("p0"), m.of("p1")), 0.0)
        assertEquals(30, m.of("p2").size)
    }

    @Test
    fun tooFewMessagesOrPeople_isRejected() {
        val one = TouchMessages(List(5) { doubleArrayOf(it.toDouble()) }, IntArray(5) { it % 2 }, List(5) { "p" }, 2)
        assertThrows(IllegalArgumentException::class.java) { SocialTouchEvaluation.crossValidate(one) }
        assertThrows(IllegalArgumentException::class.java) { SocialTouchEvaluation.leaveOneTransmitterOut(one) }
    }
}
