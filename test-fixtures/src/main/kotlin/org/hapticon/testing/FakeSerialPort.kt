package org.hapticon.testing

import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.port.PortTimeoutException
import org.hapticon.sensor.port.SerialPort
import java.io.ByteArrayOutputStream
import java.io.IOException
import java.util.ArrayDeque
import java.util.concurrent.TimeUnit
import java.util.concurrent.locks.ReentrantLock
import kotlin.concurrent.withLock

/**
 * A scripted [SerialPort] for tests. Reads return the scripted chunks in order, one chunk (or the
 * part that fits) per read, so a test chooses exactly how the stream is split; scripted events
 * make a read time out, end the stream, fail, or unplug the device. Writes are recorded.
 *
 * When the script is empty, a read waits for more to be [enqueue]d, for [close] or [unplug], or for
 * its timeout (returning 0). A test that scripts its stream to the end therefore never waits.
 *
 * Like a USB port: after [close], reads and writes throw [IOException]; after an unplug they throw
 * [PortDisconnectedException]. Thread-safe: a test thread may script while a reader thread reads.
 */
public class FakeSerialPort : SerialPort {
    private sealed class Step {
        class Data(val bytes: ByteArray, var position: Int = 0) : Step()
        object Timeout : Step()
        object End : Step()
        object Unplug : Step()
        class Failure(val error: IOException) : Step()
    }

    private val lock = ReentrantLock()
    private val changed = lock.newCondition()
    private val script = ArrayDeque<Step>()
    private val written = ByteArrayOutputStream()
    private val writeLog = ArrayList<ByteArray>()
    private var closed = false
    private var unplugged = false
    private var writeCapacityLeft = Long.MAX_VALUE

    /** The settings last passed to [configure], or null. */
    public var lineSettings: LineSettings? = null
        private set

    /** Number of [read] calls so far. */
    public val readCount: Int get() = lock.withLock { reads }
    private var reads = 0

    override val isOpen: Boolean get() = lock.withLock { !closed && !unplugged }

    /**
     * Scripts [bytes] as reads of at most [chunkSize] bytes each.
     * @throws IllegalArgumentException if [chunkSize] is not positive.
     */
    public fun enqueue(bytes: ByteArray, chunkSize: Int = bytes.size.coerceAtLeast(1)): FakeSerialPort {
        require(chunkSize > 0) { "chunkSize must be positive, was $chunkSize" }
        return enqueueChunks(bytes, intArrayOf(chunkSize))
    }

    /**
     * Scripts [bytes] as successive reads of the sizes in [chunkSizes], repeated from the start until
     * all bytes are scripted (the last read takes what is left).
     * @throws IllegalArgumentException if a size is not positive, or [chunkSizes] is empty while [bytes] is not.
     */
    public fun enqueueChunks(bytes: ByteArray, chunkSizes: IntArray): FakeSerialPort {
        require(chunkSizes.all { it > 0 }) { "chunk sizes must be positive" }
        require(chunkSizes.isNotEmpty() || bytes.isEmpty()) { "no chunk sizes for ${bytes.size} bytes" }
        lock.withLock {
            var start = 0
            var i = 0
            while (start < bytes.size) {
                val end = minOf(bytes.size, start + chunkSizes[i++ % chunkSizes.size])
                script.add(Step.Data(bytes.copyOfRange(start, end)))
                start = end
            }
            changed.signalAll()
        }
        return this
    }

    /** Scripts one read that times out (returns 0 at once, without waiting). */
    public fun enqueueTimeout(): FakeSerialPort = add(Step.Timeout)

    /** Scripts the end of a finite source: that read and all later ones return -1. */
    public fun enqueueEnd(): FakeSerialPort = add(Step.End)

    /** Scripts an unplug: that read throws [PortDisconnectedException], and the port is gone from then on. */
    public fun enqueueUnplug(): FakeSerialPort = add(Step.Unplug)

    /** Scripts one read that throws [error] (a transfer error with the device still attached). */
    public fun enqueueFailure(error: IOException): FakeSerialPort = add(Step.Failure(error))

    /** Unplugs the device now, waking a waiting read; unread script steps are discarded. */
    public fun unplug() {
        lock.withLock {
            unplugged = true
            script.clear()
            changed.signalAll()
        }
    }

    /**
     * Limits how many more bytes writes accept: a write beyond it records the bytes that fit and
     * throws [PortTimeoutException], as a stalled device would at the deadline (without waiting).
     * @throws IllegalArgumentException if [bytes] is negative.
     */
    public fun stallWritesAfter(bytes: Long) {
        require(bytes >= 0) { "bytes must not be negative, was $bytes" }
        lock.withLock { writeCapacityLeft = bytes }
    }

    /** Everything written so far, concatenated. */
    public fun writtenBytes(): ByteArray = lock.withLock { written.toByteArray() }

    /** Each [write] call's bytes (as accepted) in order. */
    public fun writes(): List<ByteArray> = lock.withLock { writeLog.map { it.copyOf() } }

    override fun configure(settings: LineSettings) {
        lock.withLock {
            checkUsable()
            lineSettings = settings
        }
    }

    /** Returns the next scripted step; see the class description. */
    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        lock.withLock {
            reads++
            var waitNanos = TimeUnit.MILLISECONDS.toNanos(timeoutMillis.toLong())
            while (true) {
                checkUsable()
                val step = script.peekFirst()
                if (step != null) return take(step, buffer, offset, length)
                if (timeoutMillis == 0) {
                    changed.await()
                } else {
                    if (waitNanos <= 0) return 0
                    waitNanos = changed.awaitNanos(waitNanos)
                }
            }
        }
    }

    private fun take(step: Step, buffer: ByteArray, offset: Int, length: Int): Int = when (step) {
        is Step.Data -> {
            val count = minOf(length, step.bytes.size - step.position)
            System.arraycopy(step.bytes, step.position, buffer, offset, count)
            step.position += count
            if (step.position == step.bytes.size) script.removeFirst()
            count
        }
        Step.Timeout -> {
            script.removeFirst()
            0
        }
        Step.End -> -1
        Step.Unplug -> {
            script.clear()
            unplugged = true
            throw PortDisconnectedException("fake device unplugged")
        }
        is Step.Failure -> {
            script.removeFirst()
            throw step.error
        }
    }

    /**
     * Records the bytes. Past the [stallWritesAfter] point, a write with a deadline throws
     * [PortTimeoutException] at once; one without (0) waits, as on a stalled device, until the port
     * is closed or unplugged.
     */
    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        lock.withLock {
            checkUsable()
            val accepted = minOf(length.toLong(), writeCapacityLeft).toInt()
            written.write(buffer, offset, accepted)
            writeLog.add(buffer.copyOfRange(offset, offset + accepted))
            writeCapacityLeft -= accepted
            if (accepted == length) return
            if (timeoutMillis > 0) throw PortTimeoutException("wrote $accepted of $length bytes before the $timeoutMillis ms deadline")
            writers++
            changed.signalAll()
            try {
                while (true) {
                    checkUsable()
                    changed.await()
                }
            } finally {
                writers--
            }
        }
    }

    /** Number of writes waiting on a stalled device (no deadline), for tests that unplug them. */
    public val stalledWrites: Int get() = lock.withLock { writers }
    private var writers = 0

    /** Closes the port, waking a waiting read (which then throws [IOException]). */
    override fun close() {
        lock.withLock {
            closed = true
            changed.signalAll()
        }
    }

    private fun add(step: Step): FakeSerialPort {
        lock.withLock {
            script.add(step)
            changed.signalAll()
        }
        return this
    }

    private fun checkUsable() {
        if (unplugged) throw PortDisconnectedException("fake device unplugged")
        if (closed) throw IOException("fake port closed")
    }
}
