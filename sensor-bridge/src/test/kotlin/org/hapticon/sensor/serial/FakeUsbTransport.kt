package org.hapticon.sensor.serial

/** A clock the test moves by hand. */
class FakeClock(var now: Long = 1_000) : MonotonicClock {
    override fun nowMillis(): Long = now

    fun advance(millis: Int) {
        now += millis
    }
}

/** One control transfer as the device saw it; [data] is the OUT payload, [length] the bytes asked for. */
data class ControlCall(
    val requestType: Int,
    val request: Int,
    val value: Int,
    val index: Int,
    val data: List<Int> = emptyList(),
    val length: Int = data.size,
) {
    override fun toString(): String =
        "Control(type=0x%02x, request=0x%02x, value=0x%04x, index=0x%04x, data=%s, length=%d)"
            .format(requestType, request, value, index, data.joinToString(" ", "[", "]") { "%02x".format(it) }, length)
}

/** One bulk transfer call: which endpoint, how many bytes were asked for, with what timeout. */
data class BulkCall(val endpoint: Int, val length: Int, val timeoutMillis: Int)

/** What the next bulk IN transfer does. */
sealed interface Incoming {
    /** Returns these bytes. */
    class Data(val bytes: ByteArray) : Incoming

    /** Waits out the timeout and returns -1, the device still attached. */
    data object Timeout : Incoming

    /** The device goes away; the transfer returns -1 at once. */
    data object Unplug : Incoming

    /** A zero-length packet. */
    data object ZeroLength : Incoming
}

/** A [UsbTransport] that records every request and plays back queued bulk IN results. */
class FakeUsbTransport(val clock: FakeClock = FakeClock()) : UsbTransport {
    val controlCalls = mutableListOf<ControlCall>()
    val claimed = mutableListOf<Int>()
    val released = mutableListOf<Int>()
    val bulkInCalls = mutableListOf<BulkCall>()
    val bulkOutCalls = mutableListOf<BulkCall>()
    val written = mutableListOf<Byte>()
    val incoming = ArrayDeque<Incoming>()

    var attached = true
    var statusChecks = 0
    var descriptors: ByteArray? = null
    var refuseClaimOf: Int? = null

    /** Replies to IN control requests, by request code. */
    val controlInReplies = mutableMapOf<Int, ByteArray>()

    /** Forced results of control requests, by request code: -1 is a STALL. */
    val controlResults = mutableMapOf<Int, Int>()

    /** What a bulk OUT transfer of `length` bytes with `timeout` does: bytes accepted or -1. */
    var onWrite: (length: Int, timeoutMillis: Int) -> Int = { length, _ -> length }

    override fun claimInterface(usbInterface: UsbInterfaceDescription): Boolean {
        if (usbInterface.id == refuseClaimOf) return false
        claimed += usbInterface.id
        return true
    }

    override fun releaseInterface(usbInterface: UsbInterfaceDescription): Boolean {
        released += usbInterface.id
        return true
    }

    override fun controlTransfer(requestType: Int, request: Int, value: Int, index: Int, data: ByteArray?, length: Int, timeoutMillis: Int): Int {
        val isIn = requestType and 0x80 != 0
        val sent = if (isIn || data == null) emptyList() else data.take(length).map { it.toInt() and 0xFF }
        controlCalls += ControlCall(requestType, request, value, index, sent, length)
        if (!attached) return -1
        controlResults[request]?.let { return it }
        if (isIn) {
            val reply = controlInReplies[request] ?: return -1
            reply.copyInto(data!!, 0, 0, minOf(length, reply.size))
            return minOf(length, reply.size)
        }
        return length
    }

    override fun bulkTransfer(endpoint: UsbEndpointDescription, buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        if (endpoint.direction == UsbDirection.OUT) {
            bulkOutCalls += BulkCall(endpoint.address, length, timeoutMillis)
            if (!attached) return -1
            val accepted = onWrite(length, timeoutMillis)
            if (accepted > 0) written += buffer.copyOfRange(offset, offset + accepted).toList()
            return accepted
        }
        bulkInCalls += BulkCall(endpoint.address, length, timeoutMillis)
        if (!attached) return -1
        val next = incoming.removeFirstOrNull() ?: Incoming.Timeout
        return when (next) {
            is Incoming.Data -> {
                check(next.bytes.size <= length) { "device sent ${next.bytes.size} bytes into a $length-byte transfer (overflow)" }
                next.bytes.copyInto(buffer, offset)
                next.bytes.size
            }
            Incoming.Timeout -> {
                check(timeoutMillis > 0) { "a read without timeout would block for ever" }
                clock.advance(timeoutMillis)
                -1
            }
            Incoming.Unplug -> {
                attached = false
                -1
            }
            Incoming.ZeroLength -> 0
        }
    }

    override fun isDeviceAttached(): Boolean {
        statusChecks++
        return attached
    }

    override fun rawDescriptors(): ByteArray? = descriptors

    fun writtenBytes(): ByteArray = written.toByteArray()
}

fun bytes(vararg values: Int): ByteArray = ByteArray(values.size) { values[it].toByte() }

fun ints(vararg values: Int): List<Int> = values.toList()

/** [count] bytes counting up from [start], wrapping at 256. */
fun ramp(count: Int, start: Int = 0): ByteArray = ByteArray(count) { (start + it).toByte() }
