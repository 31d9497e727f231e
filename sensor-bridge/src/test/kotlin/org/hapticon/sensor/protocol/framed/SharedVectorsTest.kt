package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.Recorder
import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

/** The Kotlin side of the vectors shared with the firmware (test-fixtures streams/framed-vectors.txt). */
class SharedVectorsTest {
    private val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)

    /** The `device` line of the vectors: the reference device the exchanges run on. */
    private val referenceDevice = DeviceInfo(1, 0, 0, 12, 1000, 5,
        listOf(ChannelUnit.RAW, ChannelUnit.RAW, ChannelUnit.RAW, ChannelUnit.GRAM, ChannelUnit.CENTIDEGREE), "hapticon-ref")

    private fun info(a: List<String>) = DeviceInfo(a[0].toInt(), a[1].toInt(), a[2].toInt(), a[3].toInt(), a[4].toInt(), a[5].toInt(),
        a[6].split(',').map { ChannelUnit.of(it.toInt()) }, if (a[7] == "-") "" else a[7])

    private fun ints(values: List<String>) = values.map { it.toInt() }.toIntArray()

    @Test
    fun frameVectors_kotlinEncoder_writesExactlyTheWireBytes() {
        val vectors = RecordedStreams.framedVectors()
        assertEquals(13, vectors.size)
        for (v in vectors) {
            val encoder = FramedEncoder(v.sequence)
            val a = v.args
            val n = when (v.type) {
                "sample" -> encoder.sample(a[0].toLong(), ints(a.drop(1)), buffer)
                "info" -> encoder.deviceInfo(info(a), buffer)
                "ack" -> encoder.ack(a[0].toInt(), AckStatus.of(a[1].toInt()), a[2].toInt(), buffer)
                "set-outputs" -> encoder.setOutputs(a[0].toInt(), ints(a.drop(1)), buffer)
                "request-info" -> encoder.requestInfo(buffer)
                "set-sample-rate" -> encoder.setSampleRate(a[0].toInt(), buffer)
                else -> throw AssertionError("unknown type ${v.type} in ${v.name}")
            }
            assertArrayEquals(v.name, v.wire, buffer.copyOf(n))
        }
    }

    @Test
    fun frameVectors_deviceToHost_decodeToTheirFields() {
        var checked = 0
        for (v in RecordedStreams.framedVectors()) {
            val recorder = Recorder()
            val decoder = FramedDecoder(recorder)
            decoder.feed(v.wire)
            val a = v.args
            when (v.type) {
                "sample" -> assertEquals(v.name, listOf("sample ${v.sequence} t=${a[0]} ${a.drop(1).joinToString(",")}"), recorder.events)
                "info" -> assertEquals(v.name, listOf(info(a)), recorder.infos)
                "ack" -> assertEquals(v.name, listOf("ack ${a[0]} ${AckStatus.of(a[1].toInt())} ${a[2]}"), recorder.events)
                else -> {
                    // Host-to-device commands are not for this decoder.
                    assertEquals(v.name, 1L, decoder.stats.badFrames(org.hapticon.sensor.protocol.stream.FrameError.UNKNOWN_TYPE))
                    continue
                }
            }
            assertEquals(v.name, 0L, decoder.stats.badFrames)
            checked++
        }
        assertEquals(9, checked)
    }

    @Test
    fun exchanges_commandsWithinTheLimits_areWhatTheKotlinEncoderSends() {
        val reencoded = ArrayList<String>()
        for (x in RecordedStreams.exchanges()) {
            val frame = Cobs.decode(x.command.copyOf(x.command.size - 1))!!
            val version = frame[0].toInt()
            val type = frame[1].toInt() and 0xFF
            val sequence = (frame[2].toInt() and 0xFF) or ((frame[3].toInt() and 0xFF) shl 8)
            val payload = frame.copyOfRange(4, frame.size - 2)
            val crcGood = Crc16.compute(frame) == 0
            if (version != FramedProtocol.VERSION || !crcGood) continue
            val encoder = FramedEncoder(sequence)
            val n = when (type) {
                FramedProtocol.TYPE_SET_OUTPUTS -> {
                    if (payload.size % 2 == 0) continue // malformed on purpose
                    val values = IntArray((payload.size - 1) / 2) { (payload[1 + 2 * it].toInt() and 0xFF) or ((payload[2 + 2 * it].toInt() and 0xFF) shl 8) }
                    try {
                        encoder.setOutputs(payload[0].toInt(), values, buffer)
                    } catch (e: SafetyLimitException) {
                        // The host refuses what the firmware would NACK as out of range.
                        assertEquals(x.name, "OUT_OF_RANGE", x.expected)
                        reencoded += "${x.name} refused"
                        continue
                    }
                }
                FramedProtocol.TYPE_REQUEST_INFO -> encoder.requestInfo(buffer)
                FramedProtocol.TYPE_SET_SAMPLE_RATE -> encoder.setSampleRate(
                    (payload[0].toInt() and 0xFF) or ((payload[1].toInt() and 0xFF) shl 8) or ((payload[2].toInt() and 0xFF) shl 16) or (payload[3].toInt() shl 24),
                    buffer,
                )
                else -> continue
            }
            assertArrayEquals(x.name, x.command, buffer.copyOf(n))
            reencoded += x.name
        }
        assertEquals(listOf("set-outputs-ok", "set-outputs-partial", "set-outputs-out-of-range refused", "set-outputs-bad-output", "request-info",
            "set-sample-rate-ok", "set-sample-rate-too-high"), reencoded)
    }

    @Test
    fun exchanges_answers_decodeToTheExpectedAckOrInfo() {
        val exchanges = RecordedStreams.exchanges()
        assertEquals(11, exchanges.size)
        for (x in exchanges) {
            val commandSequence = Cobs.decode(x.command.copyOf(x.command.size - 1))!!.let { (it[2].toInt() and 0xFF) or ((it[3].toInt() and 0xFF) shl 8) }
            val recorder = Recorder()
            val decoder = FramedDecoder(recorder)
            decoder.feed(x.answer)
            when (x.expected) {
                "NONE" -> assertEquals(x.name, 0, x.answer.size)
                "INFO" -> assertEquals(x.name, listOf(referenceDevice), recorder.infos)
                else -> {
                    assertEquals(x.name, 1, recorder.events.size)
                    val (word, sequence, status) = recorder.events.single().split(' ')
                    assertEquals(x.name, "ack", word)
                    assertEquals(x.name, commandSequence.toString(), sequence)
                    assertEquals(x.name, x.expected, status)
                }
            }
            assertEquals(x.name, 0L, decoder.stats.badFrames)
        }
    }
}
