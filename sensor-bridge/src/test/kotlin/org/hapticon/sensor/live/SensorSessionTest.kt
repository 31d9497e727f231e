package org.hapticon.sensor.live

import org.hapticon.testing.TestUsbDevices
import org.hapticon.testing.TEST_UNO
import kotlinx.coroutines.runBlocking
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.testing.RecordedStreams
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo

/**
 * The live session on the plain JVM: the connection state machine, the decoded values and counters
 * of the recorded streams, and the plot history. The same streams the Sensors screen's view model
 * test shows through the UI.
 */
class SensorSessionTest {
    private val usb = TestUsbDevices()
    private val session = SensorSession(usb)

    @After
    fun tearDown() = session.disconnect()

    /** Connects to a board whose port is [port] at 57 600 baud and waits for the reading thread to end. */
    private fun streamToTheEnd(port: FakeSerialPort, protocol: SensorProtocol): StreamSnapshot {
        usb.ports[TEST_UNO.id] = port
        runBlocking { session.connect(TEST_UNO, protocol, 57_600) }
        assertTrue("reader did not stop", session.awaitStopped(5_000))
        return session.snapshot()
    }

    @Test
    fun recordedCsv_keepsEveryChannelsLastValueNamedByTheHeaderAndTheCounters() {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.CSV_BANNER_HEADER), chunkSize = 64).enqueueEnd()

        val snapshot = streamToTheEnd(port, SensorProtocol.CSV)

        assertEquals(57_600, usb.opened.single().second.baudRate)
        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.CSV, StopCause.ENDED), session.state.value)
        assertEquals(listOf("fsr0", "fsr1", "fsr2", "fsr3"), snapshot.info!!.channelNames)
        // The 20th sample: (19·37 + c·211) mod 1024.
        assertEquals(listOf(703.0, 914.0, 101.0, 312.0), snapshot.latest)
        assertEquals(StreamCounters(bytes = 376, frames = 20, badFrames = 0, droppedBytes = 63, ignoredLines = 3), snapshot.counters)
        assertEquals(20L, snapshot.samples)
    }

    @Test
    fun recordedFramedStream_keepsDeviceInfoUnitsValuesAndCounters() {
        val port = FakeSerialPort().enqueueChunks(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN), intArrayOf(7, 64, 13)).enqueueEnd()

        val snapshot = streamToTheEnd(port, SensorProtocol.FRAMED)

        val info = snapshot.info!!
        assertEquals("hapticon-ref · firmware 1.0.0 · 1000 Hz · 12-bit", info.deviceDescription)
        assertEquals(listOf("ch0 (raw)", "ch1 (raw)", "ch2 (raw)", "ch3 (g)", "ch4 (°)"), info.channelNames)
        assertEquals(12, info.adcBits)
        assertEquals(1000, info.sampleRateHz)
        // Sample 19: (19·97 + c·331 + 19·c·13) mod 4096 = 1843, 2421, 2999, 3577 g, 59 centidegrees.
        assertEquals(listOf(1843.0, 2421.0, 2999.0, 3577.0, 59.0), snapshot.latest)
        // 20 samples, the device info and an ack; the leading flush delimiter is the one dropped byte.
        // Nothing was sent, so the recording's ack answers no command of ours.
        assertEquals(StreamCounters(bytes = 488, frames = 22, badFrames = 0, droppedBytes = 1, unmatchedAcks = 1), snapshot.counters)
    }

    @Test
    fun unplugMidFrame_stopsUnpluggedAndKeepsEveryFrameDecodedBefore() {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_UNPLUG), chunkSize = 32).enqueueUnplug()

        val snapshot = streamToTheEnd(port, SensorProtocol.FRAMED)

        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.FRAMED, StopCause.UNPLUGGED), session.state.value)
        // Sample 9, the last whole frame: (9·97 + c·331 + 9·c·13) mod 4096.
        assertEquals(listOf(873.0, 1321.0, 1769.0, 2217.0, 2665.0), snapshot.latest)
        assertEquals(StreamCounters(bytes = 264, frames = 11, badFrames = 1, droppedBytes = 9, truncatedFrames = 1), snapshot.counters)
        assertEquals(10L, snapshot.samples)
        val xs = FloatArray(ChannelHistory.DEFAULT_CAPACITY)
        val ys = FloatArray(ChannelHistory.DEFAULT_CAPACITY)
        assertEquals(10, session.history.copyRecent(0, 5_000_000_000L, xs, ys))
        assertEquals(873f, ys[9])
        assertFalse(port.isOpen)
    }

    @Test
    fun permissionDenied_isItsOwnStateAndOpensNothing() {
        usb.grantPermission = false

        runBlocking { session.connect(TEST_UNO, SensorProtocol.CSV, 115_200) }

        assertEquals(SessionState.PermissionDenied(TEST_UNO), session.state.value)
        assertTrue(usb.opened.isEmpty())
        assertNull(session.currentInfo())
    }

    @Test
    fun openFails_isFailedWithTheReason() {
        runBlocking { session.connect(TEST_UNO, SensorProtocol.CSV, 115_200) } // no port scripted: opening throws

        assertEquals(SessionState.Failed(TEST_UNO, "no such test port"), session.state.value)
    }

    @Test
    fun disconnect_whileStreaming_stopsByUserAndKeepsTheValues() {
        val port = FakeSerialPort().enqueue("a,b\n1,2\n3,4\n".toByteArray())
        usb.ports[TEST_UNO.id] = port
        runBlocking { session.connect(TEST_UNO, SensorProtocol.CSV, 115_200) }
        waitUntil { session.snapshot().samples == 2L }
        assertEquals(SessionState.Streaming(TEST_UNO, SensorProtocol.CSV, 115_200), session.state.value)

        session.disconnect()

        assertTrue(session.awaitStopped(5_000))
        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.CSV, StopCause.BY_USER), session.state.value)
        assertEquals(listOf(3.0, 4.0), session.snapshot().latest)
        assertFalse(port.isOpen)
    }

    @Test
    fun failingListener_isRemovedAndReportedWhileTheStreamGoesOn() {
        val heard = ArrayList<Double>()
        session.addFrameListener { _, _ -> throw IllegalStateException("refused by a safety limit") }
        session.addFrameListener { frame, _ -> heard += frame[0] }
        val port = FakeSerialPort().enqueue("x\n1\n2\n3\n".toByteArray()).enqueueEnd()

        val snapshot = streamToTheEnd(port, SensorProtocol.CSV)

        assertEquals("refused by a safety limit", session.listenerError.value)
        assertEquals(listOf(1.0, 2.0, 3.0), heard)
        assertEquals(3L, snapshot.samples)
    }

    @Test
    fun tally_measuresTheFrameRateOverOneSecondWindows() {
        val tally = StreamTally()
        val frame = LiveFrame().apply { channelCount = 1 }
        val info = StreamInfo(SensorProtocol.CSV, listOf("ch0"))
        // 101 frames 10 ms apart, from t = 1 s: the window closes at the 101st, one second later.
        for (k in 0..100) {
            frame.receivedNanos = 1_000_000_000L + k * 10_000_000L
            tally.onFrame(frame, info)
            if (k < 100) assertNull(tally.snapshot().measuredRateHz)
        }

        assertEquals(100.0, tally.snapshot().measuredRateHz!!, 1e-9)
    }

    private fun waitUntil(condition: () -> Boolean) {
        val deadline = System.nanoTime() + 5_000_000_000L
        while (!condition()) {
            check(System.nanoTime() < deadline) { "timed out" }
            Thread.sleep(2)
        }
    }
}
