package org.hapticon.app.sync

import java.io.File
import java.util.concurrent.TimeUnit
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile

/**
 * The embedded broker in a child JVM. HiveMQ cannot start inside Robolectric's sandbox class loader
 * (its classes have no code source there), so app tests that need a real broker run it next door:
 * same test classpath, plain class loader. [restart] stops the process and starts it again on the
 * same port and store, as a broker restart does. It authenticates like every Hapticon broker: the users
 * alice, bob and carol log in with the passwords `<user>-secret` ([USERS]), held to the default ACL.
 */
class BrokerProcess(private val data: File, val port: Int) : AutoCloseable {
    private var process: Process? = null

    fun start() {
        val javaBin = File(System.getProperty("java.home"), "bin/java").path
        val p = ProcessBuilder(javaBin, "-cp", System.getProperty("java.class.path"), BrokerProcess::class.java.name, data.path, port.toString())
            .redirectErrorStream(true)
            .start()
        process = p
        val lines = p.inputStream.bufferedReader()
        val ready = lines.lineSequence().firstOrNull { it.startsWith(READY) || it.startsWith(FAILED) }
        check(ready?.startsWith(READY) == true) { "broker process did not start: $ready" }
        // Keep draining its output so it never blocks on a full pipe; answers to [sessions] go to the queue.
        Thread { runCatching { lines.forEachLine { if (it.startsWith(SESSIONS)) answers.put(it) } } }.apply { isDaemon = true }.start()
    }

    private val answers = java.util.concurrent.LinkedBlockingQueue<String>()

    /** The sessions the broker holds, client id to connected ([EmbeddedBroker.sessions], asked over the child's stdin). */
    fun sessions(): Map<String, Boolean> {
        val p = checkNotNull(process) { "the broker process is not running" }
        answers.clear()
        p.outputStream.write("sessions\n".toByteArray())
        p.outputStream.flush()
        val answer = checkNotNull(answers.poll(15, TimeUnit.SECONDS)) { "the broker process did not answer" }
        return answer.removePrefix(SESSIONS).trim().split(',').filter { it.isNotEmpty() }
            .associate { entry -> entry.substringBefore('=') to entry.substringAfter('=').toBoolean() }
    }

    fun stop() {
        val p = process ?: return
        p.destroy()
        if (!p.waitFor(10, TimeUnit.SECONDS)) p.destroyForcibly().waitFor()
        process = null
    }

    /** Kills the broker with SIGKILL: its connections end at once, nothing in flight is acknowledged. */
    fun kill() {
        val p = process ?: return
        p.destroyForcibly().waitFor(10, TimeUnit.SECONDS)
        process = null
    }

    fun restart() {
        stop()
        start()
    }

    override fun close() = stop()

    companion object {
        private const val READY = "BROKER READY"
        private const val FAILED = "BROKER FAILED"
        private const val SESSIONS = "SESSIONS"

        /** The users the broker knows; each logs in with the password `<user>-secret`. */
        val USERS: List<String> = listOf("alice", "bob", "carol")

        /** Free port on the loopback interface. */
        fun freePort(): Int = java.net.ServerSocket(0, 1, java.net.InetAddress.getByName(EmbeddedBroker.HOST)).use { it.localPort }

        @JvmStatic
        fun main(args: Array<String>) {
            val data = File(args[0])
            val passwords = PasswordFile(File(data, "passwd"))
            // Few PBKDF2 rounds: the tests connect often; the format is the broker's own.
            if (!passwords.exists) USERS.forEach { passwords.add(it, "$it-secret".toCharArray(), iterations = 1_000) }
            val acl = File(data, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
            val broker = EmbeddedBroker(File(data, "store"), args[1].toInt(), BrokerSecurity.Authenticated(passwords.file, acl))
            try {
                broker.start()
            } catch (e: Exception) {
                println("$FAILED ${e.message}")
                return
            }
            Runtime.getRuntime().addShutdownHook(Thread { broker.stop() })
            println(READY)
            System.out.flush()
            // One command: "sessions", answered with "SESSIONS id=connected,...". End of input: run until killed.
            System.`in`.bufferedReader().forEachLine { command ->
                if (command == "sessions") {
                    println(SESSIONS + " " + broker.sessions().entries.joinToString(",") { "${it.key}=${it.value}" })
                    System.out.flush()
                }
            }
            Thread.currentThread().join()
        }
    }
}
