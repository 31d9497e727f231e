package org.hapticon.app.di

import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.sensors.SessionStimulatorLink
import android.content.Context
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.VibrationOutput
import org.hapticon.app.playback.VibratorVibrationOutput
import org.hapticon.sensor.usb.AndroidUsbDevices
import org.hapticon.app.sensors.CalibrationStore
import org.hapticon.app.sensors.SharedPreferencesCalibrationStore
import org.hapticon.app.sensors.ReaderThreadPriority
import org.hapticon.app.study.StudyComponent
import org.hapticon.app.sync.ChatComponent
import org.hapticon.sensor.glove.SessionGloveSource
import org.hapticon.sensor.glove.PartnerHand
import org.hapticon.sensor.glove.SimulatedPartner
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.live.UsbDevices

/**
 * The app's dependencies, built once per process (manual injection: small app, no framework). It lives in its own
 * package, below the root package's application and activity that hold it and above the features that read it,
 * so that no package imports the root (docs/architecture.md, "Packages do not import each other in a cycle").
 *
 * The sensor side is one live connection ([sensorSession]) shared by the Sensors screen, the FSR grain
 * mode ([grainEngine]) and the glove screens ([glove]), which all listen to the same stream.
 */
class AppContainer(
    val iconRepository: IconRepository,
    val player: HapticPlayer,
    val vibration: VibrationOutput,
    val usbDevices: UsbDevices,
    val sensorSession: SensorSession,
    val grainEngine: GrainEngine,
    val glove: SessionGloveSource,
    val calibrations: CalibrationStore,
    /** Makes the simulated partner of the handshake screen's toggle. */
    val simulatedPartner: () -> PartnerHand = { SimulatedPartner() },
    /** Chat: Room storage, settings, the background sync and adaptive playback; null in containers built without it. */
    val chat: ChatComponent? = null,
    /** The user-study mode: protocols, sessions, masking noise, export; null in containers built without it. */
    val study: StudyComponent? = null,
    /** Gesture recording, recognition and their files; null in containers built without it. */
    val gestures: GestureComponent? = null,
    /** The user's haptic patterns (imported AHAP / `.haptic` / pattern JSON); null in containers built without it. */
    val patterns: RoomPatternRepository? = null,
) {
    /**
     * The one command link to the electrotactile board, shared by calibration and the compliance study: one
     * [org.hapticon.sensor.protocol.framed.FramedEncoder] per session, so their commands never reuse a sequence
     * number and each ack matches the command it answers (FramedEncoder: one sequence per direction).
     */
    val stimulator: StimulatorLink by lazy { SessionStimulatorLink(sensorSession) }

    /** A pattern file shared to or opened with Hapticon, waiting for the Icons screen to import it. */
    val pendingPatternFile: kotlinx.coroutines.flow.MutableStateFlow<android.net.Uri?> = kotlinx.coroutines.flow.MutableStateFlow(null)

    companion object {
        /** The production graph, with [usbDevices] and [vibration] replaceable for tests. */
        fun create(
            context: Context,
            usbDevices: UsbDevices = AndroidUsbDevices(context),
            vibration: VibrationOutput = VibratorVibrationOutput.create(context),
            calibrations: CalibrationStore = SharedPreferencesCalibrationStore(context),
        ): AppContainer {
            // The reader thread decides the grains: raised to urgent-audio priority before its first read.
            val session = SensorSession(usbDevices, readerThreadSetup = ReaderThreadPriority::applyToCurrentThread)
            val grains = GrainEngine(vibration).also { session.addFrameListener(it) }
            // One database for chat and study: two Room instances on one file would not see each other's writes.
            val db = HapticonDatabase.create(context)
            val chat = ChatComponent.create(context, db = db)
            return AppContainer(
                // One icon list and one player for every screen: the presets plus the user's own icons,
                // played with the best renderer this phone has.
                iconRepository = chat.icons,
                player = chat.player,
                vibration = vibration,
                usbDevices = usbDevices,
                sensorSession = session,
                grainEngine = grains,
                glove = SessionGloveSource(session),
                calibrations = calibrations,
                chat = chat,
                study = StudyComponent.create(context, db),
                gestures = GestureComponent.create(context, session) { grains.currentConfig },
                // The chat's pattern store: the Icons tab and the composer see the same patterns.
                patterns = chat.patterns,
            )
        }
    }
}
