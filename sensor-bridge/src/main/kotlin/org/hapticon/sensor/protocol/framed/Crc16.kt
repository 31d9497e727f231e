package org.hapticon.sensor.protocol.framed

/**
 * CRC-16/CCITT-FALSE (called CRC-16/IBM-3740 in the RevEng catalogue): polynomial 0x1021, initial
 * value 0xFFFF, no reflection, no final XOR; check value 0x29B1 for the ASCII bytes "123456789".
 * Because nothing is reflected or XORed at the end, running it over data followed by its CRC (high
 * byte first) gives 0.
 */
internal object Crc16 {
    const val INITIAL: Int = 0xFFFF

    private val TABLE = IntArray(256) { index ->
        var crc = index shl 8
        repeat(8) { crc = if (crc and 0x8000 != 0) (crc shl 1) xor 0x1021 else crc shl 1 }
        crc and 0xFFFF
    }

    /** The CRC of [length] bytes of [bytes] from [offset], continuing from [crc]. */
    fun compute(bytes: ByteArray, offset: Int = 0, length: Int = bytes.size - offset, crc: Int = INITIAL): Int {
        var c = crc
        for (i in offset until offset + length) {
            c = ((c shl 8) xor TABLE[((c ushr 8) xor bytes[i].toInt()) and 0xFF]) and 0xFFFF
        }
        return c
    }
}
