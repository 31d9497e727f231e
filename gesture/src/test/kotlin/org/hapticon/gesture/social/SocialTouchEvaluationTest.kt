package org.hapticon.gesture.social

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class SocialTouchEvaluationTest {
    /** 3 classes told apart by feature 0 (0, 10, 20 ± person offset), 4 people × 10 messages per class. */
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
    fun separableClasses_scorePerfectlyBothWays() {
        val m = messages(personOffset = 0.0)
        assertEquals(1.0, SocialTouchEvaluation.crossValidate(m), 0.0)
        assertEquals(1.0, SocialTouchEvaluation.leaveOnePersonOut(m), 0.0)
    }

    @Test
    fun personOffsets_hurtLeaveOnePersonOutMoreThanCrossValidation() {
        // Each person shifts feature 0 by 6 per person: person 3's class 0 sits where person 0's class 1 is (18 vs 10..11).
        val m = messages(personOffset = 6.0)
        val cv = SocialTouchEvaluation.crossValidate(m, runs = 2)
        val lopo = SocialTouchEvaluation.leaveOnePersonOut(m)
        assertTrue("cv $cv lopo $lopo", cv > lopo)
    }

    @Test
    fun tooFewMessagesOrPeople_isRejected() {
        val one = TouchMessages(List(5) { doubleArrayOf(it.toDouble()) }, IntArray(5) { it % 2 }, List(5) { "p" }, 2)
        assertThrows(IllegalArgumentException::class.java) { SocialTouchEvaluation.crossValidate(one) }
        assertThrows(IllegalArgumentException::class.java) { SocialTouchEvaluation.leaveOnePersonOut(one) }
    }
}
