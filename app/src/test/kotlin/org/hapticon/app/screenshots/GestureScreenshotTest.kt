package org.hapticon.app.screenshots

import java.util.Random
import org.hapticon.app.feature.gesture.RecognitionActions
import org.hapticon.app.feature.gesture.RecognitionScreen
import org.hapticon.app.feature.gesture.RecognitionUiState
import org.hapticon.app.feature.gesture.RecorderActions
import org.hapticon.app.feature.gesture.RecorderScreen
import org.hapticon.app.feature.gesture.RecorderUiState
import org.hapticon.app.feature.gesture.SentGesture
import org.hapticon.app.feature.gesture.TeachActions
import org.hapticon.app.feature.gesture.TeachScreen
import org.hapticon.app.feature.gesture.TeachUiState
import org.hapticon.app.feature.iconeditor.IconEditorActions
import org.hapticon.app.feature.iconeditor.IconEditorScreen
import org.hapticon.app.feature.iconeditor.IconEditorViewModel
import org.hapticon.app.feature.iconeditor.IconField
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.extraction.FitOptions
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.NoisyIconRenders
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.sensor.live.EmptyPlotSource
import org.junit.Test
import org.hapticon.app.feature.gesture.RecordingPlotSource
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.gesture.synthetic.SyntheticGestures as People

/** The Gestures tab (recorder with a fitted icon, teach, live recognition) and the icon editor. */
class GestureScreenshotTest : ScreenshotTest() {
    @Test
    fun recorder_empty() = screen("gestures-recorder-empty", Variant.MAIN) {
        RecorderScreen(RecorderUiState.Ready(), EmptyPlotSource, null, RecorderActions())
    }

    @Test
    fun recorder_fittedIcon() = screen("gestures-recorder-fitted", Variant.MAIN) {
        val take = NoisyIconRenders.render(HapticIcon.KNOCK, Double.POSITIVE_INFINITY, Random(1), sampleRate = 8000).toRecording()
        val fit = IconFitter.fit(take, options = FitOptions(name = "tap"))
        RecorderScreen(
            RecorderUiState.Ready(take = take, trimTo = take.frameCount, fitChannel = "vibration", fit = fit, iconName = "tap", channels = take.channels.map { it.name }),
            EmptyPlotSource, null, RecorderActions(),
        )
    }

    @Test
    fun recorder_midRecordingFromTheSensorBoard() = screen("gestures-recorder-recording", Variant.MAIN) {
        // 2.4 s into a gentle hug on an FSR board with an accelerometer: what the live plots show mid-take.
        val person = People.people(1).single()
        val take = People.perform(person, GestureLabel.parse("hug-gentle"), take = 0).labelled.recording
        val sofar = take.slice(0, minOf(take.frameCount, (2.4 * take.sampleRate).toInt()))
        RecorderScreen(
            RecorderUiState.Ready(
                sourceKind = GestureSourceKind.SENSOR_BOARD, recording = true, seconds = sofar.durationSeconds,
                channels = sofar.channels.map { it.name }, plotRevision = 1,
            ),
            RecordingPlotSource(sofar), null, RecorderActions(),
        )
    }

    @Test
    fun teach_noTakes() = screen("gestures-teach") {
        TeachScreen(TeachUiState.Ready(), EmptyPlotSource, null, TeachActions())
    }

    @Test
    fun recognition_live() = screen("gestures-recognition") {
        val hug = GestureLabel.parse("hug-gentle")
        RecognitionScreen(
            RecognitionUiState.Ready(
                running = true, decision = hug, probability = 0.9, peers = listOf("bob"), peer = "bob", sendEnabled = true,
                sent = listOf(SentGesture(hug, "hug", "bob", 3.25)),
            ),
            null, RecognitionActions(),
        )
    }

    private val valid = mapOf(
        IconField.NAME to "buzz", IconField.ATTACK to "0.1", IconField.SUSTAIN to "0.2", IconField.LEVEL to "0.8",
        IconField.RELEASE to "0.1", IconField.NOTE to "60", IconField.PERIOD to "0.6", IconField.COUNT to "3",
    )

    @Test
    fun iconEditor_valid() = screen("icon-editor", Variant.MAIN) {
        IconEditorScreen(IconEditorViewModel.validate(valid), IconEditorActions())
    }

    @Test
    fun iconEditor_invalidLevel() = screen("icon-editor-error") {
        IconEditorScreen(IconEditorViewModel.validate(valid + (IconField.LEVEL to "1.5")), IconEditorActions())
    }
}
