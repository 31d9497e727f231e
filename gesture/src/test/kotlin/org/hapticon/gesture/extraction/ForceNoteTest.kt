package org.hapticon.gesture.extraction

import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Test

class ForceNoteTest {
    @Test fun firmAndShortIsHighSoftAndLongIsLow() {
        assertEquals(69, ForceNote.note(1.0, 0.01))
        assertEquals(69, ForceNote.note(2.0, 0.0)) // clamped both ways
        assertEquals(45, ForceNote.note(0.0, 3.0))
        assertEquals(45, ForceNote.note(-1.0, 100.0))
        assertEquals(56, ForceNote.note(0.5, 0.3)) // d = ln(30)/ln(300) = 0.596: 45 + 24·(0.5 + 0.404)/2 = 55.84
    }

    @Test fun firmnessFromNewtonsOrANormalisedChannel() {
        assertEquals(0.25, ForceNote.firmnessOf(5.0, "N")!!, 0.0)
        assertEquals(1.0, ForceNote.firmnessOf(50.0, "N")!!, 0.0)
        assertEquals(0.4, ForceNote.firmnessOf(0.4, "")!!, 0.0)
        assertNull(ForceNote.firmnessOf(3.0, "V"))
        assertThrows(IllegalArgumentException::class.java) { ForceNote.note(Double.NaN, 1.0) }
        assertThrows(IllegalArgumentException::class.java) { ForceNote.note(0.5, -1.0) }
    }
}
