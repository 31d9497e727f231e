package org.hapticon.testing

import org.hapticon.sensor.protocol.FrameSink
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.SensorProtocols
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.ValuesDocument
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * An example board protocol, added the way any new one is (docs/protocols.md, "Adding a protocol"): this one
 * file, and one row in a registry ([WITH_EXAMPLE] here; `SensorProtocols.DEFAULT` in the product). Tab-separated
 * numbers per line, channels named `tab0`, `tab1`, …; `hapticon decode` writes each line as a [ValuesDocument].
 */
object TabSeparatedProtocol : SensorProtocol {
    override val label: String = "Tabs"

    override val cliName: String = "tabs"

    override fun decoder(sink: FrameSink): StreamDecoder {
        val frame = LiveFrame()
        var info = initialInfo()
        return CsvDecoder({ sample ->
            val n = sample.fieldCount
            if (n != info.channelCount) info = StreamInfo(this, List(n) { "tab$it" })
            sample.values.copyInto(frame.values, 0, 0, n)
            frame.channelCount = n
            sink.onFrame(frame, info)
            sink.documents?.write(ValuesDocument.serializer(), ValuesDocument.of(cliName, frame))
        }, separator = '\t')
    }

    /** The product's protocols and this one, as the app, `hapticon decode` and the tests read a registry. */
    val WITH_EXAMPLE: SensorProtocols = SensorProtocols.DEFAULT + this
}
