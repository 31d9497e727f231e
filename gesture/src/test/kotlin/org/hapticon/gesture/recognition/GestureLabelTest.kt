package org.hapticon.gesture.recognition

import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Test

class GestureLabelTest {
    @Test
    fun nineLabelsInIndexOrder() {
        assertEquals(
            listOf("none", "stroke-gentle", "stroke-energetic", "hit-gentle", "hit-energetic", "knock-gentle", "knock-energetic", "hug-gentle", "hug-energetic"),
            GestureLabel.ALL.map { it.id },
        )
        GestureLabel.ALL.forEachIndexed { i, label -> assertEquals(i, label.index) }
        assertEquals(GestureLabel.of(Gesture.KNOCK, Intensity.ENERGETIC), GestureLabel.parse("KNOCK_energetic"))
        assertNull(GestureLabel.NONE.intensity)
    }

    @Test
    fun unknownLabelsAreRejected() {
        assertNull(GestureLabel.parseOrNull("stroke"))
        val e = assertThrows(IllegalArgumentException::class.java) { GestureLabel.parse("pat-gentle") }
        assertEquals(true, e.message!!.startsWith("unknown gesture label 'pat-gentle'"))
    }
}
