package org.hapticon.app.gesture

import android.hardware.Sensor
import android.hardware.SensorEvent
import android.hardware.SensorEventListener
import android.hardware.SensorManager
import android.os.Handler
import android.os.HandlerThread

/**
 * The phone's accelerometer ([Sensor.TYPE_ACCELEROMETER], gravity included) as [CHANNELS] in g — the same
 * names and unit as the FSR glove recordings and the synthetic gestures — resampled by zero-order hold to
 * [sampleRate] on the time stamps of the sensor events. Events are received on a [HandlerThread] of its
 * own, which is where frames are delivered. The sensor is asked for [REQUEST_PERIOD_US] (200 Hz), below
 * the 200 Hz cap that needs no extra permission; phones deliver 100–200 Hz.
 */
class AccelerometerGestureSource(
    private val sensorManager: SensorManager,
    override val sampleRate: Double = DEFAULT_RATE_HZ,
) : GestureSource {
    // Held while a frame is delivered and while stopping, so no frame arrives after stop() returns.
    private val lock = Any()
    private var thread: HandlerThread? = null
    private var listener: SensorEventListener? = null

    override val label: String get() = "Accelerometer"
    override val channels: List<GestureChannel> get() = CHANNELS

    @Volatile override var running: Boolean = false
        private set

    /** Whether this phone has an accelerometer at all. */
    val available: Boolean get() = sensorManager.getDefaultSensor(Sensor.TYPE_ACCELEROMETER) != null

    override fun start(sink: GestureSink) {
        check(!running) { "the accelerometer is already recording" }
        val sensor = sensorManager.getDefaultSensor(Sensor.TYPE_ACCELEROMETER)
            ?: throw IllegalStateException("This phone has no accelerometer")
        val hold = ZeroOrderHold(sampleRate, CHANNELS.size, sink)
        val values = DoubleArray(CHANNELS.size)
        val newListener = object : SensorEventListener {
            override fun onSensorChanged(event: SensorEvent) {
                synchronized(lock) {
                    if (!running) return
                    for (i in values.indices) values[i] = event.values[i] / SensorManager.STANDARD_GRAVITY.toDouble()
                    hold.update(event.timestamp, values)
                }
            }

            override fun onAccuracyChanged(sensor: Sensor?, accuracy: Int) = Unit
        }
        val newThread = HandlerThread("hapticon-accelerometer").also { it.start() }
        running = true
        if (!sensorManager.registerListener(newListener, sensor, REQUEST_PERIOD_US, Handler(newThread.looper))) {
            running = false
            newThread.quitSafely()
            throw IllegalStateException("The accelerometer could not be started")
        }
        listener = newListener
        thread = newThread
    }

    override fun stop() {
        synchronized(lock) { running = false }
        listener?.let { sensorManager.unregisterListener(it) }
        listener = null
        thread?.quitSafely()
        thread = null
    }

    companion object {
        /** 100 Hz: what the recognition models and the synthetic gestures use. */
        const val DEFAULT_RATE_HZ: Double = 100.0

        /** Requested sensor period in µs (200 Hz). */
        const val REQUEST_PERIOD_US: Int = 5_000

        /** The channels delivered, in order. */
        val CHANNELS: List<GestureChannel> = listOf(GestureChannel("accel_x", "g"), GestureChannel("accel_y", "g"), GestureChannel("accel_z", "g"))
    }
}
