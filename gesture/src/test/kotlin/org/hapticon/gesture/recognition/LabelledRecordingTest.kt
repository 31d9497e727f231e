package org.hapticon.gesture.recognition

import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Test

class LabelledRecordingTest {
    private val hit = GestureLabel.parse("hit-energetic")
    private val recording = Recording(100.0, listOf(Channel("force", "N", DoubleArray(300))))
    private val labelled = LabelledRecording(recording, listOf(LabelledSpan(100, 110, hit)))

    @Test
    fun windowsTakeTheLabelOfHalfTheirSpanOrHalfTheWindow() {
        assertEquals(GestureLabel.NONE, labelled.windowLabel(0, 100)) // ends where the hit starts
        assertEquals(hit, labelled.windowLabel(10, 95)) // holds 5 of its 10 frames
        assertNull(labelled.windowLabel(10, 94)) // holds 4: ambiguous
        assertEquals(hit, labelled.windowLabel(105, 8)) // the hit fills 5 of 8 frames
        assertEquals(GestureLabel.NONE, labelled.windowLabel(110, 50))
    }

    @Test
    fun spansMustFitAndNotOverlap() {
        assertThrows(IllegalArgumentException::class.java) { LabelledRecording(recording, listOf(LabelledSpan(250, 301, hit))) }
        assertThrows(IllegalArgumentException::class.java) { LabelledRecording(recording, listOf(LabelledSpan(0, 20, hit), LabelledSpan(19, 30, hit))) }
        assertThrows(IllegalArgumentException::class.java) { LabelledSpan(5, 5, hit) }
    }

    @Test
    fun windowsSkipAmbiguousOnesAndNeedAFullWindow() {
        val windows = LabelledWindows.of(listOf(labelled), WindowConfig(1.0, 0.5))
        // Windows start at 0, 50, 100, 150, 200: the one at 50 holds the whole hit.
        assertEquals(listOf(GestureLabel.NONE, hit, hit, GestureLabel.NONE, GestureLabel.NONE), windows.labels)
        assertEquals(0, LabelledWindows.of(listOf(labelled), WindowConfig(4.0, 1.0)).size)
        val short = LabelledRecording.whole(recording.slice(0, 50), hit)
        assertThrows(IllegalArgumentException::class.java) { PersonalTrainer().train(listOf(short)) }
    }

    @Test
    fun syntheticTakesAreRepeatableAndLabelled() {
        val person = SyntheticGestures.people(3, seed = 9)[2]
        val label = GestureLabel.parse("knock-gentle")
        val a = SyntheticGestures.perform(person, label, take = 4)
        val b = SyntheticGestures.perform(person, label, take = 4)
        assertArrayEquals(a.labelled.recording.channels[0].toDoubleArray(), b.labelled.recording.channels[0].toDoubleArray(), 0.0)
        assertEquals(label, a.labelled.spans.single().label)
        assertEquals(a.onsetFrame, a.labelled.spans.single().from)
        assertEquals(SyntheticGestures.CHANNELS, a.labelled.recording.channels.map { it.name })
        assertEquals(emptyList<LabelledSpan>(), SyntheticGestures.perform(person, GestureLabel.NONE, 0).labelled.spans)
    }
}
