package org.hapticon.app.feature.sensors

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.advanceTimeBy
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.playback.PlaybackCapabilities
import org.hapticon.app.playback.VibrationOutput
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.glove.SessionGloveSource
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.live.StopCause
import org.hapticon.sensor.live.StreamCounters
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.testing.RecordedStreams
import org.hapticon.testing.TabSeparatedProtocol
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test

@OptIn(ExperimentalCoroutinesApi::class)
class SensorsViewModelTest {
    private val dispatcher = StandardTestDispatcher()
    private val usb = TestUsbDevices()
    private val session = SensorSession(usb)
    private val grains = GrainEngine(SilentVibration).also { session.addFrameListener(it) }
    private lateinit var viewModel: SensorsViewModel

    @Before
    fun setUp() {
        // Before the view model: its viewModelScope runs on Main.
        Dispatchers.setMain(dispatcher)
        viewModel = SensorsViewModel(usb, session, grains, SessionGloveSource(session))
    }

    @After
    fun tearDown() {
        session.disconnect()
        Dispatchers.resetMain()
    }

    /** Connects to a board whose port is [port], lets the reading thread finish, and returns what the screen shows. */
    private fun TestScope.streamToTheEnd(port: FakeSerialPort, protocol: SensorProtocol): SensorsUiState.Ready {
        backgroundScope.launch { viewModel.uiState.collect {} }
        usb.ports[TEST_UNO.id] = port
        viewModel.selectProtocol(protocol)
        viewModel.selectBaudRate(57_600)
        runCurrent()
        viewModel.connect()
        runCurrent()
        assertTrue("reader did not stop", session.awaitStopped(5_000))
        advanceTimeBy(100)
        runCurrent()
        return viewModel.uiState.value as SensorsUiState.Ready
    }

    @Test
    fun recordedCsv_showsEveryChannelsLastValueNamedByTheHeaderAndTheCounters() = runTest(dispatcher) {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.CSV_BANNER_HEADER), chunkSize = 64).enqueueEnd()

        val state = streamToTheEnd(port, SensorProtocol.CSV)

        assertEquals(57_600, usb.opened.single().second.baudRate)
        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.CSV, StopCause.ENDED), state.connection)
        val stream = state.stream!!
        assertEquals(listOf("fsr0", "fsr1", "fsr2", "fsr3"), stream.channels.map { it.name })
        // The 20th sample: (19·37 + c·211) mod 1024.
        assertEquals(listOf("703", "914", "101", "312"), stream.channels.map { it.valueText })
        assertEquals(StreamCounters(bytes = 376, frames = 20, badFrames = 0, droppedBytes = 63, ignoredLines = 3), stream.counters)
        assertEquals(20L, stream.samples)
        assertTrue(state.canConnect)
        assertFalse(state.canDisconnect)
    }

    @Test
    fun registryWithTheExampleProtocol_offersItAndShowsItsStream() = runTest(dispatcher) {
        viewModel = SensorsViewModel(usb, session, grains, SessionGloveSource(session), protocols = TabSeparatedProtocol.WITH_EXAMPLE)
        val port = FakeSerialPort().enqueue("1\t2\n3\t4.5\n".toByteArray()).enqueueEnd()

        val state = streamToTheEnd(port, TabSeparatedProtocol)

        assertEquals(listOf("CSV", "LucidGloves", "Framed", "Tabs"), state.protocols.map { it.label })
        assertEquals(SessionState.Stopped(TEST_UNO, TabSeparatedProtocol, StopCause.ENDED), state.connection)
        assertEquals(listOf("tab0", "tab1"), state.stream!!.channels.map { it.name })
        assertEquals(listOf("3", "4.500"), state.stream!!.channels.map { it.valueText })
    }

    @Test
    fun recordedFramedStream_showsDeviceInfoUnitsValuesAndCounters() = runTest(dispatcher) {
        val port = FakeSerialPort().enqueueChunks(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN), intArrayOf(7, 64, 13)).enqueueEnd()

        val stream = streamToTheEnd(port, SensorProtocol.FRAMED).stream!!

        assertEquals("hapticon-ref · firmware 1.0.0 · 1000 Hz · 12-bit", stream.deviceDescription)
        assertEquals(listOf("ch0 (raw)", "ch1 (raw)", "ch2 (raw)", "ch3 (g)", "ch4 (°)"), stream.channels.map { it.name })
        // Sample 19: (19·97 + c·331 + 19·c·13) mod 4096 = 1843, 2421, 2999, 3577 g, 59 centidegrees.
        assertEquals(listOf("1843", "2421", "2999", "3577 g", "0.59°"), stream.channels.map { it.valueText })
        // 20 samples, the device info and an ack; the leading flush delimiter is the one dropped byte. Nothing was
        // sent, so the ack answers no command of ours.
        assertEquals(StreamCounters(bytes = 488, frames = 22, badFrames = 0, droppedBytes = 1, unmatchedAcks = 1), stream.counters)
    }

    @Test
    fun unplugMidFrame_showsUnpluggedAndKeepsEveryFrameDecodedBefore() = runTest(dispatcher) {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_UNPLUG), chunkSize = 32).enqueueUnplug()

        val state = streamToTheEnd(port, SensorProtocol.FRAMED)

        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.FRAMED, StopCause.UNPLUGGED), state.connection)
        val stream = state.stream!!
        // Sample 9, the last whole frame: (9·97 + c·331 + 9·c·13) mod 4096.
        assertEquals(listOf("873", "1321", "1769", "2217 g", "26.65°"), stream.channels.map { it.valueText })
        assertEquals(
            StreamCounters(bytes = 264, frames = 11, badFrames = 1, droppedBytes = 9, truncatedFrames = 1),
            stream.counters,
        )
        assertEquals(10L, stream.samples)
        // The plot history keeping them is the session's (SensorSessionTest); the screen's port is closed.
        assertFalse(port.isOpen)
    }

    @Test
    fun permissionDenied_showsDeniedAndLetsTheUserAskAgain() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        usb.grantPermission = false
        runCurrent()

        viewModel.connect()
        runCurrent()

        val state = viewModel.uiState.value as SensorsUiState.Ready
        assertEquals(SessionState.PermissionDenied(TEST_UNO), state.connection)
        assertTrue(state.canConnect)
        assertNull(state.stream)
        assertTrue(usb.opened.isEmpty())
    }

    @Test
    fun openFails_showsWhy() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()

        viewModel.connect() // no port scripted: opening throws

        runCurrent()
        assertEquals(SessionState.Failed(TEST_UNO, "no such test port"), (viewModel.uiState.value as SensorsUiState.Ready).connection)
    }

    @Test
    fun disconnect_whileStreaming_stopsByUserAndKeepsTheValues() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        val port = FakeSerialPort().enqueue("a,b\n1,2\n3,4\n".toByteArray())
        usb.ports[TEST_UNO.id] = port
        runCurrent()
        viewModel.connect()
        runCurrent()
        waitUntil { session.snapshot().samples == 2L }
        advanceTimeBy(40)
        runCurrent()
        val streaming = viewModel.uiState.value as SensorsUiState.Ready
        assertEquals(SessionState.Streaming(TEST_UNO, SensorProtocol.CSV, 115_200), streaming.connection)
        assertTrue(streaming.canDisconnect)
        assertEquals(listOf("3", "4"), streaming.stream!!.channels.map { it.valueText })

        viewModel.disconnect()
        assertTrue(session.awaitStopped(5_000))
        runCurrent()

        val stopped = viewModel.uiState.value as SensorsUiState.Ready
        assertEquals(SessionState.Stopped(TEST_UNO, SensorProtocol.CSV, StopCause.BY_USER), stopped.connection)
        assertEquals(listOf("3", "4"), stopped.stream!!.channels.map { it.valueText })
        assertFalse(port.isOpen)
    }

    @Test
    fun devices_firstIsSelectedUntilTheUserChoosesAnother() = runTest(dispatcher) {
        val other = TEST_UNO.copy(id = "/dev/bus/usb/001/009", chipFamily = "FTDI", vendorId = 0x0403, productId = 0x6001)
        usb.deviceList.value = listOf(TEST_UNO, other)
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()
        assertEquals(TEST_UNO.id, (viewModel.uiState.value as SensorsUiState.Ready).selectedDeviceId)

        viewModel.selectDevice(other.id)
        runCurrent()

        assertEquals(other.id, (viewModel.uiState.value as SensorsUiState.Ready).selectedDeviceId)
        assertEquals("0403:6001", other.usbIds)
    }

    @Test
    fun noUsbHost_isItsOwnState() {
        val vm = SensorsViewModel(TestUsbDevices(hasUsbHost = false), session, grains, SessionGloveSource(session))
        assertEquals(SensorsUiState.NoUsbHost, vm.uiState.value)
    }

    @Test
    fun grainSettings_areClampedToTheStudyRangeAndTheVibratorsAmplitudes() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setGrainCount(80)
        viewModel.setGrainAmplitude(400)
        runCurrent()
        val grainsUi = (viewModel.uiState.value as SensorsUiState.Ready).grains
        assertEquals(39, grainsUi.count)
        assertEquals(255, grainsUi.amplitude)
        viewModel.setGrainCount(2)
        runCurrent()
        assertEquals(9, (viewModel.uiState.value as SensorsUiState.Ready).grains.count)
    }

    private fun waitUntil(condition: () -> Boolean) {
        val deadline = System.nanoTime() + 5_000_000_000L
        while (!condition()) {
            check(System.nanoTime() < deadline) { "timed out" }
            Thread.sleep(2)
        }
    }

    private object SilentVibration : VibrationOutput {
        override val capabilities = PlaybackCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
        override fun play(waveform: VibrationWaveform) = Unit
        override fun playLevel(amplitude: Int, durationMillis: Long) = Unit
        override fun stop() = Unit
    }
}
