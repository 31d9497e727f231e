package org.hapticon.companion.chat.load

import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import java.io.File
import java.io.IOException
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.TimeUnit

/**
 * A broker's memory as the kernel and, for a JVM, the garbage collector see it.
 *
 * @property rssKib resident set size now (`VmRSS` of /proc/PID/status).
 * @property peakRssKib the most it was resident (`VmHWM`).
 * @property heapUsedKib Java heap in use right after a full collection (`jcmd PID GC.run`, then `GC.heap_info`): what
 *   the broker's live objects take. Null for Mosquitto, or when jcmd is missing.
 */
data class BrokerMemory(val rssKib: Long, val peakRssKib: Long, val heapUsedKib: Long?)

/**
 * A broker a load run talks to, with authentication and the shipped ACL on, running in a process of its own so
 * that its memory and CPU time are its own. [pid] is that process.
 */
interface LoadBroker : AutoCloseable {
    /** "embedded" or "mosquitto". */
    val name: String

    /** Where it listens (loopback). */
    val address: BrokerAddress

    /** Its process. */
    val pid: Long

    /** Its memory now. */
    fun memory(): BrokerMemory = ProcessStats.memory(pid, heapUsedKib = null)
}

/** Reads what Linux says about a process: memory from /proc/PID/status, CPU time from /proc/PID/stat. */
object ProcessStats {
    /** Clock ticks per second of /proc/PID/stat's times (`getconf CLK_TCK`; 100 on every Linux we run on). */
    private const val TICKS_PER_SECOND = 100.0

    /** [pid]'s memory, with [heapUsedKib] as given. Zeros off Linux. */
    fun memory(pid: Long, heapUsedKib: Long?): BrokerMemory {
        val status = runCatching { File("/proc/$pid/status").readLines() }.getOrDefault(emptyList())
        fun field(name: String) = status.firstOrNull { it.startsWith("$name:") }?.let { Regex("(\\d+)").find(it)?.value?.toLong() } ?: 0L
        return BrokerMemory(field("VmRSS"), field("VmHWM"), heapUsedKib)
    }

    /** User plus system CPU seconds [pid] has used (all its threads), or NaN off Linux. */
    fun cpuSeconds(pid: Long): Double {
        val stat = runCatching { File("/proc/$pid/stat").readText() }.getOrNull() ?: return Double.NaN
        // The command name (field 2) is in parentheses and may hold spaces: count from the last ')'.
        val fields = stat.substringAfterLast(')').trim().split(' ')
        return (fields[11].toLong() + fields[12].toLong()) / TICKS_PER_SECOND // utime, stime: fields 14 and 15
    }

    /**
     * The whole machine's CPU ticks so far, busy and in all (the first line of /proc/stat: busy = user, nice, system,
     * irq, softirq and steal; all adds idle and iowait), summed over every core; zeros off Linux.
     */
    fun machineTicks(): Pair<Long, Long> {
        val line = runCatching { File("/proc/stat").useLines { it.first() } }.getOrNull() ?: return 0L to 0L
        val t = line.trim().split(Regex("\\s+")).drop(1).take(8).map { it.toLong() }
        val busy = t[0] + t[1] + t[2] + t[5] + t[6] + t[7]
        return busy to busy + t[3] + t[4]
    }

    /** The 1, 5 and 15 minute load averages as `uptime` prints them, or "unknown" off Linux. */
    fun loadAverage(): String =
        runCatching { File("/proc/loadavg").readText().split(' ').take(3).joinToString(" / ") }.getOrDefault("unknown")
}

/** A free TCP port on loopback (free when asked; the broker binds it moments later). */
internal fun freeLoopbackPort(): Int = ServerSocket(0, 1, InetAddress.getByName(EmbeddedBroker.HOST)).use { it.localPort }

/** Waits until something accepts connections on [port], or fails with [describe]'s text when [process] died or 60 s passed. */
internal fun awaitListening(port: Int, process: Process, describe: () -> String) {
    val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60)
    while (true) {
        try {
            Socket(EmbeddedBroker.HOST, port).close()
            return
        } catch (e: IOException) {
            if (!process.isAlive) throw IOException("the broker exited with ${process.exitValue()}: ${describe()}")
            if (System.nanoTime() > deadline) throw IOException("the broker did not listen on $port within 60 s: ${describe()}")
            Thread.sleep(50)
        }
    }
}

/** Stops [process] with SIGTERM (both brokers save their store on the way out), then SIGKILL after 20 s. */
internal fun stopProcess(process: Process) {
    process.destroy()
    if (!process.waitFor(20, TimeUnit.SECONDS)) {
        process.destroyForcibly()
        process.waitFor(10, TimeUnit.SECONDS)
    }
}

/**
 * The embedded broker (HiveMQ CE) as `hapticon broker` runs it, in a child JVM started from this JVM's own class
 * path, with [passwords] and the shipped ACL ([AclFile.DEFAULT_TEXT]) in [directory]. Its heap is measured with jcmd.
 */
class ChildEmbeddedBroker private constructor(private val process: Process, override val address: BrokerAddress, private val log: File) : LoadBroker {
    override val name: String = "embedded"
    override val pid: Long = process.pid()

    override fun memory(): BrokerMemory = ProcessStats.memory(pid, heapUsedAfterGc())

    private fun heapUsedAfterGc(): Long? {
        val jcmd = File(File(javaBinary()).parentFile, "jcmd").takeIf { it.canExecute() }?.path ?: findTool("jcmd") ?: return null
        if (run(listOf(jcmd, pid.toString(), "GC.run")) == null) return null
        val info = run(listOf(jcmd, pid.toString(), "GC.heap_info")) ?: return null
        // One "total NK, used NK" per generation (PSYoungGen, ParOldGen with the parallel collector).
        val used = Regex("total \\d+K, used (\\d+)K").findAll(info).map { it.groupValues[1].toLong() }.toList()
        return if (used.isEmpty()) null else used.sum()
    }

    override fun close() {
        stopProcess(process)
    }

    companion object {
        /** The class whose `main` is the `hapticon` command. */
        private const val MAIN_CLASS = "org.hapticon.companion.MainKt"

        /**
         * Starts it on a free port, [passwordFile] holding its users; blocks until it accepts connections. [heapMib]
         * caps its heap (null: the JVM's default, a quarter of the machine's memory).
         */
        fun start(directory: File, passwordFile: File, heapMib: Int?): ChildEmbeddedBroker {
            val acl = File(directory, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
            val port = freeLoopbackPort()
            val log = File(directory, "broker.log")
            val command = listOf(javaBinary(), "-Djava.awt.headless=true", "-XX:+UseParallelGC") +
                listOfNotNull(heapMib?.let { "-Xmx${it}m" }) +
                listOf("-cp", System.getProperty("java.class.path"), MAIN_CLASS, "broker", "--port", port.toString(), "--data", File(directory, "data").path, "--users", passwordFile.path, "--acl", acl.path)
            val process = ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.appendTo(log)).start()
            try {
                awaitListening(port, process) { log.readText().takeLast(2_000) }
            } catch (e: IOException) {
                process.destroyForcibly()
                throw e
            }
            return ChildEmbeddedBroker(process, BrokerAddress(EmbeddedBroker.HOST, port), log)
        }

        private fun javaBinary(): String = ProcessHandle.current().info().command().orElse("java")
    }
}

/**
 * The embedded broker in this JVM (no child process): for tests, where this JVM's class path need not start the
 * `hapticon` command. Its memory is this JVM's, so none is reported.
 */
class InProcessEmbeddedBroker(directory: File, passwordFile: File) : LoadBroker {
    private val broker = EmbeddedBroker(
        File(directory, "store"),
        security = BrokerSecurity.Authenticated(passwordFile, File(directory, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }),
    ).apply { start() }

    override val name: String = "embedded"
    override val address: BrokerAddress = BrokerAddress(EmbeddedBroker.HOST, broker.port)
    override val pid: Long = ProcessHandle.current().pid()

    override fun memory(): BrokerMemory = BrokerMemory(0, 0, null)

    override fun close(): Unit = broker.stop()
}

/**
 * Mosquitto run from the shipped deployment file [conf] (companion/mosquitto/mosquitto.conf) with its listener on
 * a free loopback port, its store, password file and log in [directory] and the ACL file next to [conf]; every
 * other setting as shipped.
 */
class MosquittoBroker private constructor(private val process: Process, override val address: BrokerAddress) : LoadBroker {
    override val name: String = "mosquitto"
    override val pid: Long = process.pid()

    override fun close() {
        stopProcess(process)
    }

    companion object {
        /** Why Mosquitto cannot run here, or null when it can. */
        fun unavailable(): String? = if (findTool("mosquitto") == null) "mosquitto is not installed (apt-get install mosquitto)" else null

        /** Starts it; blocks until it accepts connections. */
        fun start(directory: File, conf: File, passwordFile: File): MosquittoBroker {
            val port = freeLoopbackPort()
            val data = File(directory, "mosquitto-data").apply { mkdirs() }
            val settings = mapOf(
                "listener " to "listener $port ${EmbeddedBroker.HOST}",
                "persistence_location " to "persistence_location ${data.absolutePath}/",
                "password_file " to "password_file ${passwordFile.absolutePath}",
                "acl_file " to "acl_file ${File(conf.absoluteFile.parentFile, "aclfile").absolutePath}",
            )
            val shipped = conf.readLines()
            val missing = settings.keys.filter { key -> shipped.none { it.startsWith(key) } }
            if (missing.isNotEmpty()) throw IOException("$conf has no line starting with ${missing.joinToString { "\"$it\"" }}")
            // Only the first (plain, loopback) listener is rewritten; the commented TLS ones stay commented.
            val rewritten = shipped.map { line -> settings.entries.firstOrNull { line.startsWith(it.key) }?.value ?: line }
            // As root Mosquitto would switch to the mosquitto user, who cannot read our temporary files.
            val config = File(directory, "mosquitto.conf").apply { writeText((rewritten + "user ${System.getProperty("user.name")}").joinToString("\n", postfix = "\n")) }
            val log = File(directory, "mosquitto.log")
            val process = ProcessBuilder(findTool("mosquitto") ?: throw IOException(unavailable()), "-c", config.path)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.appendTo(log)).start()
            try {
                awaitListening(port, process) { log.readText().takeLast(2_000) }
            } catch (e: IOException) {
                process.destroyForcibly()
                throw e
            }
            return MosquittoBroker(process, BrokerAddress(EmbeddedBroker.HOST, port))
        }

        /**
         * The shipped mosquitto.conf: companion/mosquitto/mosquitto.conf in the working directory or a directory above
         * it, or above this program's class files (`./hapticon` runs from out/ inside the repository). Null when not found.
         */
        fun shippedConf(): File? {
            val starts = listOfNotNull(
                File("").absoluteFile,
                runCatching { File(MosquittoBroker::class.java.protectionDomain.codeSource.location.toURI()) }.getOrNull(),
            )
            return starts.asSequence()
                .flatMap { generateSequence(it) { dir -> dir.parentFile } }
                .map { File(it, "companion/mosquitto/mosquitto.conf") }
                .firstOrNull { it.isFile }
        }
    }
}

// Debian installs the broker in /usr/sbin, which is not on every user's PATH.
private fun findTool(name: String): String? =
    (System.getenv("PATH").orEmpty().split(File.pathSeparator) + listOf("/usr/sbin", "/usr/bin", "/usr/local/sbin"))
        .map { File(it, name) }
        .firstOrNull { it.isFile && it.canExecute() }?.path

/** Runs [command], returning its output, or null when it failed. */
private fun run(command: List<String>): String? = runCatching {
    val p = ProcessBuilder(command).redirectErrorStream(true).start()
    val output = p.inputStream.readBytes().decodeToString()
    if (p.waitFor() == 0) output else null
}.getOrNull()
