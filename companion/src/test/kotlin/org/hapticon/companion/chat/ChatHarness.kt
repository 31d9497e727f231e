package org.hapticon.companion.chat

import org.hapticon.companion.cli.Console
import kotlinx.coroutines.runBlocking
import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.reportFailure
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttSettings
import org.hapticon.messaging.e2e.EndToEnd
import org.junit.rules.ExternalResource
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream
import java.io.Reader
import java.nio.file.Files
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicInteger

/** How long a test waits for something that should happen at once: a hang detector, not a measurement. */
const val WAIT_SECONDS: Long = 20

/** Input typed by a test, line by line; [end] is the end of input. */
class TypedInput : Reader() {
    private val lines = LinkedBlockingQueue<String>()
    private var current = ""
    private var position = 0
    private var ended = false

    fun type(line: String) = lines.put(line + "\n")

    fun end() = lines.put(END)

    override fun read(buffer: CharArray, offset: Int, length: Int): Int {
        if (ended) return -1
        if (position == current.length) {
            val next = lines.take()
            if (next === END) {
                ended = true
                return -1
            }
            current = next
            position = 0
        }
        val n = minOf(length, current.length - position)
        current.toCharArray(buffer, offset, position, position + n)
        position += n
        return n
    }

    override fun close() = Unit

    private companion object {
        val END = String(charArrayOf('\u0004'))
    }
}

/** A PrintStream whose text can be read while another thread writes it. */
class Captured {
    private val bytes = ByteArrayOutputStream()
    val stream = PrintStream(object : java.io.OutputStream() {
        override fun write(b: Int) = synchronized(bytes) { bytes.write(b) }
        override fun write(b: ByteArray, off: Int, len: Int) = synchronized(bytes) { bytes.write(b, off, len) }
    }, true, "UTF-8")

    val text: String get() = synchronized(bytes) { bytes.toString("UTF-8") }
    val lines: List<String> get() = text.lines().dropLastWhile { it.isEmpty() }

    /** Waits until a line satisfies [predicate] and returns it; fails after [WAIT_SECONDS]. */
    fun awaitLine(predicate: (String) -> Boolean): String {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(WAIT_SECONDS)
        while (System.nanoTime() < deadline) {
            lines.firstOrNull(predicate)?.let { return it }
            Thread.sleep(5)
        }
        throw AssertionError("no matching line within $WAIT_SECONDS s in:\n$text")
    }

    /** Waits for a line equal to [line]. */
    fun awaitLine(line: String): String = awaitLine { it == line }
}

/**
 * `hapticon chat` running in-process on its own thread, with typed input and captured output. Without `--data-dir`
 * (and `--keys-dir`, unless `--plaintext`) it gets fresh temporary ones: no test writes into `~/.hapticon`.
 */
class ChatRun(givenArgs: List<String>) {
    private val args = givenArgs + scratchDirs(givenArgs)
    val input = TypedInput()
    val out = Captured()
    val err = Captured()
    @Volatile var exitCode: Int? = null
    private val thread = Thread {
        exitCode = try {
            runChat(args, Console(out.stream, err.stream), input, home = ChatFixture.home)
            EXIT_OK
        } catch (e: Throwable) {
            reportFailure(e, err.stream, debug = true)
        }
    }.apply { start() }

    /** Ends the input and waits for the chat to finish; returns its exit status. */
    fun quit(command: String? = "/quit"): Int {
        if (command != null) input.type(command) else input.end()
        thread.join(TimeUnit.SECONDS.toMillis(WAIT_SECONDS))
        return exitCode ?: throw AssertionError("chat did not end within $WAIT_SECONDS s\n--- out\n${out.text}--- err\n${err.text}")
    }
}

private val scratch: File by lazy {
    Files.createTempDirectory("hapticon-chat-test-dirs").toFile().also { dir -> Runtime.getRuntime().addShutdownHook(Thread { dir.deleteRecursively() }) }
}

private fun scratchDirs(args: List<String>): List<String> {
    val extra = mutableListOf<String>()
    if ("--data-dir" !in args) extra += listOf("--data-dir", Files.createTempDirectory(scratch.toPath(), "data").toString())
    if ("--keys-dir" !in args && "--plaintext" !in args) extra += listOf("--keys-dir", Files.createTempDirectory(scratch.toPath(), "keys").toString())
    return extra
}

/**
 * The embedded broker the chat tests share (a start costs seconds), a temporary folder per test, and the
 * messengers standing in for the phone at the other end. Tests keep apart by their own user names ([unique]).
 */
class ChatFixture : ExternalResource() {
    val temp = TemporaryFolder()
    val broker: EmbeddedBroker get() = shared
    private val messengers = mutableListOf<MqttMessenger>()

    val url: String get() = "tcp://${EmbeddedBroker.HOST}:${broker.port}"

    override fun before() {
        temp.create()
    }

    override fun after() {
        runBlocking { messengers.forEach { it.disconnect() } }
        temp.delete()
    }

    /** A connected messenger for [user] (sealing end to end with [e2e]) whose events land in the returned queue. */
    fun phone(user: String, e2e: EndToEnd? = null): Pair<MqttMessenger, LinkedBlockingQueue<InboxEvent>> {
        val events = LinkedBlockingQueue<InboxEvent>()
        val messenger = MqttMessenger(MqttSettings(BrokerAddress.parse(url), user, register(user), phoneDevice(user)), e2e)
        messengers += messenger
        runBlocking { messenger.connect(InboxListener { events.put(it) }) }
        return messenger to events
    }

    companion object {
        private val names = AtomicInteger()

        private val root: File by lazy {
            Files.createTempDirectory("hapticon-chat-test-broker").toFile().also { dir -> Runtime.getRuntime().addShutdownHook(Thread { dir.deleteRecursively() }) }
        }
        private val passwords: PasswordFile by lazy { PasswordFile(File(root, "passwd")) }
        private val registered = mutableSetOf<String>()

        private val shared: EmbeddedBroker by lazy {
            val acl = File(root, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
            EmbeddedBroker(File(root, "store"), security = BrokerSecurity.Authenticated(passwords.file, acl)).also { it.start() }
        }

        /** Adds [user] to the shared broker's password file (once) and returns its password, `<user>-secret`. */
        @Synchronized
        fun register(user: String): String {
            if (registered.add(user)) passwords.add(user, "$user-secret".toCharArray(), iterations = 1_000)
            return "$user-secret"
        }

        /** The home directory `hapticon chat` keeps its device ids in (`.hapticon/devices/USER`), not the tester's. */
        val home: File get() = File(root, "home")

        private val phoneDevices = java.util.concurrent.ConcurrentHashMap<String, DeviceId>()

        /** The device id of [user]'s phone: one per user, another device than the user's `hapticon chat`. */
        fun phoneDevice(user: String): DeviceId = phoneDevices.computeIfAbsent(user) { DeviceId.generate() }

        /** A file holding [user]'s password, for `--password-file`. */
        fun passwordFile(user: String): String = File(root, "$user.pw").apply { writeText(register(user) + "\n") }.path

        /** [base] with a suffix no other test of this JVM uses, e.g. `alice-3`. */
        fun unique(base: String): String = "$base-${names.incrementAndGet()}"
    }
}

/** The next event that is not a capabilities announcement; fails after [WAIT_SECONDS]. */
fun LinkedBlockingQueue<InboxEvent>.nextNonCapabilities(): InboxEvent {
    while (true) {
        val event = poll(WAIT_SECONDS, TimeUnit.SECONDS) ?: throw AssertionError("no event within $WAIT_SECONDS s")
        if (event !is InboxEvent.CapabilitiesReceived) return event
    }
}
