package org.hapticon.companion.chat

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.Clock
import org.hapticon.messaging.InboxGate
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Topics
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.ClientCertificate
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.FileKeyPins
import org.hapticon.messaging.e2e.Identity
import java.io.BufferedReader
import java.io.IOException
import java.security.GeneralSecurityException
import java.io.File
import java.io.InputStreamReader
import java.io.Reader

/**
 * `hapticon chat --broker URL --user NAME [--to PEER] [--password-file FILE | --client-cert FILE.p12
 * --client-cert-password-file FILE | --anonymous] [--ca FILE] [--wav-dir DIR] [--keys-dir DIR | --plaintext]
 * [--data-dir DIR]`: a terminal chat over MQTT with the phone app or another `hapticon chat`. Reads lines from
 * [input] (stdin by default) until `/quit` or its end; see [ChatSession]. Connection failures are printed as they
 * happen (refused, TLS trust, unknown host); a refusal by the broker (bad password) or lines that never
 * reached it end the command with one line and a non-zero exit. Every payload is sealed end to end
 * (org.hapticon.messaging.e2e.EndToEnd), so the broker's operator can neither read nor forge it, unless
 * `--plaintext` says otherwise (a study that needs the broker to see content; warned about on stderr at every
 * start). `--e2e` is accepted for scripts written when encryption was opt-in. Unconfirmed messages and the ids of
 * the messages shown are kept in `DIR/chat.db` ([ChatStore]; `--data-dir`, default `~/.hapticon/chat/USER`).
 * `--client-cert` logs in with a client certificate (mutual TLS, an `ssl://` broker) instead of a password;
 * `--ca` trusts the study's own CA (`ca.crt` of `hapticon broker ca init`) instead of the system's. Each user has
 * one broker session per terminal account ([home]`/.hapticon/devices/USER`), beside those of the user's phones.
 */
fun runChat(
    args: List<String>,
    console: Console,
    input: Reader = InputStreamReader(System.`in`, Charsets.UTF_8),
    home: File = File(System.getProperty("user.home")),
) {
    val arguments = Arguments.parse(
        "chat", args,
        valueOptions = setOf("broker", "user", "to", "password-file", "wav-dir", "keys-dir", "data-dir", "client-cert", "client-cert-password-file", "ca"),
        flagOptions = setOf("anonymous", "e2e", "plaintext"),
    )
    arguments.requireNoPositionals()
    val broker = try {
        BrokerAddress.parse(arguments.required("broker"))
    } catch (e: IllegalArgumentException) {
        throw UsageException("--broker: ${e.message}")
    }
    val user = userName(arguments.required("user"), "--user")
    val peer = arguments.value("to")?.let { userName(it, "--to") }
    val password = arguments.value("password-file")?.let { String(readPasswordFile(it)) }
    val certificate = arguments.value("client-cert")?.let { clientCertificate(it, arguments.value("client-cert-password-file")) }
    if (certificate == null && arguments.value("client-cert-password-file") != null) throw UsageException("--client-cert-password-file needs --client-cert")
    if (password == null && certificate == null && !arguments.flag("anonymous")) {
        throw UsageException("chat needs --password-file FILE or --client-cert FILE.p12 (the broker authenticates every user), or --anonymous for a broker run with --allow-anonymous")
    }
    if ((password != null || certificate != null) && arguments.flag("anonymous")) throw UsageException("--anonymous excludes --password-file and --client-cert")
    val trusted = arguments.value("ca")?.let { path ->
        val file = File(path)
        if (!file.isFile) throw UsageException("--ca $path: no such file")
        if (file.length() > ClientCertificate.MAX_PKCS12_BYTES) throw UsageException("--ca $path is larger than ${ClientCertificate.MAX_PKCS12_BYTES / 1024} KiB: not a CA certificate")
        try {
            ClientCertificate.certificatesFromPem(file.readBytes())
        } catch (e: IllegalArgumentException) {
            throw UsageException("--ca $path: ${e.message}")
        }
    }.orEmpty()
    val device = deviceOf(user, home)
    val settings = try {
        MqttSettings(broker, user, password, device, clientCertificate = certificate, trustedCertificates = trusted)
    } catch (e: IllegalArgumentException) {
        throw UsageException("${if (certificate != null && certificate.user != user) "--client-cert" else "--broker"}: ${e.message}")
    }
    certificate?.let { console.err.println("chat: client certificate of ${it.user}, valid until ${it.notAfter}") }
    val wavDir = arguments.value("wav-dir")?.let(::File)?.also(OutputFiles::ensureDirectory)

    val plaintext = arguments.flag("plaintext")
    if (plaintext && arguments.flag("e2e")) throw UsageException("--plaintext excludes --e2e")
    if (plaintext && arguments.value("keys-dir") != null) throw UsageException("--keys-dir is for end-to-end encryption, which --plaintext turns off")
    val store = chatStore(File(arguments.value("data-dir") ?: File(System.getProperty("user.home"), ".hapticon/chat/$user").path))
    store.use {
        val e2e = if (plaintext) {
            // Loud on purpose, at every start: the operator reads and may forge everything this chat sends and receives.
            console.err.println("chat: WARNING: --plaintext: end-to-end encryption is OFF; the broker's operator can read and forge every message, and peers who encrypt refuse these")
            null
        } else {
            endToEnd(user, arguments.value("keys-dir"), console)
        }
        val messenger = MqttMessenger(settings, e2e)
        val gate = InboxGate(store, VibrationRateLimiter(Clock.MONOTONIC))
        console.err.println("chat: connecting to $broker as $user")
        val session = ChatSession(messenger, peer, console.out, console.err, wavDir, gate, e2e = e2e, outbox = store, keptIn = store.file)
        try {
            runBlocking { session.run(BufferedReader(input)) }
        } catch (e: MessagingException) {
            throw UsageException(e.message ?: "cannot connect to $broker")
        }
    }
}

/** The chat's store in [dir] (`chat.db`), made on first use; one line when it cannot be opened. */
private fun chatStore(dir: File): ChatStore = try {
    ChatStore.open(File(dir, "chat.db"))
} catch (e: java.sql.SQLException) {
    throw UsageException("--data-dir: cannot open ${File(dir, "chat.db")} (${e.message?.lineSequence()?.firstOrNull()})")
}

/**
 * This terminal's device id for [user] ([DeviceId]: its own broker session, a secret), kept in
 * `HOME/.hapticon/devices/USER` (mode 600) and made on first use.
 */
private fun deviceOf(user: String, home: File): DeviceId {
    val file = File(home, ".hapticon/devices/$user")
    return try {
        DeviceId.loadOrCreate(file)
    } catch (e: IOException) {
        throw UsageException("cannot keep this device's session id: ${e.message}")
    }
}

/**
 * [user]'s keys from [keysDir] (default `~/.hapticon/keys/USER`): `identity.keys` (private, mode 600, made on
 * first use) and `pins/PEER.pub` (the peers' keys as first seen).
 */
private fun endToEnd(user: String, keysDir: String?, console: Console): EndToEnd {
    val dir = File(keysDir ?: File(System.getProperty("user.home"), ".hapticon/keys/$user").path)
    val identityFile = File(dir, "identity.keys")
    val identity = try {
        Identity.loadOrCreate(user, identityFile)
    } catch (e: GeneralSecurityException) {
        throw UsageException("--keys-dir: $identityFile is not a key file of $user (${e.message})")
    } catch (e: IOException) {
        throw UsageException("--keys-dir: cannot write $identityFile (${e.message})")
    }
    console.err.println("chat: end-to-end encryption on; keys of $user in $dir (--plaintext turns it off)")
    return EndToEnd(identity, FileKeyPins(File(dir, "pins")))
}

/**
 * The PKCS#12 client certificate at [path], opened with the first line of [passwordFile] (never a password on the
 * command line, where `ps` shows it). Every problem is one line: missing file, wrong password, expired, no user.
 */
private fun clientCertificate(path: String, passwordFile: String?): ClientCertificate {
    val file = File(path)
    if (!file.isFile) throw UsageException("--client-cert $path: no such file")
    if (file.length() > ClientCertificate.MAX_PKCS12_BYTES) throw UsageException("--client-cert $path is larger than ${ClientCertificate.MAX_PKCS12_BYTES / 1024} KiB: not a PKCS#12 file")
    val password = readPasswordFile(
        passwordFile ?: throw UsageException("--client-cert needs --client-cert-password-file FILE (the PKCS#12 password's file)"),
        "--client-cert-password-file",
    )
    return try {
        ClientCertificate.fromPkcs12(file.readBytes(), password)
    } catch (e: IllegalArgumentException) {
        throw UsageException("--client-cert $path: ${e.message}")
    } catch (e: IOException) {
        throw UsageException("cannot read --client-cert $path: ${e.message}")
    } finally {
        password.fill('\u0000')
    }
}

private fun userName(name: String, option: String): String {
    if (!Topics.isValidUserName(name)) {
        throw UsageException("$option must be 1..${Topics.MAX_USER_NAME_LENGTH} letters, digits, '.', '_' or '-', starting with a letter or digit; got '$name'")
    }
    return name
}
