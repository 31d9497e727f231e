package org.hapticon.app.screenshots

import kotlin.math.PI
import kotlin.math.sin
import org.hapticon.app.feature.sensors.ChannelUi
import org.hapticon.app.feature.sensors.GloveUi
import org.hapticon.app.feature.sensors.GrainUi
import org.hapticon.app.feature.sensors.SensorsActions
import org.hapticon.app.feature.sensors.SensorsScreen
import org.hapticon.app.feature.sensors.SensorsUiState
import org.hapticon.app.feature.sensors.StreamUi
import org.hapticon.testing.TEST_UNO
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.live.ChannelHistory
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.live.StopCause
import org.hapticon.sensor.live.StreamCounters
import org.hapticon.sensor.protocol.SensorProtocol
import org.junit.Test

/** The Sensors tab: no USB host, no board yet, a live stream with plots, an unplugged board. */
class SensorsScreenshotTest : ScreenshotTest() {
    private val names = listOf("ch0 (raw)", "ch1 (g)")

    /** Two seconds of a 1 kHz stream: a 2 Hz sine on ch0 (counts) and a pressing force ramp on ch1 (g). */
    private fun history(): ChannelHistory = ChannelHistory().apply {
        val frame = LiveFrame()
        frame.channelCount = 2
        for (i in 0 until 2000) {
            val t = i / 1000.0
            frame.values[0] = 2048 + 1200 * sin(2 * PI * 2 * t)
            frame.values[1] = if (t < 1) 1500 * t else 1500 * (2 - t)
            frame.receivedNanos = i * 1_000_000L
            append(frame)
        }
    }

    private fun ready(connection: SessionState, stream: StreamUi?, devices: Boolean = true) = SensorsUiState.Ready(
        devices = if (devices) listOf(TEST_UNO) else emptyList(),
        selectedDeviceId = if (devices) TEST_UNO.id else null,
        protocol = SensorProtocol.FRAMED,
        baudRate = 115_200,
        connection = connection,
        canConnect = devices && connection !is SessionState.Streaming,
        canDisconnect = connection is SessionState.Streaming,
        stream = stream,
        grains = GrainUi(
            enabled = stream != null, channel = 1, channelNames = names, input = null, count = 24,
            distribution = BinDistribution.CONVEX, amplitude = 255, fallbackSampleRateHz = 100,
            deviceSampleRateHz = stream?.let { 1000 }, grainsPlayed = if (stream != null) 7 else 0, error = null,
        ),
        glove = GloveUi(thumbChannel = 0, middleChannel = 1, adcBits = 12, adcBitsFromDevice = stream?.let { 12 }, channelNames = names),
    )

    private fun stream(samples: Long) = StreamUi(
        deviceDescription = "hapticon-ref · firmware 1.0.0 · 1000 Hz · 12-bit",
        channels = listOf(ChannelUi(0, names[0], "2048", plotted = true), ChannelUi(1, names[1], "1321 g", plotted = true)),
        counters = StreamCounters(bytes = 48_000, frames = samples, badFrames = 0, droppedBytes = 0, truncatedFrames = 0),
        measuredRateHz = 999.8,
        samples = samples,
        plot = history(),
        outputError = null,
    )

    @Test
    fun sensors_streaming_showsLivePlots() = screen("sensors-live", Variant.MAIN) {
        SensorsScreen(ready(SessionState.Streaming(TEST_UNO, SensorProtocol.FRAMED, 115_200), stream(2000)), SensorsActions())
    }

    @Test
    fun sensors_noBoard_explainsWhatToPlugIn() = screen("sensors-no-board", Variant.MAIN) {
        SensorsScreen(ready(SessionState.Idle, stream = null, devices = false), SensorsActions())
    }

    @Test
    fun sensors_unplugged_keepsWhatArrived() = screen("sensors-unplugged") {
        SensorsScreen(
            ready(SessionState.Stopped(TEST_UNO, SensorProtocol.FRAMED, StopCause.UNPLUGGED), stream(2000)),
            SensorsActions(),
        )
    }

    @Test
    fun sensors_noUsbHost_saysSo() = screen("sensors-no-usb-host") {
        SensorsScreen(SensorsUiState.NoUsbHost, SensorsActions())
    }

    @Test
    fun sensors_loading_showsProgress() = screen("sensors-loading") {
        SensorsScreen(SensorsUiState.Loading, SensorsActions())
    }
}
