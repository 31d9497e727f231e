package org.hapticon.companion.bench

import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort
import java.io.IOException
import java.util.ArrayDeque
import java.util.concurrent.TimeUnit
import java.util.concurrent.locks.ReentrantLock
import kotlin.concurrent.withLock

/**
 * The grain-latency bench's serial line: the bench thread [send]s each encoded frame, the reader thread
 * reads it, and what the reader writes back (the grain commands) is copied and kept, as a USB port's
 * transfer copies it. One lock and one condition, so a read that finds nothing parks until the next
 * frame, as a reader blocked in a USB bulk transfer does; a read waits at most its timeout (0: until a
 * frame or [close]) and throws [IOException] once the line is closed.
 */
internal class BenchSerialLine : SerialPort {
    private val lock = ReentrantLock()
    private val arrived = lock.newCondition()
    private val pending = ArrayDeque<ByteArray>()
    private var position = 0
    private var closed = false

    /** Everything the reader wrote, one copy per write. */
    val written: MutableList<ByteArray> = ArrayList()

    override val isOpen: Boolean get() = lock.withLock { !closed }

    /** Queues [frame] to be read (in one read if the reader's buffer holds it) and wakes the reader. */
    fun send(frame: ByteArray) {
        lock.withLock {
            pending.addLast(frame)
            arrived.signalAll()
        }
    }

    override fun configure(settings: LineSettings) {}

    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int = lock.withLock {
        var left = TimeUnit.MILLISECONDS.toNanos(timeoutMillis.toLong())
        while (!closed && pending.isEmpty()) {
            if (timeoutMillis == 0) arrived.await() else if (left <= 0) return 0 else left = arrived.awaitNanos(left)
        }
        if (closed) throw IOException("bench line closed")
        val head = pending.first
        val count = minOf(length, head.size - position)
        System.arraycopy(head, position, buffer, offset, count)
        position += count
        if (position == head.size) {
            pending.removeFirst()
            position = 0
        }
        count
    }

    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        lock.withLock {
            if (closed) throw IOException("bench line closed")
            written += buffer.copyOfRange(offset, offset + length)
        }
    }

    override fun close() {
        lock.withLock {
            closed = true
            arrived.signalAll()
        }
    }
}
