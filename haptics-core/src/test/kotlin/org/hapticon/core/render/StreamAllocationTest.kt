package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Test
import java.lang.management.ManagementFactory

/**
 * Reading a stream allocates nothing per block, for every sample type and mode: the audio thread must not make
 * garbage. The least over three windows counts, so a one-off (class loading, the JIT) does not; a per-block
 * allocation (a boxed count, a lambda) shows in every window. `hapticon bench` reports the same figure for floats.
 */
class StreamAllocationTest {
    private val threads = ManagementFactory.getThreadMXBean() as com.sun.management.ThreadMXBean

    @Test
    fun read_floatsDoublesAndPcm16_bothModes_allocateNothingPerBlock() {
        val icon = HapticIcon.STROKE
        for (mode in RenderMode.values()) {
            val floats = FloatArray(441)
            val doubles = DoubleArray(441)
            val shorts = ShortArray(441)
            val floatStream = IconRenderer(icon, 44_100, EnvelopeModel.PAPER, mode).stream()
            val doubleStream = IconRenderer(icon, 44_100, EnvelopeModel.PAPER, mode).stream()
            val pcmStream = PcmRenderer(icon, 44_100, EnvelopeModel.PAPER).stream()
            assertEquals("$mode floats", 0L, leastAllocatedOver(50) { floatStream.read(floats, 0, floats.size) })
            assertEquals("$mode doubles", 0L, leastAllocatedOver(50) { doubleStream.read(doubles, 0, doubles.size) })
            assertEquals("$mode pcm16", 0L, leastAllocatedOver(50) { pcmStream.read(shorts, 0, shorts.size) })
        }
    }

    // The least bytes this thread allocated over [blocks] calls of [read], in three windows, the counter's own cost taken off.
    private inline fun leastAllocatedOver(blocks: Int, read: () -> Int): Long {
        val thread = Thread.currentThread().id
        repeat(blocks) { read() }
        val overhead = (1..5).minOf { threads.getThreadAllocatedBytes(thread).let { before -> threads.getThreadAllocatedBytes(thread) - before } }
        return (1..3).minOf {
            val before = threads.getThreadAllocatedBytes(thread)
            repeat(blocks) { read() }
            threads.getThreadAllocatedBytes(thread) - before - overhead
        }
    }
}
