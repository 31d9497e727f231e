package org.hapticon.app.screenshots

import org.hapticon.app.data.ElectrodeLevelsStore
import org.hapticon.app.feature.gesture.SocialTouchActions
import org.hapticon.app.feature.gesture.SocialTouchResult
import org.hapticon.app.feature.gesture.SocialTouchScreen
import org.hapticon.app.feature.gesture.SocialTouchUiState
import org.hapticon.app.feature.sensors.ElectrotactileActions
import org.hapticon.app.feature.sensors.ElectrotactileCalibrationScreen
import org.hapticon.app.feature.sensors.ElectrotactileUiState
import org.hapticon.app.feature.study.ComplianceActions
import org.hapticon.app.feature.study.ComplianceScreen
import org.hapticon.app.feature.study.ComplianceUiState
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.sensor.grains.FirmwareCommands
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandState
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.describeProblem
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.DrawingPoint
import org.hapticon.app.feature.study.DrawingCanvas
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.mutableStateListOf
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import java.time.Instant
import org.junit.Test

/** The sensing papers' screens: electrotactile calibration (Sensors), social touch (Gestures), the compliance study (Study). */
class SensingPapersScreenshotTest : ScreenshotTest() {
    @Test
    fun electrotactile_fifthElectrode() = screen("sensors-electrotactile", Variant.MAIN) {
        val steps = listOf(66, 72, 61, 80, 63, 60, 60, 60, 60)
        ElectrotactileCalibrationScreen(
            ElectrotactileUiState.Electrode(4, 63, AmplitudeSteps.milliampsOf(63), atCap = false, steps = steps, boardReady = true, message = null),
            ElectrotactileActions(),
        )
    }

    @Test
    fun electrotactile_wholeArrayCheck() = screen("sensors-electrotactile-check") {
        ElectrotactileCalibrationScreen(
            ElectrotactileUiState.WholeArrayCheck(
                sent = true, selected = 3, steps = listOf(66, 72, 61, 78, 63, 70, 64, 68, 75), boardReady = true, message = "Sent: press the sensor and feel the grains",
            ),
            ElectrotactileActions(),
        )
    }

    /**
     * A participant's calibration file from the laptop (`hapticon board calibrate --save`) just imported, before this
     * phone's own calibration began: the stored calibration is the file's, the grid still this session's first electrode.
     */
    @Test
    fun electrotactile_imported() = screen("sensors-electrotactile-imported") {
        val stored = StoredCalibration(ElectrotactileCalibrationResult(listOf(61, 62, 63, 64, 65, 66, 67, 68, 90)), Instant.parse("2026-11-20T09:30:00Z"), "P07")
        ElectrotactileCalibrationScreen(
            ElectrotactileUiState.Electrode(
                0, 60, AmplitudeSteps.milliampsOf(60), atCap = false, steps = List(9) { 60 }, boardReady = true,
                message = "Imported ${ElectrodeLevelsStore.describe(stored)}: the compliance study now stimulates at these levels",
            ),
            ElectrotactileActions(),
            stored,
        )
    }

    /**
     * The error card: the board never answered the second electrode's stimulus (the link failed). The line is the
     * session's own ([describeProblem] of the [CommandWriter]'s timeout), as the view model shows it.
     */
    @Test
    fun electrotactile_boardProblem() = screen("sensors-electrotactile-error") {
        val command = FirmwareCommands.stimulate(FramedEncoder(), FirmwareStimulus(1, 61))
        val noAnswer = CommandState.TimedOut("no acknowledgement within ${CommandWriter.ACK_TIMEOUT_MILLIS} ms")
        ElectrotactileCalibrationScreen(
            ElectrotactileUiState.Electrode(
                1, 61, AmplitudeSteps.milliampsOf(61), atCap = false, steps = listOf(66, 61, 60, 60, 60, 60, 60, 60, 60), boardReady = true,
                message = describeProblem(command.description, noAnswer), problem = true,
            ),
            ElectrotactileActions(),
        )
    }

    @Test
    fun socialTouch_recognised() = screen("gestures-social-touch", Variant.MAIN) {
        SocialTouchScreen(
            SocialTouchUiState.Ready(
                modelLabels = listOf("hug", "pat", "stroke"),
                results = listOf(SocialTouchResult("hug", 0.87, 1, 1.6, "touch pad"), SocialTouchResult("pat", 0.74, 3, 0.7, "touch pad")),
                peers = listOf("bob"), peer = "bob", sendEnabled = true,
            ),
            SocialTouchActions(),
        )
    }

    @Test
    fun compliance_trial() = screen("study-compliance-trial", Variant.MAIN) {
        val protocol = ComplianceStudy.PROTOCOL
        ComplianceScreen(
            ComplianceUiState.Trial("p7", protocol, protocol.trials(6)[16], protocol.trialCount, sent = true, boardReady = true, message = null),
            ComplianceActions(),
        )
    }

    @Test
    fun compliance_setup() = screen("study-compliance-setup") {
        ComplianceScreen(
            ComplianceUiState.Setup(ComplianceStudy.ALL, ComplianceStudy.PROTOCOL, "p7", 6, calibration, boardReady = true, message = null),
            ComplianceActions(),
        )
    }

    /** The break after the first repetition: the calibration is redone before the second (003_8ca1dc8f53472543.txt:150, :152). */
    @Test
    fun compliance_breakAndCalibration() = screen("study-compliance-break") {
        val protocol = ComplianceStudy.PROTOCOL
        ComplianceScreen(
            ComplianceUiState.Calibrate("p7", protocol, protocol.trials(6)[12], isBreak = true, calibration = calibration, fresh = false, boardReady = true, message = null),
            ComplianceActions(),
        )
    }

    /** Task 2: yes/no, then the outline drawn on the device's outline (one already drawn). */
    @Test
    fun compliance_drawing() = screen("study-compliance-drawing", Variant.MAIN) {
        val protocol = ComplianceStudy.SHAPES_PROTOCOL
        val contours = remember {
            mutableStateListOf(listOf(DrawingPoint(0.33, 0.31), DrawingPoint(0.52, 0.28), DrawingPoint(0.68, 0.36), DrawingPoint(0.7, 0.55), DrawingPoint(0.5, 0.66), DrawingPoint(0.31, 0.6)))
        }
        Column(Modifier.padding(16.dp)) {
            Text("p3 · trial 4 of ${protocol.trialCount}: the drawing area", style = MaterialTheme.typography.titleMedium)
            DrawingCanvas(contours, Modifier.fillMaxWidth())
        }
    }

    @Test
    fun compliance_drawingTrial() = screen("study-compliance-drawing-trial") {
        val protocol = ComplianceStudy.SHAPES_PROTOCOL
        ComplianceScreen(ComplianceUiState.Trial("p3", protocol, protocol.trials(2)[3], protocol.trialCount, sent = true, boardReady = true, message = null), ComplianceActions())
    }

    @Test
    fun compliance_done() = screen("study-compliance-done") {
        val protocol = ComplianceStudy.PROTOCOL
        val medians = ComplianceStudy.CONDITIONS.associate { it.id to (it.grains / 10.0 + it.mask.pattern.activeCount / 6.0) }
        ComplianceScreen(
            ComplianceUiState.Done(
                "p7", protocol, 36, java.io.File("p7-shaping-compliance.csv"), medians, summaryProblem = null,
                exported = java.io.File("p7-shaping-compliance.csv"), boardReady = true, message = null,
            ),
            ComplianceActions(),
        )
    }

    private val calibration = StoredCalibration(ElectrotactileCalibrationResult(listOf(66, 72, 61, 80, 63, 70, 64, 68, 75)), Instant.parse("2026-12-01T09:30:00Z"), "P07")
}
