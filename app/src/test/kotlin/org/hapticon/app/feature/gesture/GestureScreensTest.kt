package org.hapticon.app.feature.gesture

import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import java.util.Random
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.extraction.FitOptions
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.NoisyIconRenders
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.sensor.live.EmptyPlotSource
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** What the gesture screens show for given states. */
@RunWith(RobolectricTestRunner::class)
class GestureScreensTest {
    @get:Rule
    val compose = createComposeRule()

    @Test
    fun recorder_fittedIcon_showsEnvelopeReportAndSave() {
        val take = NoisyIconRenders.render(HapticIcon.KNOCK, Double.POSITIVE_INFINITY, Random(1), sampleRate = 8000).toRecording()
        val fit = IconFitter.fit(take, options = FitOptions(name = "tap"))
        val state = RecorderUiState.Ready(take = take, trimTo = take.frameCount, fitChannel = "vibration", fit = fit, iconName = "tap")
        compose.setContent { RecorderScreen(state, EmptyPlotSource, null, RecorderActions()) }

        compose.onNodeWithContentDescription("Envelope of tap").assertExists()
        compose.onNodeWithText("R²").assertExists()
        compose.onNodeWithText(fit.report.onsets.joinToString { String.format(java.util.Locale.ROOT, "%.3f s", it) }).assertExists()
        compose.onNodeWithText("Note 57.0", substring = true).assertExists()
        compose.onNodeWithContentDescription("Trim start").assertExists()
        compose.onNodeWithText("Save icon").assertExists()
    }

    @Test
    fun teach_withoutTakes_trainIsDisabledAndTheFirstTakeIsRest() {
        compose.setContent { TeachScreen(TeachUiState.Ready(), EmptyPlotSource, null, TeachActions()) }

        compose.onNodeWithText("Train").assertIsNotEnabled()
        compose.onNodeWithText("Record none").assertExists()
        compose.onNodeWithText("0 of 10 takes").assertExists()
    }

    @Test
    fun recognition_showsDecisionAndSentGestures() {
        val hug = GestureLabel.parse("hug-gentle")
        val state = RecognitionUiState.Ready(
            running = true, decision = hug, probability = 0.9, peers = listOf("bob"), peer = "bob", sendEnabled = true,
            sent = listOf(SentGesture(hug, "hug", "bob", 3.25)),
        )
        compose.setContent { RecognitionScreen(state, null, RecognitionActions()) }

        compose.onNodeWithText("hug-gentle (90 %)").assertExists()
        compose.onNodeWithText("Send recognised gestures to bob").assertExists()
        compose.onNodeWithText("Sent hug (hug-gentle) to bob at 3.3 s").assertExists()
    }
}
