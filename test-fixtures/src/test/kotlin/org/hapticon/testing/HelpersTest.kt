package org.hapticon.testing

import org.hapticon.core.render.IconRenderer
import org.hapticon.core.render.SampleStream
import org.junit.Assert.assertEquals
import org.junit.Test

class HelpersTest {
    @Test
    fun readAllSamples_iconStream_matchesRandomAccessSamples() {
        val renderer = IconRenderer(TestIcons.STEP_ONSET, 8_000)
        val samples = renderer.stream().readAllSamples()
        assertEquals(renderer.sampleCount.toInt(), samples.size)
        for (i in listOf(0, 1, 100, samples.size - 1)) {
            assertEquals(renderer.sampleAt(i.toLong()).toFloat(), samples[i], 0f)
        }
    }

    @Test(expected = IllegalStateException::class)
    fun readAllSamples_streamEndingEarly_fails() {
        val short = object : SampleStream {
            override val sampleRate = 8_000
            override val totalSamples = 10L
            override var position = 0L
            override fun read(destination: FloatArray, offset: Int, length: Int): Int {
                if (position >= 5) return -1
                position += 5
                return 5
            }
        }
        short.readAllSamples()
    }

    @Test
    fun littleEndian_readsFieldsLowByteFirst() {
        val bytes = byteArrayOf('R'.code.toByte(), 'I'.code.toByte(), 'F'.code.toByte(), 'F'.code.toByte(), 0x34, 0x12, 0xFF.toByte(), 0xFF.toByte())
        assertEquals("RIFF", LittleEndian.fourCc(bytes, 0))
        assertEquals(0x1234, LittleEndian.u16(bytes, 4))
        assertEquals(0xFFFF1234L, LittleEndian.u32(bytes, 4))
    }
}
