package org.hapticon.app.gesture

import android.content.Context
import android.hardware.Sensor
import android.hardware.SensorManager
import android.view.MotionEvent
import androidx.test.core.app.ApplicationProvider
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.shadows.ShadowSensor
import org.robolectric.shadows.SensorEventBuilder

/** The touchscreen and accelerometer sources: exact resampled frames for scripted events. */
@RunWith(RobolectricTestRunner::class)
class TouchGestureSourceTest {
    private val frames = ArrayList<DoubleArray>()
    private val ms = 1_000_000L

    @Test
    fun touch_scriptedEvents_zeroOrderHoldAt200HzWithVelocityAndZeroAfterUp() {
        // The grid starts at 1000 ms (the clock minus the ticker's lag): frames every 5 ms.
        val source = TouchGestureSource(clockNanos = { 1000 * ms + TouchGestureSource.LAG_NANOS }, autoTick = false)
        source.start { frames += it.copyOf() }
        source.onMotionEvent(MotionEvent.obtain(1000, 1012, MotionEvent.ACTION_DOWN, 100f, 200f, 0.5f, 0.25f, 0, 1f, 1f, 0, 0))
        val move = MotionEvent.obtain(1000, 1017, MotionEvent.ACTION_MOVE, 105f, 195f, 0.625f, 0.375f, 0, 1f, 1f, 0, 0)
        move.addBatch(1020, 110f, 190f, 0.75f, 0.5f, 0) // 1017 becomes a historical sample
        source.onMotionEvent(move)
        source.onMotionEvent(MotionEvent.obtain(1000, 1031, MotionEvent.ACTION_UP, 110f, 190f, 0f, 0f, 0, 1f, 1f, 0, 0))
        source.pump(1040 * ms)

        val rest = doubleArrayOf(0.0, 0.0, 0.0, 0.0)
        val down = doubleArrayOf(0.5, 0.25, 0.0, 0.0)
        // 1017 → 1020: 5 px in 3 ms.
        val moving = doubleArrayOf(0.75, 0.5, 5 / 0.003, -5 / 0.003)
        val expected = listOf(rest, rest, rest, down, moving, moving, moving, rest) // 1000, 1005, …, 1035 ms
        assertEquals(expected.size, frames.size)
        for ((i, frame) in frames.withIndex()) assertArrayEquals("frame $i", expected[i], frame, 1e-9)
        assertEquals(listOf("pressure", "size", "velocity_x", "velocity_y"), source.channels.map { it.name })
        source.stop()
    }

    @Test
    fun touch_eventsWhileStoppedAreIgnoredAndPumpEmitsNothing() {
        val source = TouchGestureSource(clockNanos = { 0L }, autoTick = false)
        source.onMotionEvent(MotionEvent.obtain(0, 10, MotionEvent.ACTION_DOWN, 1f, 1f, 1f, 1f, 0, 1f, 1f, 0, 0))
        source.pump(1_000 * ms)
        assertEquals(0, frames.size)
    }

    @Test
    fun zeroOrderHold_readingOlderThanEmittedFramesCountsAsNow() {
        val hold = ZeroOrderHold(100.0, 1) { frames += it.copyOf() }
        hold.update(0, doubleArrayOf(1.0))
        hold.advanceTo(25 * ms) // frames 0, 10, 20 ms
        hold.update(5 * ms, doubleArrayOf(2.0)) // late: applies from the next frame on
        hold.advanceTo(41 * ms)
        assertEquals(listOf(1.0, 1.0, 1.0, 2.0, 2.0), frames.map { it[0] })
        assertEquals(5L, hold.framesEmitted)
    }

    @Test
    fun zeroOrderHold_rejectsBadRateAndWrongWidth() {
        assertThrows(IllegalArgumentException::class.java) { ZeroOrderHold(Double.NaN, 1) {} }
        assertThrows(IllegalArgumentException::class.java) { ZeroOrderHold(0.0, 1) {} }
        val hold = ZeroOrderHold(100.0, 2) {}
        val e = assertThrows(IllegalArgumentException::class.java) { hold.update(0, doubleArrayOf(1.0)) }
        assertEquals("expected 2 values, got 1", e.message)
    }

    private fun sensorManager(): SensorManager =
        ApplicationProvider.getApplicationContext<Context>().getSystemService(SensorManager::class.java)

    @Test
    fun accelerometer_eventsResampledTo100HzInG() {
        val manager = sensorManager()
        shadowOf(manager).addSensor(ShadowSensor.newInstance(Sensor.TYPE_ACCELEROMETER))
        val source = AccelerometerGestureSource(manager)
        source.start { frames += it.copyOf() }
        fun send(atMillis: Long, x: Float, y: Float, z: Float) {
            val event = SensorEventBuilder.newBuilder()
                .setSensor(manager.getDefaultSensor(Sensor.TYPE_ACCELEROMETER)!!)
                .setValues(floatArrayOf(x, y, z))
                .setTimestamp(5_000 * ms + atMillis * ms)
                .build()
            shadowOf(manager).sendSensorEventToListeners(event)
        }
        val g = SensorManager.STANDARD_GRAVITY
        send(0, g, 0f, 0f)
        send(25, 0f, -g / 2, 0f) // frames at 0, 10, 20 ms hold the first reading
        send(41, 0f, 0f, g) // frames at 30, 40 ms hold the second
        source.stop()
        send(80, g, g, g) // after stop: nothing

        val expected = listOf(doubleArrayOf(1.0, 0.0, 0.0), doubleArrayOf(1.0, 0.0, 0.0), doubleArrayOf(1.0, 0.0, 0.0), doubleArrayOf(0.0, -0.5, 0.0), doubleArrayOf(0.0, -0.5, 0.0))
        assertEquals(expected.size, frames.size)
        for ((i, frame) in frames.withIndex()) assertArrayEquals("frame $i", expected[i], frame, 0.0)
        assertEquals(listOf("accel_x", "accel_y", "accel_z"), source.channels.map { it.name })
        assertEquals(listOf("g", "g", "g"), source.channels.map { it.unit })
    }

    @Test
    fun accelerometer_missingSensor_saysSo() {
        val source = AccelerometerGestureSource(sensorManager())
        val e = assertThrows(IllegalStateException::class.java) { source.start {} }
        assertEquals("This phone has no accelerometer", e.message)
    }
}
