package org.hapticon.gesture.io

import org.hapticon.core.HapticIcon
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavWriter
import org.hapticon.core.render.IconRenderer
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream

class RecordingWavTest {
    @Test fun readsAFloatWavAsOneVibrationChannel() {
        val bytes = ByteArrayOutputStream()
        WavWriter.write(IconRenderer(HapticIcon.KNOCK, 8000).stream(), bytes, WavEncoding.FLOAT32)
        val recording = RecordingWav.read(ByteArrayInputStream(bytes.toByteArray()))
        assertEquals(8000.0, recording.sampleRate, 0.0)
        assertEquals(listOf(RecordingWav.CHANNEL_NAME), recording.channels.map { it.name })
        val expected = IconRenderer(HapticIcon.KNOCK, 8000)
        assertEquals(expected.sampleCount.toInt(), recording.frameCount)
        assertEquals(expected.sampleAt(100).toFloat().toDouble(), recording.channels[0][100], 0.0)
    }

    @Test fun writeThenReadKeepsTheSamplesToFloatPrecision() {
        val recording = Recording(1000.0, listOf(Channel("vibration", "", doubleArrayOf(0.0, 0.5, -0.25, 1.0))))
        val bytes = ByteArrayOutputStream()
        RecordingWav.write(recording, bytes, encoding = WavEncoding.FLOAT32)
        val back = RecordingWav.read(ByteArrayInputStream(bytes.toByteArray()))
        assertEquals(1000.0, back.sampleRate, 0.0)
        assertArrayEquals(doubleArrayOf(0.0, 0.5, -0.25, 1.0), back.channels[0].toDoubleArray(), 0.0)
        val fractional = assertThrows(IllegalArgumentException::class.java) {
            RecordingWav.write(Recording(100.5, recording.channels), ByteArrayOutputStream())
        }
        assertEquals("a WAV needs a whole number of Hz, the recording has 100.5", fractional.message)
    }

    @Test fun reportsABrokenFileWithItsName() {
        val e = assertThrows(RecordingFormatException::class.java) { RecordingWav.read(ByteArrayInputStream(ByteArray(10)), "tap.wav") }
        assertEquals(true, e.message!!.startsWith("tap.wav: "))
    }
}
