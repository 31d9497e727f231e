package org.hapticon.sensor.glove

import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

/** The glove as the session's frames carry it: which channels, and how counts become divider volts. */
class SessionGloveSourceTest {
    private val session = SensorSession(TestUsbDevices())
    private val glove = SessionGloveSource(session)
    private val heard = ArrayList<Triple<Double, Double, Long>>()
    private val frame = LiveFrame()

    init {
        glove.addListener { thumb, middle, nanos -> heard += Triple(thumb, middle, nanos) }
    }

    private fun send(info: StreamInfo, vararg values: Double) {
        frame.channelCount = values.size
        values.copyInto(frame.values)
        frame.receivedNanos = 42
        glove.onFrame(frame, info)
    }

    @Test
    fun lucidGloves_thumbIsAAndMiddleIsCInTwelveBitCounts() {
        send(StreamInfo(SensorProtocol.LUCID_GLOVES, listOf("thumb", "index", "middle", "ring", "pinky")), 4095.0, 1.0, 0.0, 2.0, 3.0)

        val supply = glove.divider.supplyVolts
        assertEquals(Triple(supply, 0.0, 42L), heard.single())
    }

    @Test
    fun csv_channelsZeroAndOneInTenBitCounts_outOfRangeIsNaN() {
        send(StreamInfo(SensorProtocol.CSV, listOf("a", "b")), 1023.0, 1024.0)

        assertEquals(glove.divider.supplyVolts, heard.single().first, 0.0)
        assertTrue(heard.single().second.isNaN())
    }

    @Test
    fun framedMillivolts_areVolts_andAnglesAreNotFlexVoltages() {
        val info = StreamInfo(SensorProtocol.FRAMED, listOf("ch0 (mV)", "ch1 (°)"), listOf(ChannelUnit.MILLIVOLT, ChannelUnit.CENTIDEGREE))
        send(info, 1250.0, 4500.0)

        assertEquals(1.25, heard.single().first, 0.0)
        assertTrue(heard.single().second.isNaN())
    }

    @Test
    fun chosenChannels_replaceTheProtocolDefaults() {
        glove.setChannels(GloveChannels(thumb = 2, middle = 0, adcBits = 10))
        send(StreamInfo(SensorProtocol.CSV, listOf("a", "b", "c")), 0.0, 5.0, 1023.0)

        assertEquals(glove.divider.supplyVolts, heard.single().first, 0.0)
        assertEquals(0.0, heard.single().second, 0.0)
    }

    @Test
    fun failingListener_isDroppedAndReported_othersStillHear() {
        glove.addListener { _, _, _ -> throw IllegalStateException("screen gone") }
        send(StreamInfo(SensorProtocol.CSV, listOf("a", "b")), 0.0, 0.0)
        send(StreamInfo(SensorProtocol.CSV, listOf("a", "b")), 0.0, 0.0)

        assertEquals("screen gone", glove.listenerError.value)
        assertEquals(2, heard.size)
    }

    @Test
    fun connected_followsTheSessionsStream() = runBlocking {
        assertFalse(glove.connected.first())
        session.start(FakeSerialPort(), TEST_UNO, SensorProtocol.CSV, 115_200)
        try {
            assertTrue(glove.connected.first())
        } finally {
            session.disconnect()
        }
    }
}
