package org.hapticon.sensor.grains

import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assume.assumeTrue
import org.junit.Test

/** The grain engine on the plain JVM: force frames in, the bursts its [GrainSink] was handed out. */
class GrainEngineTest {
    private val played = ArrayList<VibrationWaveform>()
    private val engine = GrainEngine { played += it }
    private val frame = LiveFrame()

    /** 10 linear grains over 0–10 N (an edge every newton), 200 amplitude, at the CSV fallback of 100 Hz. */
    private val config = GrainConfig(
        channel = 0,
        input = ForceInput.NEWTONS,
        settings = GrainSettings(grainCount = 10, distribution = BinDistribution.LINEAR),
        amplitude = 200,
    )

    private fun feed(forces: List<Double>, info: StreamInfo = StreamInfo(SensorProtocol.CSV, listOf("force"))) {
        for ((k, force) in forces.withIndex()) {
            frame.channelCount = 1
            frame.values[0] = force
            frame.receivedNanos = k * 10_000_000L
            engine.onFrame(frame, info)
        }
    }

    @Test
    fun forceRamp_playsOneTwentyMillisecondBurstPerNewtonCrossed() {
        engine.configure(config)
        // 0 → 4.5 N in 0.05 N steps (0.9 s), then held: the filtered force crosses 1, 2, 3 and 4 N.
        feed((0..90).map { it * 0.05 } + List(20) { 4.5 })

        assertEquals(4, played.size)
        for (burst in played) {
            assertArrayEquals(longArrayOf(20), burst.timings())
            assertArrayEquals(intArrayOf(200), burst.amplitudes())
        }
        assertEquals(4L, engine.grainsPlayed)
        assertEquals(GrainStatus(enabled = true, sampleRateHz = 100.0), engine.status.value)
    }

    @Test
    fun forceStep_noNewGrainWhileOnePlays() {
        engine.configure(config)
        // 0 → 9.5 N at once: bin 6 fires, bin 8 comes while its 2-sample grain plays, bin 9 fires after it.
        feed(listOf(0.0) + List(30) { 9.5 })

        assertEquals(2, played.size)
        assertEquals(2L, engine.grainsPlayed)
    }

    @Test
    fun modeOff_playsNothing() {
        feed(listOf(0.0, 5.0, 9.0, 0.0))

        assertEquals(0, played.size)
        assertFalse(engine.status.value.enabled)
    }

    @Test
    fun framedBoard_runsAtItsAnnouncedRateAndReadsGramsFromTheUnit() {
        engine.configure(config.copy(input = null))
        val info = StreamInfo(SensorProtocol.FRAMED, listOf("ch0 (g)"), listOf(ChannelUnit.GRAM), adcBits = 12, sampleRateHz = 1000)

        // 0 → 459 g (4.5 N at 0.00980665 N/g) in 0.1 g steps at 1 kHz, then held: crosses 1, 2, 3 and 4 N.
        feed((0..4590).map { it * 0.1 } + List(200) { 459.0 }, info)

        assertEquals(1000.0, engine.status.value.sampleRateHz!!, 0.0)
        assertEquals(4, played.size)
    }

    @Test
    fun refusingSink_turnsTheModeOffWithTheReason() {
        val refusing = GrainEngine { throw IllegalStateException("amplitude above the safety limit") }
        refusing.configure(config)
        frame.channelCount = 1
        for (force in listOf(0.0, 9.5, 9.5, 9.5)) {
            frame.values[0] = force
            refusing.onFrame(frame, StreamInfo(SensorProtocol.CSV, listOf("force")))
        }

        assertEquals(GrainStatus(enabled = false, error = "amplitude above the safety limit"), refusing.status.value)
        assertEquals(0L, refusing.grainsPlayed)
        assertNull(refusing.currentConfig)
    }

    @Test
    fun channelBeyondTheFrame_isIgnored() {
        engine.configure(config.copy(channel = 3))
        feed(List(50) { 9.5 })

        assertEquals(0, played.size)
        assertEquals(0L, engine.grainsPlayed)
    }

    @Test
    fun configure_buildsTheDeciderAtTheRateTheStreamAnnounced() {
        val info = StreamInfo(SensorProtocol.FRAMED, listOf("ch0 (g)"), listOf(ChannelUnit.GRAM), adcBits = 12, sampleRateHz = 1000)
        feed(List(5) { 0.0 }, info) // the mode is off, but the engine notes the announced 1 kHz

        engine.configure(config.copy(input = null))

        // Before any further frame: the decider runs at 1 kHz, not the 100 Hz fallback.
        assertEquals(GrainStatus(enabled = true, sampleRateHz = 1000.0), engine.status.value)
        assertEquals(config.copy(input = null), engine.currentConfig)
    }

    @Test
    fun laterAnnouncedRate_rebuildsTheDeciderOnceAndKeepsTheCount() {
        engine.configure(config) // no stream yet: the 100 Hz fallback
        assertEquals(100.0, engine.status.value.sampleRateHz!!, 0.0)
        feed(listOf(0.0) + List(30) { 9.5 }) // CSV at the fallback: 2 grains
        val framed = StreamInfo(SensorProtocol.FRAMED, listOf("ch0 (N)"), adcBits = 12, sampleRateHz = 1000)

        feed(List(200) { 0.0 }, framed)

        assertEquals(GrainStatus(enabled = true, sampleRateHz = 1000.0), engine.status.value)
        assertEquals(2L, engine.grainsPlayed)
    }

    @Test
    fun reconfigure_startsTheCountAfresh_andOffKeepsNothing() {
        engine.configure(config)
        feed(listOf(0.0) + List(30) { 9.5 })
        assertEquals(2L, engine.grainsPlayed)

        engine.configure(config.copy(amplitude = 100))
        assertEquals(0L, engine.grainsPlayed)
        engine.configure(null)
        assertEquals(GrainStatus(enabled = false), engine.status.value)
        assertNull(engine.currentConfig)
    }

    @Test
    fun onFrame_afterWarmup_allocatesNothingPerFrameOrPerGrain() {
        val threads = java.lang.management.ManagementFactory.getThreadMXBean() as com.sun.management.ThreadMXBean
        assumeTrue(threads.isThreadAllocatedMemorySupported && threads.isThreadAllocatedMemoryEnabled)
        var grains = 0
        val counting = GrainEngine { grains++ }
        counting.configure(config)
        val info = StreamInfo(SensorProtocol.CSV, listOf("force"))
        frame.channelCount = 1
        // A 0 -> 9.9 -> 0 N press every 200 frames: 18 grains per press.
        fun press(frames: Int) {
            for (k in 0 until frames) {
                val phase = k % 200
                frame.values[0] = if (phase < 100) phase * 0.099 else (200 - phase) * 0.099
                counting.onFrame(frame, info)
            }
        }
        press(40_000) // JIT warm-up
        val before = grains
        val thread = Thread.currentThread().id
        val start = threads.getThreadAllocatedBytes(thread)
        press(20_000)
        val bytes = threads.getThreadAllocatedBytes(thread) - start

        assertTrue("grains ${grains - before}", grains - before >= 100)
        // One object per frame would be >= 16 bytes per frame; below 1 allows a one-off (a JIT tier change).
        assertTrue("$bytes bytes over 20000 frames", bytes / 20_000.0 < 1.0)
    }
}
