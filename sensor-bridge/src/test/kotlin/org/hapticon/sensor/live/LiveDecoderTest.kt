package org.hapticon.sensor.live

import org.hapticon.sensor.protocol.SensorProtocol
import org.junit.Assert.assertEquals
import org.junit.Test
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo

/** Each protocol's frames as one [LiveFrame] shape, with the stream info the session shows. */
class LiveDecoderTest {
    private val seen = ArrayList<Pair<List<Double>, StreamInfo>>()
    private val times = ArrayList<Long>()

    private fun decoder(protocol: SensorProtocol) = LiveDecoder(protocol) { frame, info ->
        seen += List(frame.channelCount) { frame[it] } to info
        times += frame.receivedNanos
    }

    @Test
    fun lucidGloves_curlsAreFiveChannelsNamedByFinger() {
        val live = decoder(SensorProtocol.LUCID_GLOVES)
        live.nowNanos = 7
        live.decoder.feed("A1B2C3D4E4095\n".toByteArray())

        assertEquals(listOf(1.0, 2.0, 3.0, 4.0, 4095.0), seen.single().first)
        assertEquals(listOf("thumb", "index", "middle", "ring", "pinky"), seen.single().second.channelNames)
        assertEquals(listOf(7L), times)
    }

    @Test
    fun csvWithoutHeader_namesChannelsByIndex() {
        val live = decoder(SensorProtocol.CSV)
        live.nowNanos = 1
        live.decoder.feed("1,2\n".toByteArray())
        live.nowNanos = 2
        live.decoder.feed("3,4\n".toByteArray())

        assertEquals(listOf(listOf(1.0, 2.0), listOf(3.0, 4.0)), seen.map { it.first })
        assertEquals(listOf("ch0", "ch1"), seen[0].second.channelNames)
        // Without a header the count is learned from two lines, so the first sample arrives with the second.
        assertEquals(listOf(2L, 2L), times)
    }

    @Test
    fun csvHeader_namesTheChannels() {
        val live = decoder(SensorProtocol.CSV)
        live.decoder.feed("x,y,z\n5,6,7\n".toByteArray())

        assertEquals(listOf(5.0, 6.0, 7.0), seen.single().first)
        assertEquals(listOf("x", "y", "z"), seen.single().second.channelNames)
    }
}
