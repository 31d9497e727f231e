package org.hapticon.messaging.broker

import org.junit.After
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assume.assumeTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.IOException
import java.net.ConnectException
import java.net.Inet4Address
import java.net.InetAddress
import java.net.InetSocketAddress
import java.net.NetworkInterface
import java.net.ServerSocket
import java.net.Socket

class EmbeddedBrokerTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val brokers = mutableListOf<EmbeddedBroker>()

    // A stop takes 2 s (Netty's graceful quiet period); every test has its own port, so they wind down meanwhile.
    @After
    fun stopBrokers() = brokers.forEach { Thread(it::stop).start() }

    private fun broker(port: Int = 0, host: String = EmbeddedBroker.HOST): EmbeddedBroker {
        val dir = temp.newFolder()
        val passwords = PasswordFile(java.io.File(dir, "passwd")).apply { add("alice", "alice-secret".toCharArray(), iterations = 1_000) }
        val acl = java.io.File(dir, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
        return EmbeddedBroker(java.io.File(dir, "store"), port, BrokerSecurity.Authenticated(passwords.file, acl), host).also { brokers += it }
    }

    @Test
    fun start_portZero_answersAnMqttConnectOnLoopbackOnly() {
        val broker = broker()
        broker.start()
        assertArrayEquals(CONNACK_ACCEPTED, connect(InetAddress.getByName(EmbeddedBroker.HOST), broker.port))
        assertArrayEquals(CONNACK_NOT_AUTHORIZED, connect(InetAddress.getByName(EmbeddedBroker.HOST), broker.port, user = null))
        assertArrayEquals(CONNACK_BAD_PASSWORD, connect(InetAddress.getByName(EmbeddedBroker.HOST), broker.port, password = "guess"))
        // Only USER:DEVICE of the user itself: not its bare name, not another user's device, not a short device id.
        for (foreign in listOf("alice", "bob", "bob:$DEVICE", "alice:${DEVICE.drop(1)}", "alice:${DEVICE.uppercase()}")) {
            assertArrayEquals(foreign, CONNACK_IDENTIFIER_REJECTED, connect(InetAddress.getByName(EmbeddedBroker.HOST), broker.port, clientId = foreign))
        }
        val other = NetworkInterface.networkInterfaces().toList()
            .flatMap { it.inetAddresses.toList() }
            .firstOrNull { it is Inet4Address && !it.isLoopbackAddress }
        assumeTrue("no non-loopback IPv4 address to try", other != null)
        assertThrows(ConnectException::class.java) { Socket().use { it.connect(InetSocketAddress(other, broker.port), 2_000) } }
    }

    @Test
    fun start_lanHost_answersThereWithTheSameLoginRules() {
        val lan = NetworkInterface.networkInterfaces().toList()
            .flatMap { it.inetAddresses.toList() }
            .firstOrNull { it is Inet4Address && !it.isLoopbackAddress }
        assumeTrue("no non-loopback IPv4 address to bind", lan != null)
        val broker = broker(host = lan!!.hostAddress)
        broker.start()
        assertArrayEquals(CONNACK_ACCEPTED, connect(lan, broker.port))
        assertArrayEquals(CONNACK_NOT_AUTHORIZED, connect(lan, broker.port, user = null))
    }

    // One test for the lifecycle: every stop takes 4.5 s.
    @Test
    fun restartThenStop_keepsThePortThenFreesIt() {
        val broker = broker()
        broker.start()
        val port = broker.port
        broker.start() // already running: nothing happens
        broker.restart()
        assertEquals(port, broker.port)
        assertEquals(true, broker.isRunning)
        assertArrayEquals(CONNACK_ACCEPTED, connect(InetAddress.getByName(EmbeddedBroker.HOST), port))
        broker.stop()
        broker.stop()
        assertEquals(false, broker.isRunning)
        assertThrows(ConnectException::class.java) { Socket(EmbeddedBroker.HOST, port).close() }
    }

    @Test
    fun start_portTaken_throwsIOException() {
        ServerSocket(0, 1, InetAddress.getByName(EmbeddedBroker.HOST)).use { taken ->
            val broker = broker(taken.localPort)
            val e = assertThrows(IOException::class.java) { broker.start() }
            assertEquals("cannot listen on 127.0.0.1:${taken.localPort}: Address already in use", e.message!!.substringBefore(" (Bind failed)"))
            assertEquals(false, broker.isRunning)
        }
    }

    @Test
    fun sessions_cleanOnesEndWithTheConnectionPersistentOnesStay() {
        val broker = broker()
        broker.start()
        val loopback = InetAddress.getByName(EmbeddedBroker.HOST)
        assertEquals(emptyMap<String, Boolean>(), broker.sessions())

        assertArrayEquals(CONNACK_ACCEPTED, connect(loopback, broker.port, clean = true))
        assertEquals(emptyMap<String, Boolean>(), awaitSessions(broker) { it.isEmpty() })
        assertArrayEquals(CONNACK_BAD_PASSWORD, connect(loopback, broker.port, password = "guess", clean = false))
        assertEquals(emptyMap<String, Boolean>(), broker.sessions())

        assertArrayEquals(CONNACK_ACCEPTED, connect(loopback, broker.port, clean = false))
        assertEquals(mapOf("alice:$DEVICE" to false), awaitSessions(broker) { it == mapOf("alice:$DEVICE" to false) })
    }

    /** The broker's sessions once [done] holds (a closed socket takes the broker a moment to notice), or the last seen. */
    private fun awaitSessions(broker: EmbeddedBroker, done: (Map<String, Boolean>) -> Boolean): Map<String, Boolean> {
        val until = System.nanoTime() + 5_000_000_000L
        var seen = broker.sessions()
        while (!done(seen) && System.nanoTime() < until) {
            Thread.sleep(20)
            seen = broker.sessions()
        }
        return seen
    }

    @Test
    fun port_beforeTheFirstStartWithPortZero_throws() {
        assertThrows(IllegalStateException::class.java) { broker().port }
        assertEquals(1883, EmbeddedBroker(temp.root, 1883, BrokerSecurity.AllowAnonymous).port)
    }

    /** Sends an MQTT 3.1.1 CONNECT ([clean] session or not) as [user] (none when null) and returns the 4-byte reply. */
    private fun connect(
        host: InetAddress, port: Int, user: String? = "alice", password: String = "alice-secret", clientId: String = user?.let { "$it:$DEVICE" } ?: "t",
        clean: Boolean = true,
    ): ByteArray =
        Socket(host, port).use { socket ->
            socket.soTimeout = 10_000
            fun field(text: String) = byteArrayOf(0, text.length.toByte()) + text.toByteArray()
            // clean session (+ user name and password)
            val flags = (if (user == null) 0x00 else 0xC0) or (if (clean) 0x02 else 0x00)
            val variable = field("MQTT") + byteArrayOf(4, flags.toByte(), 0, 30) // level 4 = 3.1.1, keep-alive 30 s
            val payload = field(clientId) + (if (user == null) ByteArray(0) else field(user) + field(password))
            val body = variable + payload
            socket.getOutputStream().write(byteArrayOf(0x10, body.size.toByte()) + body)
            socket.getInputStream().readNBytes(4)
        }

    private companion object {
        const val DEVICE = "0123456789abcdef0123456789abcdef"
        val CONNACK_ACCEPTED = byteArrayOf(0x20, 0x02, 0x00, 0x00)
        val CONNACK_IDENTIFIER_REJECTED = byteArrayOf(0x20, 0x02, 0x00, 0x02)
        val CONNACK_BAD_PASSWORD = byteArrayOf(0x20, 0x02, 0x00, 0x04)
        val CONNACK_NOT_AUTHORIZED = byteArrayOf(0x20, 0x02, 0x00, 0x05)
    }
}
