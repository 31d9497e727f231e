package org.hapticon.companion.chat

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.messaging.Topics
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.BrokerTls
import org.hapticon.messaging.broker.CertificateAuthority
import org.hapticon.messaging.broker.ClientCertificates
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import java.io.BufferedReader
import java.io.File
import java.net.Inet4Address
import java.net.NetworkInterface
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.BrokerAddress
import java.io.IOException
import java.io.InputStreamReader
import java.io.Reader

/**
 * `hapticon broker [--port N] [--host ADDR] [--data DIR] [--users FILE] [--acl FILE] [--allow-anonymous]
 * [--tls-port N [--client-certs required|optional|none] [--ca-dir DIR]]`: runs the embedded MQTT broker in the foreground until the process is stopped (Ctrl-C). Every client
 * authenticates against the users file (Mosquitto's password-file format; created empty on first run) and
 * is held to the ACL file (Mosquitto's format; written from [AclFile.DEFAULT_TEXT] on first run): the same
 * rules as the Mosquitto deployment. `--allow-anonymous` switches that off, loudly. [waitForStop] blocks
 * until the broker should stop; tests pass their own.
 *
 * `hapticon broker adduser NAME [--data DIR | --users FILE] [--password-file FILE | --generate] [--iterations N]` adds
 * a user or changes its password; the password comes from the file's first line, else from the terminal (asked
 * twice, not echoed), else from the first line of [input]; `--generate` makes a random one and prints it once. It is
 * stored with N PBKDF2 rounds (210,000 by default). A running broker sees the change at once.
 *
 * `--tls-port` adds a TLS listener on `--host` (the plain one then stays on 127.0.0.1) with the broker certificate
 * of `hapticon broker ca init`; `--client-certs` (default required) says whether clients must show a certificate of
 * that CA (`hapticon broker cert issue USER`), may, or need not. docs/security.md, "Client certificates".
 */
fun runBroker(
    args: List<String>,
    console: Console,
    input: Reader = InputStreamReader(System.`in`, Charsets.UTF_8),
    waitForStop: () -> Unit = { Thread.currentThread().join() },
) {
    if (args.firstOrNull() == "adduser") return addUser(args.drop(1), console, input)
    if (args.take(2) == listOf("ca", "init")) return initCertificateAuthority(args.drop(2), console)
    if (args.take(2) == listOf("cert", "issue")) return issueCertificate(args.drop(2), console, input)
    if (args.firstOrNull() == "ca" || args.firstOrNull() == "cert") throw UsageException("broker ${args[0]}: expected 'broker ca init' or 'broker cert issue USER'")
    val arguments = Arguments.parse(
        "broker", args,
        valueOptions = setOf("port", "host", "data", "users", "acl", "tls-port", "client-certs", "ca-dir"),
        flagOptions = setOf("allow-anonymous"),
    )
    arguments.requireNoPositionals()
    val port = arguments.int("port", DEFAULT_BROKER_PORT)
    if (port !in 1..65_535) throw UsageException("--port must be in 1..65535, got $port")
    val data = File(arguments.value("data") ?: defaultDataDirectory())
    val tls = tlsListener(arguments, data)
    // With a TLS listener, --host is where it listens; the plain listener (passwords in clear) stays on loopback.
    val tlsHost = arguments.value("host") ?: EmbeddedBroker.HOST
    val host = if (tls != null) EmbeddedBroker.HOST else tlsHost
    val security = if (arguments.flag("allow-anonymous")) {
        console.err.println(
            "broker: WARNING --allow-anonymous: any client that reaches $host:$port connects without a password, " +
                "reads every inbox and sends as anyone. Use it for a throw-away local test only.",
        )
        BrokerSecurity.AllowAnonymous
    } else {
        prepareSecurity(arguments, data, console)
    }
    val broker = EmbeddedBroker(File(data, "store"), port, security, host, listOfNotNull(tls?.copy(host = tlsHost)))
    try {
        broker.start()
    } catch (e: IOException) {
        throw UsageException("cannot start the broker: ${e.message}")
    }
    // Ctrl-C ends the JVM through its shutdown hooks; this one closes the store so queued messages are kept.
    val hook = Thread { broker.stop() }
    Runtime.getRuntime().addShutdownHook(hook)
    val auth = if (security is BrokerSecurity.Authenticated) "users ${security.passwordFile}, ACL ${security.aclFile}" else "ANONYMOUS"
    console.out.println("broker: listening on tcp://${if (':' in host) "[$host]" else host}:${broker.port} ($auth), store in ${broker.dataDirectory}; Ctrl-C stops it")
    if (tls != null) {
        val mode = when (tls.clientCertificates) {
            ClientCertificates.REQUIRED -> "client certificate of ${tls.clientCaFile} required; passwords not accepted there"
            ClientCertificates.OPTIONAL -> "client certificate of ${tls.clientCaFile} or password"
            ClientCertificates.NONE -> "passwords, no client certificates"
        }
        console.out.println("broker: TLS on ssl://${if (':' in tlsHost) "[$tlsHost]" else tlsHost}:${broker.tlsPort()} ($mode); clients trust ${File(tls.certificateFile.parentFile, "ca.crt")}")
    }
    if (tlsHost == EmbeddedBroker.HOST) console.out.println("broker: reachable from this machine only; --host ADDRESS (e.g. this laptop's Wi-Fi address) lets phones in")
    // The invitation a phone opens (or scans in the app) to fill in this broker: the same link the app shares.
    val inviteHost = if (tlsHost != EmbeddedBroker.HOST) tlsHost else lanAddress()
    inviteHost?.let {
        val hint = if (tlsHost == EmbeddedBroker.HOST) " (start the broker with --host $it so that phones can reach it)" else ""
        val address = if (tls != null) BrokerAddress(it, broker.tlsPort(), tls = true) else BrokerAddress(it, broker.port)
        console.out.println("invite: ${InviteLink(null, address)}$hint")
    }
    console.out.flush()
    try {
        waitForStop()
    } finally {
        Runtime.getRuntime().removeShutdownHook(hook)
        broker.stop()
    }
}

/** The TLS listener `--tls-port` asks for, with the CA of `--ca-dir` (default DATA/ca); null without `--tls-port`. */
private fun tlsListener(arguments: Arguments, data: File): BrokerTls? {
    val modes = mapOf("required" to ClientCertificates.REQUIRED, "optional" to ClientCertificates.OPTIONAL, "none" to ClientCertificates.NONE)
    if (arguments.value("tls-port") == null) {
        if (arguments.value("client-certs") != null || arguments.value("ca-dir") != null) throw UsageException("--client-certs and --ca-dir need --tls-port")
        return null
    }
    val tlsPort = arguments.int("tls-port", DEFAULT_BROKER_TLS_PORT)
    if (tlsPort !in 1..65_535) throw UsageException("--tls-port must be in 1..65535, got $tlsPort")
    val mode = arguments.choice("client-certs", modes, ClientCertificates.REQUIRED)
    val caDir = File(arguments.value("ca-dir") ?: File(data, "ca").path)
    if (!CertificateAuthority.exists(caDir)) {
        throw UsageException("--tls-port: no certificate authority in $caDir; make one first: hapticon broker ca init --host ADDRESS" + (arguments.value("ca-dir")?.let { " --ca-dir $it" } ?: arguments.value("data")?.let { " --data $it" } ?: ""))
    }
    val ca = CertificateAuthority.load(caDir)
    return BrokerTls(tlsPort, EmbeddedBroker.HOST, ca.serverCertificateFile, ca.serverKeyFile, ca.certificateFile, mode)
}

/**
 * `hapticon broker ca init [--data DIR | --ca-dir DIR] [--host NAME[,NAME…]]`: the study's certificate authority
 * and the broker's certificate for the given host names and addresses (plus localhost and 127.0.0.1).
 */
private fun initCertificateAuthority(args: List<String>, console: Console) {
    val arguments = Arguments.parse("broker ca init", args, valueOptions = setOf("data", "ca-dir", "host"))
    arguments.requireNoPositionals()
    val caDir = caDirectory(arguments)
    val hosts = arguments.value("host")?.split(',')?.map { it.trim() }?.filter { it.isNotEmpty() } ?: listOfNotNull(lanAddress())
    for (host in hosts) {
        if (!host.matches(Regex("[A-Za-z0-9.:-]{1,253}"))) throw UsageException("--host: not a host name or address: '$host'")
    }
    val ca = try {
        CertificateAuthority.init(caDir, "Hapticon study CA", hosts)
    } catch (e: IOException) {
        throw UsageException("broker ca init: ${e.message}")
    }
    console.out.println("broker: certificate authority in $caDir: ca.crt (give it to clients), ca.key (mode 600, keep it secret)")
    console.out.println("broker: broker certificate server.crt for localhost, 127.0.0.1${hosts.joinToString("") { ", $it" }} (key server.key, mode 600)")
    console.out.println("broker: next: hapticon broker cert issue USER" + caHint(arguments) + ", then hapticon broker --tls-port $DEFAULT_BROKER_TLS_PORT" + caHint(arguments))
}

/**
 * `hapticon broker cert issue USER [--data DIR | --ca-dir DIR] [--out FILE] [--password-file FILE] [--days N]`:
 * USER's client certificate and a fresh key as a PKCS#12 file (mode 600), encrypted with the password from the
 * file (else asked twice on the terminal, else the first line of [input]).
 */
private fun issueCertificate(args: List<String>, console: Console, input: Reader) {
    val arguments = Arguments.parse("broker cert issue", args, valueOptions = setOf("data", "ca-dir", "out", "password-file", "days"))
    val user = arguments.single("a user name")
    if (!Topics.isValidUserName(user)) {
        throw UsageException("the user name must be 1..${Topics.MAX_USER_NAME_LENGTH} letters, digits, '.', '_' or '-', starting with a letter or digit; got '$user'")
    }
    val days = arguments.int("days", CertificateAuthority.DEFAULT_CLIENT_VALIDITY.toDays().toInt())
    if (days !in 1..MAX_CERTIFICATE_DAYS) throw UsageException("--days must be in 1..$MAX_CERTIFICATE_DAYS, got $days")
    val ca = try {
        CertificateAuthority.load(caDirectory(arguments))
    } catch (e: IOException) {
        throw UsageException("broker cert issue: ${e.message}")
    }
    val out = File(arguments.value("out") ?: "$user.p12")
    if (out.exists()) throw UsageException("--out $out exists already; move it away or choose another file")
    val password = arguments.value("password-file")?.let(::readPasswordFile) ?: askPassword("$user.p12", input)
    try {
        CertificateAuthority.writeAtomically(out, ca.issueClient(user, password, java.time.Duration.ofDays(days.toLong())))
    } catch (e: IOException) {
        throw UsageException("cannot write $out: ${e.message}")
    } finally {
        password.fill('\u0000')
    }
    console.out.println("broker: $out (mode 600): client certificate of $user, valid $days days; with ${ca.certificateFile} it connects to a --tls-port listener")
}

private fun caDirectory(arguments: Arguments): File =
    File(arguments.value("ca-dir") ?: File(arguments.value("data") ?: defaultDataDirectory(), "ca").path)

private fun caHint(arguments: Arguments): String =
    arguments.value("ca-dir")?.let { " --ca-dir $it" } ?: arguments.value("data")?.let { " --data $it" } ?: ""

/** Longer than a CA's own ten years makes no sense; a study runs months. */
private const val MAX_CERTIFICATE_DAYS = 3650

/** The users and ACL files of a broker run, created on first use. */
private fun prepareSecurity(arguments: Arguments, data: File, console: Console): BrokerSecurity.Authenticated {
    val users = File(arguments.value("users") ?: File(data, "passwd").path)
    val acl = File(arguments.value("acl") ?: File(data, "aclfile").path)
    try {
        if (!acl.exists() && arguments.value("acl") == null) {
            acl.absoluteFile.parentFile.mkdirs()
            acl.writeText(AclFile.DEFAULT_TEXT)
        }
        AclFile.read(acl)
    } catch (e: IOException) {
        throw UsageException("--acl: ${e.message}")
    }
    val passwords = PasswordFile(users)
    val known = try {
        passwords.users()
    } catch (e: IOException) {
        throw UsageException("cannot read the users file $users: ${e.message}")
    }
    if (!passwords.exists) {
        users.absoluteFile.parentFile.mkdirs()
        users.createNewFile()
        users.setReadable(false, false)
        users.setReadable(true, true)
        users.setWritable(false, false)
        users.setWritable(true, true)
    }
    if (known.isEmpty()) {
        console.out.println("broker: no users yet in $users; nobody can connect until you add one:")
        console.out.println("broker:   hapticon broker adduser NAME" + (arguments.value("users")?.let { " --users $it" } ?: arguments.value("data")?.let { " --data $it" } ?: ""))
    } else {
        console.out.println("broker: ${known.size} user(s): ${known.joinToString(", ")}")
    }
    return BrokerSecurity.Authenticated(users, acl)
}

private fun addUser(args: List<String>, console: Console, input: Reader) {
    val arguments = Arguments.parse("broker adduser", args, valueOptions = setOf("data", "users", "password-file", "iterations"), flagOptions = setOf("generate"))
    val name = arguments.single("a user name")
    if (!Topics.isValidUserName(name)) {
        throw UsageException("the user name must be 1..${Topics.MAX_USER_NAME_LENGTH} letters, digits, '.', '_' or '-', starting with a letter or digit; got '$name'")
    }
    val iterations = arguments.int("iterations", PasswordFile.DEFAULT_ITERATIONS)
    if (iterations !in 1..MAX_ITERATIONS) throw UsageException("--iterations must be in 1..$MAX_ITERATIONS, got $iterations")
    val generate = arguments.flag("generate")
    if (generate && arguments.value("password-file") != null) throw UsageException("--generate excludes --password-file")
    val users = File(arguments.value("users") ?: File(arguments.value("data") ?: defaultDataDirectory(), "passwd").path)
    val password = when {
        generate -> generatedPassword()
        else -> arguments.value("password-file")?.let(::readPasswordFile) ?: askPassword(name, input)
    }
    try {
        PasswordFile(users).add(name, password, iterations)
        if (generate) console.out.println("broker: password of $name: ${String(password)} (shown once; give it to $name)")
    } catch (e: IOException) {
        throw UsageException("cannot write the users file $users: ${e.message}")
    } finally {
        password.fill('\u0000')
    }
    console.out.println("broker: $name can connect now (users file $users)")
}

/**
 * 100 random bits as four groups of five letters and digits (base32 without 0, 1, 8, 9, easy to type on a phone). A
 * password nobody can guess needs no slow hash (docs/security.md, "Floods and guessing"): with it, `--iterations 101`
 * keeps Mosquitto, which checks passwords on its only thread, fast under a wrong-password flood.
 */
private fun generatedPassword(): CharArray {
    val alphabet = "abcdefghijklmnopqrstuvwxyz234567"
    val random = java.security.SecureRandom()
    return CharArray(23) { i -> if (i % 6 == 5) '-' else alphabet[random.nextInt(alphabet.length)] }
}

private const val MAX_ITERATIONS = 10_000_000

private fun askPassword(name: String, input: Reader): CharArray {
    val terminal = System.console()
    if (terminal != null) {
        val first = terminal.readPassword("password for %s: ", name) ?: throw UsageException("no password given")
        val again = terminal.readPassword("again: ") ?: throw UsageException("no password given")
        if (!first.contentEquals(again)) throw UsageException("the two passwords differ")
        if (first.isEmpty()) throw UsageException("the password must not be empty")
        return first
    }
    val line = BufferedReader(input).readLine()?.takeIf { it.isNotEmpty() } ?: throw UsageException("no password on standard input")
    return line.toCharArray()
}

/** The first line of [path], for `--password-file` (or [option]): a password on the command line would show in `ps`. */
internal fun readPasswordFile(path: String, option: String = "--password-file"): CharArray {
    val file = File(path)
    if (!file.isFile) throw UsageException("$option $path: no such file")
    val text = try {
        if (file.length() > 4096) throw UsageException("$option $path is larger than 4096 bytes")
        file.readText()
    } catch (e: IOException) {
        throw UsageException("cannot read $option $path: ${e.message}")
    }
    return text.lineSequence().firstOrNull()?.takeIf { it.isNotEmpty() }?.toCharArray() ?: throw UsageException("$option $path is empty")
}

/** The standard MQTT port, which `hapticon broker` uses unless told otherwise. */
const val DEFAULT_BROKER_PORT: Int = 1883

/** The standard MQTT-over-TLS port. */
const val DEFAULT_BROKER_TLS_PORT: Int = 8883

/**
 * This machine's address on the local network (the first site-local IPv4 address of an interface that
 * is up), which a phone on the same Wi-Fi can reach; null when there is none.
 */
internal fun lanAddress(): String? = runCatching {
    NetworkInterface.getNetworkInterfaces().toList()
        .filter { it.isUp && !it.isLoopback }
        .flatMap { it.inetAddresses.toList() }
        .firstOrNull { it is Inet4Address && it.isSiteLocalAddress }
        ?.hostAddress
}.getOrNull()

private fun defaultDataDirectory(): String = File(System.getProperty("user.home"), ".hapticon/broker").path
