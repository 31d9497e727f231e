package org.hapticon.sensor.live

import org.hapticon.sensor.protocol.FrameListener
import org.hapticon.sensor.protocol.FrameSink
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * A decoder for [protocol] that hands each decoded frame, with what is known of the stream, to [listener]:
 * the decoding a [SensorSession] runs on its reading thread (without its counters and plot history), for
 * benches that drive a real [FrameListener] such as the grain engine. Frames carry no arrival time.
 */
public fun liveDecoderFor(protocol: SensorProtocol, listener: FrameListener): StreamDecoder =
    LiveDecoder(protocol, sink = { frame, info -> listener.onFrame(frame, info) }).decoder

/**
 * The session's side of one protocol's [decoder]: stamps each frame with its arrival time for [sink], keeps
 * [info] up to date and passes the board's acks on. Used only on the reading thread.
 */
internal class LiveDecoder(
    val protocol: SensorProtocol,
    /** Hears the board's acknowledgements (framed protocol), to settle the commands awaiting them. */
    private val acks: (sequence: Int, status: AckStatus, detail: Int) -> Unit = { _, _, _ -> },
    private val sink: (LiveFrame, StreamInfo) -> Unit,
) : FrameSink {
    /** Read by the receiver of a frame; replaced (never mutated) when the stream tells more. */
    @Volatile var info: StreamInfo = protocol.initialInfo()
        private set

    /** Set by the reader before each feed, so frames carry their arrival time. */
    var nowNanos: Long = 0

    val decoder: StreamDecoder = protocol.decoder(this)

    override fun onFrame(frame: LiveFrame, info: StreamInfo) {
        this.info = info
        frame.receivedNanos = nowNanos
        sink(frame, info)
    }

    override fun onInfo(info: StreamInfo) {
        this.info = info
    }

    override fun onAck(sequence: Int, status: AckStatus, detail: Int) {
        acks(sequence, status, detail)
    }
}
