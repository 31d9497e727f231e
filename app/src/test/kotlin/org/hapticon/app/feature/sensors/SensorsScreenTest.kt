package org.hapticon.app.feature.sensors

import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.hasScrollToNodeAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToNode
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.testing.TEST_UNO
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.live.ChannelHistory
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.StopCause
import org.hapticon.sensor.live.StreamCounters
import org.hapticon.sensor.protocol.SensorProtocol
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The stateless Sensors screen with a stream that ended by an unplug, in the dark theme. */
@RunWith(RobolectricTestRunner::class)
class SensorsScreenTest {
    @get:Rule
    val rule = createComposeRule()

    private val unplugged = SensorsUiState.Ready(
        devices = listOf(TEST_UNO),
        selectedDeviceId = TEST_UNO.id,
        protocol = SensorProtocol.FRAMED,
        baudRate = 115_200,
        connection = SessionState.Stopped(TEST_UNO, SensorProtocol.FRAMED, StopCause.UNPLUGGED),
        canConnect = true,
        canDisconnect = false,
        stream = StreamUi(
            deviceDescription = "hapticon-ref · firmware 1.0.0 · 1000 Hz · 12-bit",
            channels = listOf(ChannelUi(0, "ch0 (raw)", "873", plotted = true), ChannelUi(1, "ch1 (g)", "1321 g", plotted = true)),
            counters = StreamCounters(bytes = 264, frames = 11, badFrames = 1, droppedBytes = 9, truncatedFrames = 1),
            measuredRateHz = null,
            samples = 10,
            plot = ChannelHistory(),
            outputError = null,
        ),
        grains = GrainUi(
            enabled = true, channel = 1, channelNames = listOf("ch0 (raw)", "ch1 (g)"), input = null, count = 24,
            distribution = BinDistribution.CONVEX, amplitude = 255, fallbackSampleRateHz = 100, deviceSampleRateHz = 1000,
            grainsPlayed = 7, error = null,
        ),
        glove = GloveUi(thumbChannel = 0, middleChannel = 1, adcBits = 12, adcBitsFromDevice = 12, channelNames = listOf("ch0 (raw)", "ch1 (g)")),
    )

    private fun scrollTo(matcher: SemanticsMatcher) {
        rule.onNode(hasScrollToNodeAction()).performScrollToNode(matcher)
    }

    @Test
    fun unpluggedStream_darkTheme_keepsValuesPlotsAndCounters() {
        var connects = 0
        rule.setContent { HapticonTheme(darkTheme = true) { SensorsScreen(unplugged, SensorsActions(onConnect = { connects++ })) } }

        scrollTo(hasText("Board unplugged", substring = true))
        rule.onNodeWithText("Board unplugged. The 11 frames received before are kept below.").assertExists()
        scrollTo(hasContentDescription("Plot of ch1 (g) over the last 5 seconds"))
        rule.onNodeWithContentDescription("Plot of ch0 (raw) over the last 5 seconds").assertExists()
        rule.onNodeWithText("1321 g").assertExists()
        scrollTo(hasText("Dropped bytes"))
        rule.onNodeWithText("Cut off by the end of the stream").assertExists()
        scrollTo(hasText("Grains played: 7"))
        rule.onNodeWithText("Sample rate from the board: 1000 Hz").assertExists()
        rule.onNodeWithContentDescription("Grain count").assertExists()
        // Grains = bins − 1 (Shaping Compliance): 24 grains are 25 bins.
        rule.onNodeWithText("Grains per full press: 24 (25 force bins)").assertExists()
        rule.onNodeWithContentDescription("Burst strength").assertExists()

        scrollTo(hasText("Connect"))
        rule.onNodeWithText("Connect").performClick()
        assertEquals(1, connects)
    }
}
