package org.hapticon.sensor.protocol.stream

/** Throws [IndexOutOfBoundsException] unless [offset], [length] describe a range inside [size]. */
internal fun checkRange(size: Int, offset: Int, length: Int) {
    if (offset < 0 || length < 0 || offset > size - length) {
        throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..$size")
    }
}
