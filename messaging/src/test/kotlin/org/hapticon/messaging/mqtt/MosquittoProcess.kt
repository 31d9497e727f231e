package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.broker.CertificateAuthority
import org.junit.Assert.fail
import org.junit.Assume.assumeTrue
import java.io.File
import java.io.IOException
import java.net.InetAddress
import java.net.ServerSocket
import java.net.Socket
import java.util.concurrent.TimeUnit

/**
 * A real Mosquitto broker, started from the deployment files in companion/mosquitto with their paths
 * rewritten into [dir] and its listener on a free loopback port. Missing Mosquitto skips the test, except
 * on CI (env CI=true), which installs it and must run these tests.
 */
class MosquittoProcess(
    private val dir: File,
    users: Map<String, String>,
    certificates: CertificateAuthority? = null,
    /** Options added to the plain listener, to show what the shipped file leaves out and why. */
    listenerOptions: List<String> = emptyList(),
) {
    val port: Int = ServerSocket(0, 1, InetAddress.getByName(HOST)).use { it.localPort }

    /** The client-certificate listener's port (the shipped file's commented `listener 8884` block, enabled when [certificates] are given). */
    val tlsPort: Int = ServerSocket(0, 1, InetAddress.getByName(HOST)).use { it.localPort }
    private val config = File(dir, "mosquitto.conf")
    private val log = File(dir, "mosquitto.log")
    private var process: Process? = null

    init {
        val passwd = File(dir, "passwd")
        for ((user, password) in users) {
            run(listOf(tool("mosquitto_passwd"), "-b") + (if (passwd.exists()) emptyList() else listOf("-c")) + listOf(passwd.path, user, password))
        }
        File(dir, "data").mkdirs()
        val plain = deploymentConfig(port, File(dir, "data"), passwd).replace("listener $port $HOST\n", (listOf("listener $port $HOST") + listenerOptions).joinToString("\n", postfix = "\n"))
        config.writeText(plain + (certificates?.let { certificateListener(tlsPort, it) } ?: ""))
    }

    val address: BrokerAddress get() = BrokerAddress(HOST, port)

    /** The client-certificate listener. */
    val tlsAddress: BrokerAddress get() = BrokerAddress(HOST, tlsPort, tls = true)

    /** Starts Mosquitto and waits until it accepts connections. */
    fun start() {
        process = ProcessBuilder(tool("mosquitto"), "-c", config.path)
            .redirectErrorStream(true)
            .redirectOutput(ProcessBuilder.Redirect.appendTo(log))
            .start()
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20)
        while (true) {
            try {
                Socket(HOST, port).close()
                return
            } catch (e: IOException) {
                if (!process!!.isAlive) fail("mosquitto exited ${process!!.exitValue()}:\n${log.readText()}")
                if (System.nanoTime() > deadline) fail("mosquitto did not listen on $port within 20 s:\n${log.readText()}")
                Thread.sleep(20)
            }
        }
    }

    /** Stops Mosquitto with SIGTERM (it saves its persistence file on the way out) and waits for it. */
    fun stop() {
        val running = process ?: return
        process = null
        running.destroy()
        if (!running.waitFor(20, TimeUnit.SECONDS)) {
            running.destroyForcibly()
            fail("mosquitto did not stop on SIGTERM:\n${log.readText()}")
        }
    }

    /** Kills Mosquitto with SIGKILL: no chance to save anything on the way out. */
    fun kill() {
        val running = process ?: return
        process = null
        running.destroyForcibly() // SIGKILL on Unix (java.lang.Process)
        running.waitFor(20, TimeUnit.SECONDS)
    }

    fun restart() {
        stop()
        start()
    }

    /** What Mosquitto logged, for failure messages. */
    fun log(): String = log.readText()

    /** The installed Mosquitto's version, e.g. `2.0.11` (from `mosquitto -h`). */
    val version: String by lazy { installedVersion() }

    private fun run(command: List<String>) {
        val p = ProcessBuilder(command).redirectErrorStream(true).start()
        val output = p.inputStream.readBytes().decodeToString()
        if (p.waitFor() != 0) fail("${command.joinToString(" ")} failed: $output")
    }

    companion object {
        const val HOST = "127.0.0.1"

        /**
         * The shipped file's commented client-certificate listener (from `#listener 8884` to the next blank line),
         * uncommented, on [port] with [ca]'s files. Fails when the block is no longer there or lost a line the
         * test relies on, so the test keeps exercising the shipped text.
         */
        fun certificateListener(port: Int, ca: CertificateAuthority): String {
            val lines = File(deploymentDir(), "mosquitto.conf").readLines()
            val start = lines.indexOf("#listener 8884")
            if (start < 0) fail("mosquitto.conf no longer has the commented line \"#listener 8884\"")
            val block = lines.drop(start).takeWhile { it.isNotBlank() }.map { it.removePrefix("#") }
            val replacements = mapOf(
                "listener 8884" to "listener $port $HOST",
                "cafile " to "cafile ${ca.certificateFile.absolutePath}",
                "certfile " to "certfile ${ca.serverCertificateFile.absolutePath}",
                "keyfile " to "keyfile ${ca.serverKeyFile.absolutePath}",
            )
            for (required in replacements.keys + listOf("require_certificate true", "use_identity_as_username true")) {
                if (block.none { it.startsWith(required) }) fail("mosquitto.conf's certificate listener no longer has a line starting with \"$required\"")
            }
            return block.joinToString("\n", prefix = "\n", postfix = "\n") { line -> replacements.entries.firstOrNull { line.startsWith(it.key) }?.value ?: line }
        }

        /** Skips the calling test unless the installed Mosquitto is 2.0.11 (Debian 12's, which CI installs). */
        fun assumeVersion2011() {
            assumeInstalled()
            assumeTrue("Mosquitto ${installedVersion()}, not 2.0.11", installedVersion() == "2.0.11")
        }

        private fun installedVersion(): String {
            val p = ProcessBuilder(tool("mosquitto"), "-h").redirectErrorStream(true).start()
            val output = p.inputStream.readBytes().decodeToString()
            p.waitFor()
            return Regex("mosquitto version (\\S+)").find(output)?.groupValues?.get(1) ?: "unknown"
        }

        /** Skips the calling test when Mosquitto is not installed, or fails it on CI. */
        fun assumeInstalled() {
            val missing = listOf("mosquitto", "mosquitto_passwd").filter { find(it) == null }
            if (missing.isEmpty()) return
            val message = "${missing.joinToString(" and ")} not installed (apt-get install mosquitto)"
            if (System.getenv("CI") == "true") fail("$message; CI must run the Mosquitto tests")
            assumeTrue(message, false)
        }

        private fun tool(name: String): String = find(name)?.path ?: throw AssertionError("$name not installed")

        // Debian installs the broker in /usr/sbin, which is not on every user's PATH.
        private fun find(name: String): File? =
            (System.getenv("PATH").orEmpty().split(File.pathSeparator) + listOf("/usr/sbin", "/usr/bin", "/usr/local/sbin"))
                .map { File(it, name) }
                .firstOrNull { it.isFile && it.canExecute() }

        /** The repository's companion/mosquitto directory, found from the test's working directory upwards. */
        fun deploymentDir(): File {
            var dir: File? = File("").absoluteFile
            while (dir != null && !File(dir, "settings.gradle.kts").isFile) dir = dir.parentFile
            return File(dir ?: throw AssertionError("project root not found"), "companion/mosquitto")
        }

        /**
         * companion/mosquitto/mosquitto.conf with the listener on [port] and its files in [data] and
         * [passwd]; the ACL file is used as it is. Fails when a setting it rewrites is no longer there, so the
         * test keeps exercising the shipped file.
         */
        fun deploymentConfig(port: Int, data: File, passwd: File): String {
            val replacements = mapOf(
                "listener 1883 127.0.0.1" to "listener $port $HOST",
                "persistence_location " to "persistence_location ${data.absolutePath}/",
                "password_file " to "password_file ${passwd.absolutePath}",
                "acl_file " to "acl_file ${File(deploymentDir(), "aclfile").absolutePath}",
            )
            val lines = File(deploymentDir(), "mosquitto.conf").readLines()
            for (key in replacements.keys) {
                if (lines.none { it.startsWith(key) }) fail("mosquitto.conf no longer has a line starting with \"$key\"")
            }
            val rewritten = lines.map { line -> replacements.entries.firstOrNull { line.startsWith(it.key) }?.value ?: line }
            // Run as ourselves: as root, Mosquitto would switch to the mosquitto user, who cannot read our temp files.
            return (rewritten + "user ${System.getProperty("user.name")}").joinToString("\n", postfix = "\n")
        }
    }
}
