package org.hapticon.companion.chat

import kotlinx.coroutines.runBlocking
import org.hapticon.companion.cli
import org.hapticon.companion.cli.Console
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.broker.CertificateAuthority
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.ClientCertificate
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.net.InetAddress
import java.net.ServerSocket
import java.nio.file.Files
import java.nio.file.attribute.PosixFilePermissions
import java.time.Duration
import java.time.Instant
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/** `hapticon broker ca init`, `broker cert issue`, `broker --tls-port` and `chat --client-cert`, end to end. */
class ClientCertificateCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun freePort() = ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { it.localPort }

    private fun mode(file: File) = PosixFilePermissions.toString(Files.getPosixFilePermissions(file.toPath()))

    @Test
    fun caInit_certIssue_tlsBroker_chatWithClientCertificates() {
        val data = temp.newFolder("broker")
        val ca = File(data, "ca")
        val init = cli("broker", "ca", "init", "--data", data.path, "--host", "127.0.0.1,chat.example.org")
        assertEquals(init.toString(), 0, init.exitCode)
        assertEquals(
            listOf(
                "broker: certificate authority in $ca: ca.crt (give it to clients), ca.key (mode 600, keep it secret)",
                "broker: broker certificate server.crt for localhost, 127.0.0.1, 127.0.0.1, chat.example.org (key server.key, mode 600)",
                "broker: next: hapticon broker cert issue USER --data $data, then hapticon broker --tls-port 8883 --data $data",
            ),
            init.stdout.lines().dropLast(1),
        )
        assertEquals(listOf("rw-------", "rw-------", "rw-r--r--"), listOf("ca.key", "server.key", "ca.crt").map { mode(File(ca, it)) })
        assertEquals(
            listOf("hapticon: broker ca init: $ca already holds a certificate authority; delete it first to start over (every certificate it issued stops working)"),
            cli("broker", "ca", "init", "--data", data.path).stderrLines,
        )

        val pw = File(temp.root, "p12.pw").apply { writeText("p12-secret\n") }
        for (user in listOf("alice", "bob")) {
            val out = File(temp.root, "$user.p12")
            val issued = cli("broker", "cert", "issue", user, "--data", data.path, "--password-file", pw.path, "--out", out.path, "--days", "30")
            assertEquals(
                listOf("broker: $out (mode 600): client certificate of $user, valid 30 days; with ${File(ca, "ca.crt")} it connects to a --tls-port listener"),
                issued.stdout.lines().dropLast(1),
            )
            assertEquals("rw-------", mode(out))
        }
        val alice = File(temp.root, "alice.p12")
        assertEquals(
            listOf("hapticon: --out $alice exists already; move it away or choose another file"),
            cli("broker", "cert", "issue", "alice", "--data", data.path, "--password-file", pw.path, "--out", alice.path).stderrLines,
        )

        val port = freePort()
        val tlsPort = freePort()
        val url = "ssl://127.0.0.1:$tlsPort"
        val out = Captured()
        val received = LinkedBlockingQueue<InboxEvent>()
        var refusedLine: String? = null
        var chatExit: Int? = null
        runBroker(listOf("--port", "$port", "--tls-port", "$tlsPort", "--data", data.path), Console(out.stream, Captured().stream)) {
            val bobCertificate = ClientCertificate.fromPkcs12(File(temp.root, "bob.p12").readBytes(), "p12-secret".toCharArray())
            val bob = MqttMessenger(
                MqttSettings(BrokerAddress.parse(url), "bob", null, DeviceId.generate(), clientCertificate = bobCertificate, trustedCertificates = CertificateAuthority.readCertificates(File(ca, "ca.crt"))),
            )
            runBlocking { bob.connect { received.put(it) } }
            val chat = ChatRun(listOf("--broker", url, "--user", "alice", "--to", "bob", "--client-cert", alice.path, "--client-cert-password-file", pw.path, "--ca", File(ca, "ca.crt").path, "--plaintext"))
            chat.err.awaitLine("chat: connected as alice, talking to bob; /help lists commands")
            chat.input.type("hello over mutual TLS")
            chatExit = chat.quit()

            // A certificate of another CA: the broker ends the handshake, and the chat says why.
            val other = CertificateAuthority.init(File(temp.root, "other-ca"), "Another CA", emptyList())
            val foreign = File(temp.root, "foreign.p12").apply { writeBytes(other.issueClient("alice", "p12-secret".toCharArray())) }
            val refused = ChatRun(listOf("--broker", url, "--user", "alice", "--client-cert", foreign.path, "--client-cert-password-file", pw.path, "--ca", File(ca, "ca.crt").path))
            refusedLine = refused.err.awaitLine { "refused this client's certificate" in it }
            refused.quit(command = null)
            runBlocking { bob.disconnect() }
        }
        assertEquals(0, chatExit)
        assertEquals(
            listOf(
                "broker: listening on tcp://127.0.0.1:$port (users ${File(data, "passwd")}, ACL ${File(data, "aclfile")}), store in ${File(data, "store")}; Ctrl-C stops it",
                "broker: TLS on $url (client certificate of ${File(ca, "ca.crt")} required; passwords not accepted there); clients trust ${File(ca, "ca.crt")}",
            ),
            out.lines.filter { it.startsWith("broker: listening") || it.startsWith("broker: TLS") },
        )
        val message = generateSequence { received.poll(WAIT_SECONDS, TimeUnit.SECONDS) }.filterIsInstance<InboxEvent.MessageReceived>().first().message
        assertEquals("alice" to "hello over mutual TLS", message.sender to message.text)
        assertEquals(
            "chat: cannot connect: TLS: the broker refused this client's certificate (missing, expired, or not signed by the broker's CA)",
            refusedLine!!.substringBefore(" ["),
        )
    }

    @Test
    fun chatClientCert_wrongPasswordExpiredOtherUserOrNoPasswordFile_oneLineEach() {
        val caDir = File(temp.root, "ca")
        val ca = CertificateAuthority.init(caDir, "Test CA", emptyList())
        val pw = File(temp.root, "p12.pw").apply { writeText("p12-secret\n") }
        val wrong = File(temp.root, "wrong.pw").apply { writeText("guess\n") }
        val alice = File(temp.root, "alice.p12").apply { writeBytes(ca.issueClient("alice", "p12-secret".toCharArray())) }
        val expired = File(temp.root, "expired.p12").apply {
            writeBytes(ca.issueClient("alice", "p12-secret".toCharArray(), Duration.ofDays(30), Instant.parse("2025-01-01T00:00:00Z")))
        }
        val base = arrayOf("chat", "--broker", "ssl://127.0.0.1:8883", "--user", "alice")
        val cases = listOf(
            listOf("--client-cert", alice.path, "--client-cert-password-file", wrong.path) to
                "hapticon: --client-cert $alice: the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file",
            listOf("--client-cert", expired.path, "--client-cert-password-file", pw.path) to
                "hapticon: --client-cert $expired: the client certificate of alice expired on 2025-01-31T00:00:00Z; ask for a new one (hapticon broker cert issue alice)",
            listOf("--client-cert", alice.path) to "hapticon: --client-cert needs --client-cert-password-file FILE (the PKCS#12 password's file)",
            listOf("--client-cert", alice.path, "--client-cert-password-file", File(temp.root, "none.pw").path) to
                "hapticon: --client-cert-password-file ${File(temp.root, "none.pw")}: no such file",
            listOf("--client-cert", pw.path, "--client-cert-password-file", pw.path) to
                "hapticon: --client-cert $pw: the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file",
            listOf("--client-cert", File(temp.root, "none.p12").path, "--client-cert-password-file", pw.path) to
                "hapticon: --client-cert ${File(temp.root, "none.p12")}: no such file",
        )
        for ((extra, line) in cases) {
            val result = cli(*base, *extra.toTypedArray())
            assertEquals(result.toString(), 2, result.exitCode)
            assertEquals(listOf(line), result.stderrLines)
        }
        val asBob = cli("chat", "--broker", "ssl://127.0.0.1:8883", "--user", "bob", "--client-cert", alice.path, "--client-cert-password-file", pw.path)
        assertEquals(
            listOf("hapticon: --client-cert: the client certificate is for alice, not bob: the broker takes the user name from the certificate"),
            asBob.stderrLines,
        )
        val plain = cli("chat", "--broker", "tcp://127.0.0.1:1883", "--user", "alice", "--client-cert", alice.path, "--client-cert-password-file", pw.path)
        assertEquals(listOf("hapticon: --broker: a client certificate needs a TLS broker address (ssl://…), not tcp://127.0.0.1:1883"), plain.stderrLines)
        assertEquals(
            listOf("hapticon: --tls-port: no certificate authority in ${File(temp.root, "nothing/ca")}; make one first: hapticon broker ca init --host ADDRESS --data ${File(temp.root, "nothing")}"),
            cli("broker", "--tls-port", "8883", "--data", File(temp.root, "nothing").path).stderrLines,
        )
        assertEquals(
            listOf("hapticon: --client-certs must be required or optional or none, got 'maybe'"),
            cli("broker", "--tls-port", "8883", "--ca-dir", caDir.path, "--client-certs", "maybe").stderrLines,
        )
    }
}
