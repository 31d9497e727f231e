package org.hapticon.sensor.protocol.framed

/**
 * Consistent Overhead Byte Stuffing (Cheshire and Baker, 1999): removes every 0x00 from a frame so
 * that 0x00 can delimit frames, at a cost of one byte per started 254. Decoding is done
 * incrementally in [FramedDecoder]; this is the encoder, plus a whole-buffer decoder for tests.
 */
internal object Cobs {
    /** The most bytes [encode] writes for [length] input bytes (no delimiter). */
    fun maxEncodedLength(length: Int): Int = length + length / 254 + 1

    /**
     * Encodes [length] bytes of [source] from [offset] into [destination] from [destinationOffset],
     * without a delimiter, and returns the number of bytes written.
     */
    fun encode(source: ByteArray, offset: Int, length: Int, destination: ByteArray, destinationOffset: Int): Int {
        var codeAt = destinationOffset
        var out = destinationOffset + 1
        var code = 1
        val last = offset + length - 1
        for (i in offset..last) {
            val b = source[i]
            if (b.toInt() == 0) {
                destination[codeAt] = code.toByte()
                codeAt = out++
                code = 1
            } else {
                destination[out++] = b
                code++
                // A full block ends here; the canonical encoding starts the next only if data follows.
                if (code == 0xFF && i != last) {
                    destination[codeAt] = code.toByte()
                    codeAt = out++
                    code = 1
                }
            }
        }
        destination[codeAt] = code.toByte()
        return out - destinationOffset
    }

    /** Decodes one whole encoded frame (no delimiter); null if it is not valid COBS. */
    fun decode(encoded: ByteArray): ByteArray? {
        val out = java.io.ByteArrayOutputStream()
        var i = 0
        while (i < encoded.size) {
            val code = encoded[i].toInt() and 0xFF
            if (code == 0 || i + code > encoded.size) return null
            for (j in i + 1 until i + code) {
                if (encoded[j].toInt() == 0) return null
                out.write(encoded[j].toInt())
            }
            i += code
            if (code != 0xFF && i < encoded.size) out.write(0)
        }
        return out.toByteArray()
    }
}
