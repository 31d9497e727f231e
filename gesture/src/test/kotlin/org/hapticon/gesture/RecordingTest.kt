package org.hapticon.gesture

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class RecordingTest {
    @Test fun requireChannelFindsByNameOrTakesTheFirst() {
        val recording = Recording(100.0, listOf(Channel("force", "N", doubleArrayOf(1.0)), Channel("bend", "deg", doubleArrayOf(2.0))))
        assertEquals("force", recording.requireChannel(null).name)
        assertEquals("bend", recording.requireChannel("bend").name)
        val e = assertThrows(IllegalArgumentException::class.java) { recording.requireChannel("x") }
        assertEquals("no channel 'x'; the recording has force, bend", e.message)
    }
}
