package org.hapticon.app.sensors

import android.os.Process
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.di.AppContainer
import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.util.concurrent.ArrayBlockingQueue
import java.util.concurrent.TimeUnit

@RunWith(RobolectricTestRunner::class)
class ReaderThreadPriorityTest {
    @Test
    fun appSession_readerThreadDecidesAtUrgentAudioPriority_callerUnchanged() {
        // The app's own graph: its session's reader thread is where GrainEngine decides the grains.
        val container = AppContainer.create(ApplicationProvider.getApplicationContext(), usbDevices = TestUsbDevices())
        val session = container.sensorSession
        val seen = ArrayBlockingQueue<Pair<String, Int>>(16)
        session.addFrameListener(FrameListener { _, _ -> seen.offer(Thread.currentThread().name to Process.getThreadPriority(Process.myTid())) })
        val port = FakeSerialPort()
        val encoder = FramedEncoder()
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        port.enqueue(buffer.copyOf(encoder.deviceInfo(DeviceInfo(1, 0, 0, 12, 1000, 0, listOf(ChannelUnit.RAW), "board12"), buffer)))
        port.enqueue(buffer.copyOf(encoder.sample(0, intArrayOf(2048), buffer)))
        try {
            session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
            val frame = seen.poll(10, TimeUnit.SECONDS)
            assertEquals("hapticon-sensor-reader" to Process.THREAD_PRIORITY_URGENT_AUDIO, frame)
            assertEquals(-19, ReaderThreadPriority.PRIORITY)
            // Only the reader was raised, not the thread that started the stream.
            assertEquals(Process.THREAD_PRIORITY_DEFAULT, Process.getThreadPriority(Process.myTid()))
        } finally {
            session.disconnect()
        }
    }
}
