package org.hapticon.app.navigation

import androidx.compose.runtime.Composable
import org.hapticon.app.di.AppContainer
import org.hapticon.app.feature.chat.ChatsNavigation
import org.hapticon.app.feature.chat.ChatsRoute
import org.hapticon.app.feature.gesture.GesturesRoute
import org.hapticon.app.feature.glove.CalibrationRoute
import org.hapticon.app.feature.glove.HandshakeRoute
import org.hapticon.app.feature.iconeditor.IconEditorRoute
import org.hapticon.app.feature.icons.IconsRoute
import org.hapticon.app.feature.sensors.ElectrotactileCalibrationRoute
import org.hapticon.app.feature.sensors.SensorsRoute
import org.hapticon.app.feature.study.StudyRoute
import org.hapticon.app.sensors.NoHandshakeLink

/**
 * Each top-level destination wired from the [AppContainer]: the container is opened here, so a feature's route
 * receives only the repositories and links it uses, and a screen one feature borrows from another (the icon editor
 * in Chats, the glove screens in Sensors, the electrotactile calibration in Study) is handed in as a composable.
 * No feature package imports another.
 */
@Composable
internal fun Destination(
    container: AppContainer,
    destination: TopLevelDestination,
    chatsNavigation: ChatsNavigation,
    onSelect: (TopLevelDestination) -> Unit,
) {
    when (destination) {
        // A container built without chat (some tests) shows an empty Chats destination.
        TopLevelDestination.CHATS -> container.chat?.let { chat ->
            ChatsRoute(
                chat,
                iconEditor = { onDone -> IconEditorRoute(chat.icons, chat.player, onDone) },
                onOpenStudy = { onSelect(TopLevelDestination.STUDY) },
                navigation = chatsNavigation,
            )
        }
        TopLevelDestination.ICONS -> IconsRoute(container.iconRepository, container.player, container.patterns, container.pendingPatternFile)
        TopLevelDestination.SENSORS -> SensorsRoute(
            container.usbDevices, container.sensorSession, container.grainEngine, container.glove, container.stimulator,
            gloveCalibration = { onBack -> CalibrationRoute(container.glove, container.calibrations, onBack) },
            handshake = { onBack ->
                HandshakeRoute(
                    container.glove, container.calibrations, container.vibration, container.simulatedPartner,
                    link = container.chat?.sync ?: NoHandshakeLink, onBack = onBack,
                )
            },
        )
        TopLevelDestination.STUDY -> StudyRoute(
            container.study, container.player, container.iconRepository, container.stimulator,
            electrotactileCalibration = { key, onBack -> ElectrotactileCalibrationRoute(container.stimulator, onBack, key) },
        )
        TopLevelDestination.GESTURES -> {
            val chat = container.chat
            GesturesRoute(
                container.gestures, chat?.icons, chat?.repository, container.player,
                user = { chat?.settings?.preferences?.value?.userName },
                onSent = { chat?.sync?.wake() },
            )
        }
    }
}
