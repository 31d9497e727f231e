package org.hapticon.app.gesture

import org.hapticon.sensor.live.SensorSession
import android.content.Context
import android.hardware.SensorManager
import org.hapticon.sensor.grains.GrainConfig
import java.io.File

/** The kinds of live source the Gestures screens offer (a file is imported, not streamed). */
enum class GestureSourceKind(val label: String) {
    TOUCH("Touchscreen"),
    ACCELEROMETER("Accelerometer"),
    SENSOR_BOARD("Sensor board"),
}

/**
 * Everything the Gestures destination needs, built once in the [org.hapticon.app.di.AppContainer]: one
 * instance of each [GestureSource] (the touch pad and the recorder share the touch source), the
 * recording files and the personal model file.
 */
class GestureComponent(
    /** The touchscreen source, also fed by the touch pad on screen. */
    val touch: TouchGestureSource,
    private val accelerometer: GestureSource?,
    private val sensorBoard: GestureSource,
    /** The saved recordings. */
    val recordings: RecordingStore,
    /** The personal recognition model. */
    val models: GestureModelStore,
    /** The social-touch (LogitBoost) model. */
    val socialTouch: SocialTouchModelStore,
) {
    /** The source of [kind], or null when this phone lacks it (no accelerometer). */
    fun source(kind: GestureSourceKind): GestureSource? = when (kind) {
        GestureSourceKind.TOUCH -> touch
        GestureSourceKind.ACCELEROMETER -> accelerometer
        GestureSourceKind.SENSOR_BOARD -> sensorBoard
    }

    companion object {
        /**
         * Recordings in `filesDir/recordings`, the models in `filesDir/gesture-model.json` and `filesDir/social-touch-model.json`;
         * the sensor board's force channel is levelled against the grain mode's calibrated range ([grains]).
         */
        fun create(context: Context, session: SensorSession, grains: () -> GrainConfig? = { null }): GestureComponent {
            val sensors = context.getSystemService(SensorManager::class.java)
            val accelerometer = sensors?.let { AccelerometerGestureSource(it) }?.takeIf { it.available }
            return GestureComponent(
                touch = TouchGestureSource(),
                accelerometer = accelerometer,
                sensorBoard = SensorSessionGestureSource(session, grains),
                recordings = FileRecordingStore(File(context.filesDir, "recordings")),
                models = FileGestureModelStore(File(context.filesDir, "gesture-model.json")),
                socialTouch = FileSocialTouchModelStore(File(context.filesDir, "social-touch-model.json")),
            )
        }
    }
}
