package org.hapticon.sensor.protocol

import kotlinx.serialization.SerializationStrategy
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * A byte protocol a board may speak (docs/protocols.md): the name the app shows ([label]), the one the `hapticon`
 * command line takes ([cliName]), and a [decoder] that turns its bytes into [LiveFrame]s. One implementation per
 * protocol, each registered by one row of [SensorProtocols.DEFAULT], which the app's protocol choice,
 * `hapticon decode` and the benches read, as usb-serial-for-android registers one driver per chip family in its
 * probe table.
 */
public interface SensorProtocol {
    /** The name the app shows. */
    public val label: String

    /** The `--protocol` value of `hapticon decode`: lower case, unique in a registry. */
    public val cliName: String

    /**
     * A fresh decoder of this protocol's bytes that hands every frame to [sink], on the thread that feeds it
     * (see [StreamDecoder]). Decoders of the live path must not allocate per frame; they build the protocol's
     * JSON documents only when [FrameSink.documents] asks for them.
     */
    public fun decoder(sink: FrameSink): StreamDecoder

    /** What is known about a stream of this protocol before it has said anything; by default nothing. */
    public fun initialInfo(): StreamInfo = StreamInfo(this, emptyList())

    /** The ADC resolution a stream of this protocol is assumed to have when it does not say (Arduino's 10 bits). */
    public val assumedAdcBits: Int get() = 10

    public companion object {
        /** Lines of numbers, as Arduino sketches print them. */
        public val CSV: SensorProtocol get() = CsvProtocol

        /** LucidGloves / OpenGloves lines (the glove features read this one). */
        public val LUCID_GLOVES: SensorProtocol get() = LucidGlovesProtocol

        /** The Hapticon framed binary protocol, the only one that carries commands and acks. */
        public val FRAMED: SensorProtocol get() = FramedBinaryProtocol
    }
}

/**
 * Where a protocol's decoder delivers, on the decoding thread. [onFrame] is the common shape every reader uses;
 * the others are for what only some protocols carry.
 */
public interface FrameSink {
    /** One decoded frame with what is known of the stream; [frame] is reused and valid only during this call. */
    public fun onFrame(frame: LiveFrame, info: StreamInfo)

    /** The stream described itself (framed device info): [info] replaces what was known. */
    public fun onInfo(info: StreamInfo) {}

    /** The board answered the command numbered [sequence] (framed protocol; see [AckStatus]). */
    public fun onAck(sequence: Int, status: AckStatus, detail: Int) {}

    /**
     * Where the decoder writes its protocol's JSON document of each frame, device info or ack (`hapticon decode`'s
     * lines), or null when nobody reads them: the default, so the live path builds none.
     */
    public val documents: FrameDocuments? get() = null
}

/** Receives a protocol's own JSON documents, each with its serializer (docs/json.md, "hapticon decode"). */
public interface FrameDocuments {
    /** One document, written as one JSON object. */
    public fun <T> write(serializer: SerializationStrategy<T>, document: T)
}

/** Baud rates offered in the UI; 1200 is left out on purpose (it reboots native-USB boards). */
public val BAUD_RATES: List<Int> = listOf(9_600, 19_200, 38_400, 57_600, 115_200, 230_400, 460_800, 921_600)
