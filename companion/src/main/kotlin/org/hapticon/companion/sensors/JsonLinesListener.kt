package org.hapticon.companion.sensors

import kotlinx.serialization.SerializationStrategy
import org.hapticon.core.io.SchemaJson
import org.hapticon.sensor.protocol.FrameDocuments
import org.hapticon.sensor.protocol.FrameSink
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo
import java.io.Writer

/**
 * Hears any protocol's decoder and writes each of the protocol's own documents (a frame, device info, an ack;
 * [org.hapticon.sensor.protocol.SensorProtocol.decoder]) to [out] as one line of compact JSON.
 */
class JsonLinesListener(private val out: Writer) : FrameSink, FrameDocuments {
    override val documents: FrameDocuments get() = this

    // The protocol writes its own document of every frame; the common shape adds nothing to it.
    override fun onFrame(frame: LiveFrame, info: StreamInfo) {}

    /** Writes [document] as one line. */
    override fun <T> write(serializer: SerializationStrategy<T>, document: T) {
        out.write(SchemaJson.encode(serializer, document))
        out.write("\n")
    }
}
