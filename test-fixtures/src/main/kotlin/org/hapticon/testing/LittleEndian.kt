package org.hapticon.testing

/**
 * Little-endian field readers for asserting on binary headers (WAV, RIFF) byte by byte, so a test can
 * check exactly what a writer put at each offset rather than trusting a reader written alongside it.
 */
public object LittleEndian {
    /** The unsigned 16-bit value at [offset]. */
    public fun u16(bytes: ByteArray, offset: Int): Int =
        (bytes[offset].toInt() and 0xFF) or ((bytes[offset + 1].toInt() and 0xFF) shl 8)

    /** The unsigned 32-bit value at [offset]. */
    public fun u32(bytes: ByteArray, offset: Int): Long =
        (u16(bytes, offset).toLong()) or (u16(bytes, offset + 2).toLong() shl 16)

    /** The four ASCII characters at [offset], e.g. a RIFF chunk id. */
    public fun fourCc(bytes: ByteArray, offset: Int): String =
        String(CharArray(4) { (bytes[offset + it].toInt() and 0xFF).toChar() })
}
