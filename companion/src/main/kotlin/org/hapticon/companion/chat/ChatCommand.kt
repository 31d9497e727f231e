package org.hapticon.companion.chat

import kotlinx.coroutines.runBlocking
import org.hapticon.companion.Arguments
import org.hapticon.companion.Console
import org.hapticon.companion.OutputFiles
import org.hapticon.companion.UsageException
import org.hapticon.messaging.BoundedDeduplicator
import org.hapticon.messaging.Clock
import org.hapticon.messaging.InboxGate
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Topics
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.mqtt.BrokerAddress
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import java.io.BufferedReader
import java.io.File
import java.io.IOException
import java.io.InputStreamReader
import java.io.Reader

/**
 * `hapticon chat --broker URL --user NAME [--to PEER] [--device ID] [--password-file FILE] [--wav-dir DIR]`:
 * a terminal chat over MQTT with the phone app or another `hapticon chat`. Reads lines from [input]
 * (stdin by default) until `/quit` or its end; see [ChatSession].
 */
fun runChat(args: List<String>, console: Console, input: Reader = InputStreamReader(System.`in`, Charsets.UTF_8)) {
    val arguments = Arguments.parse("chat", args, valueOptions = setOf("broker", "user", "to", "device", "password-file", "wav-dir"))
    arguments.requireNoPositionals()
    val broker = try {
        BrokerAddress.parse(arguments.required("broker"))
    } catch (e: IllegalArgumentException) {
        throw UsageException("--broker: ${e.message}")
    }
    val user = userName(arguments.required("user"), "--user")
    val peer = arguments.value("to")?.let { userName(it, "--to") }
    val device = arguments.value("device")?.let { userName(it, "--device") } ?: DEFAULT_DEVICE
    val password = arguments.value("password-file")?.let(::readPassword)
    val wavDir = arguments.value("wav-dir")?.let(::File)?.also(OutputFiles::ensureDirectory)

    val messenger = MqttMessenger(MqttSettings(broker, user, device, password))
    val gate = InboxGate(BoundedDeduplicator(), VibrationRateLimiter(Clock.MONOTONIC))
    console.err.println("chat: connecting to $broker as $user (client id ${MqttSettings(broker, user, device).clientId})")
    val session = ChatSession(messenger, peer, console.out, console.err, wavDir, gate)
    try {
        runBlocking { session.run(BufferedReader(input)) }
    } catch (e: MessagingException) {
        throw UsageException(e.message ?: "cannot connect to $broker")
    }
}

/** The device id when `--device` is not given; a second chat as the same user needs another one. */
const val DEFAULT_DEVICE: String = "cli"

private fun userName(name: String, option: String): String {
    if (!Topics.isValidUserName(name)) {
        throw UsageException("$option must be 1..${Topics.MAX_USER_NAME_LENGTH} letters, digits, '.', '_' or '-', starting with a letter or digit; got '$name'")
    }
    return name
}

// A password on the command line would show in `ps` and the shell history; a file (mode 600) does not.
private fun readPassword(path: String): String {
    val file = File(path)
    if (!file.isFile) throw UsageException("--password-file $path: no such file")
    val text = try {
        if (file.length() > 4096) throw UsageException("--password-file $path is larger than 4096 bytes")
        file.readText()
    } catch (e: IOException) {
        throw UsageException("cannot read --password-file $path: ${e.message}")
    }
    return text.lineSequence().firstOrNull()?.takeIf { it.isNotEmpty() } ?: throw UsageException("--password-file $path is empty")
}
