package org.hapticon.companion.bench

import java.io.Closeable
import java.io.IOException
import java.lang.management.ManagementFactory
import java.nio.ByteBuffer
import java.nio.ByteOrder
import java.nio.channels.FileChannel
import java.nio.file.Files
import java.nio.file.Path
import java.nio.file.StandardOpenOption
import java.util.concurrent.TimeUnit
import javax.management.ObjectName

/**
 * A Linux PM QoS CPU latency request held open: while it is, no idle CPU enters a state whose exit latency is
 * above [micros], so a thread woken on an idle CPU is not also waiting for that CPU to wake (with 0 the CPUs poll).
 * The kernel's Documentation/power/pm_qos_interface.rst: "To register the default PM QoS target for the CPU
 * latency QoS, the process must open /dev/cpu_dma_latency. As long as the device node is held open that process
 * has a registered request on the parameter. To change the requested target value, the process needs to write
 * an s32 value to the open device node … To remove the user mode request for a target value simply close the
 * device node." Only root may open it (mode 0600).
 */
class CpuLatencyRequest private constructor(val micros: Int, private val channel: FileChannel?, val outcome: String) : Closeable {
    /** Whether the request is in force. */
    val granted: Boolean get() = channel != null

    /** Drops the request (closing the node removes it). */
    override fun close() {
        channel?.close()
    }

    /** Opens requests. */
    companion object {
        /** The device node of the CPU latency QoS. */
        val DEVICE: Path = Path.of("/dev/cpu_dma_latency")

        /**
         * Asks for at most [micros] µs of CPU wake-up latency and holds the request until [close]. Refused (not
         * root, no such node) is not an error: [granted] is false and [outcome] says why in one line.
         */
        fun open(micros: Int, device: Path = DEVICE): CpuLatencyRequest {
            require(micros >= 0) { "micros must not be negative, was $micros" }
            val channel = try {
                FileChannel.open(device, StandardOpenOption.READ, StandardOpenOption.WRITE)
            } catch (e: IOException) {
                return CpuLatencyRequest(micros, null, "cpu latency $micros µs refused ($device: ${e.javaClass.simpleName} ${e.message}; root only); runs go on without it")
            } catch (e: SecurityException) {
                return CpuLatencyRequest(micros, null, "cpu latency $micros µs refused ($device: ${e.message}); runs go on without it")
            }
            return try {
                // The s32 in the CPU's byte order, as the kernel reads it from a 4-byte write.
                channel.write(ByteBuffer.allocate(4).order(ByteOrder.nativeOrder()).putInt(0, micros))
                // Reading the node gives the limit now in force, over every request: ours, or a stricter one
                // (a plain read: a device node need not support reads at an offset).
                val now = ByteBuffer.allocate(4).order(ByteOrder.nativeOrder())
                val read = channel.read(now)
                val effective = if (read == 4) "${now.getInt(0)} µs" else "unknown"
                CpuLatencyRequest(micros, channel, "cpu latency $micros µs granted (limit in force $effective)")
            } catch (e: IOException) {
                channel.close()
                CpuLatencyRequest(micros, null, "cpu latency $micros µs refused (${e.message}); runs go on without it")
            }
        }
    }
}

/**
 * Sets a thread's nice value with the `renice` command (util-linux; `renice -n N -p TID` acts on that one thread,
 * a Linux thread being a task with its own id). Java has no setpriority(2); running `renice` costs a fork and
 * an exec, so it is done once, before the measured samples, never on the path. Returns the outcome in one line.
 */
object Renice {
    /** Renices [tid] to [nice] (-20..19); a refusal (not root, no renice) is reported, not thrown. */
    fun apply(tid: Long, nice: Int): String {
        require(nice in -20..19) { "nice must be in -20..19, was $nice" }
        return try {
            val process = ProcessBuilder("renice", "-n", nice.toString(), "-p", tid.toString()).redirectErrorStream(true).start()
            val said = process.inputStream.bufferedReader().readText().trim()
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroy()
                "reader nice $nice refused (renice did not finish)"
            } else if (process.exitValue() == 0 && niceOf(tid) == nice) {
                "reader nice $nice granted"
            } else {
                "reader nice $nice refused (${said.lineSequence().firstOrNull().orEmpty().ifEmpty { "renice exit ${process.exitValue()}" }})"
            }
        } catch (e: IOException) {
            "reader nice $nice refused (${e.message})"
        }
    }

    /** The nice value of thread [tid] of this process (Linux: field 19 of its stat), or null if unreadable. */
    fun niceOf(tid: Long): Int? = runCatching {
        val text = Files.readString(Path.of("/proc/self/task/$tid/stat"))
        text.substring(text.lastIndexOf(')') + 2).split(' ')[NICE_FIELD - 3].toInt()
    }.getOrNull()

    private const val NICE_FIELD = 19
}

/**
 * HotSpot's safepoint log, switched on for this process while it runs and off again, through the
 * DiagnosticCommand MBean's `VM.log` (what `jcmd PID VM.log` does): `output=file=… what=safepoint=info
 * decorators=timenanos` adds one file output, `what=all=off` on the same output removes it. Null when this JVM
 * has no such command (not HotSpot).
 */
class SafepointLogging private constructor(private val file: Path) : Closeable {
    private var open = true

    /** Stops logging, reads the safepoints and deletes the file. */
    fun finish(): List<Safepoint> {
        close()
        return runCatching { SafepointLog.parse(Files.readString(file)) }.getOrDefault(emptyList()).also { cleanUp() }
    }

    override fun close() {
        if (!open) return
        open = false
        runCatching { vmLog("output=file=$file", "what=all=off") }
    }

    private fun cleanUp() {
        runCatching {
            Files.deleteIfExists(file)
            Files.deleteIfExists(file.parent)
        }
    }

    /** Starts the log. */
    companion object {
        /** Starts logging safepoints to a new file, or null if this JVM cannot. */
        fun start(): SafepointLogging? {
            val dir = runCatching { Files.createTempDirectory("hapticon-safepoints") }.getOrNull() ?: return null
            val file = dir.resolve("safepoint.log")
            return if (runCatching { vmLog("output=file=$file", "what=safepoint=info", "decorators=timenanos") }.isSuccess) {
                SafepointLogging(file)
            } else {
                runCatching { Files.deleteIfExists(dir) }
                null
            }
        }

        private fun vmLog(vararg arguments: String) {
            ManagementFactory.getPlatformMBeanServer().invoke(
                ObjectName("com.sun.management:type=DiagnosticCommand"), "vmLog", arrayOf<Any>(arrayOf(*arguments)), arrayOf(Array<String>::class.java.name),
            )
        }
    }
}
