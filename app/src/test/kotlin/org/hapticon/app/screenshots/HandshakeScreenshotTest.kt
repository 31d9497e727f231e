package org.hapticon.app.screenshots

import androidx.compose.runtime.getValue
import org.hapticon.app.playback.usageVibrator
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.feature.glove.HandshakeActions
import org.hapticon.app.feature.glove.HandshakeScreen
import org.hapticon.app.feature.glove.HandshakeViewModel
import org.hapticon.app.playback.VibratorVibrationOutput
import org.hapticon.app.playback.defaultVibrator
import org.hapticon.app.sensors.TestCalibrationStore
import org.hapticon.app.sensors.TestClock
import org.hapticon.app.sensors.TestGloveSource
import org.hapticon.app.sensors.TestHandshakeLink
import org.hapticon.app.sensors.TestPartnerHand
import org.hapticon.sensor.glove.FlexCalibration
import org.junit.Test

/** The tele-handshake (Sensors › Handshake) gripping the simulated partner's hand. */
class HandshakeScreenshotTest : ScreenshotTest() {
    private val glove = TestGloveSource()
    private val viewModel = HandshakeViewModel(
        glove, TestCalibrationStore(), VibratorVibrationOutput(usageVibrator(defaultVibrator(ApplicationProvider.getApplicationContext()))),
        simulatedPartner = TestPartnerHand(thumbDegrees = 0.0, middleDegrees = 67.95), clock = TestClock(),
        link = TestHandshakeLink(),
    )

    @Test
    fun handshake_gripping() = screen("glove-handshake", Variant.MAIN, prepare = {
        viewModel.setSimulatedPartner(true)
        glove.push(glove.voltsAt(40.0, FlexCalibration.THUMB_DEFAULT), glove.voltsAt(75.0, FlexCalibration.MIDDLE_DEFAULT))
        compose.mainClock.advanceTimeBy(100)
        compose.waitForIdle()
    }) {
        val state by viewModel.uiState.collectAsStateWithLifecycle()
        HandshakeScreen(state, HandshakeActions(onSimulatedPartner = viewModel::setSimulatedPartner, onVibration = viewModel::setVibration))
    }
}
