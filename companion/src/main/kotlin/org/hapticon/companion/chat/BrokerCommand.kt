package org.hapticon.companion.chat

import org.hapticon.companion.Arguments
import org.hapticon.companion.Console
import org.hapticon.companion.UsageException
import org.hapticon.messaging.broker.EmbeddedBroker
import java.io.File
import java.net.Inet4Address
import java.net.NetworkInterface
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.mqtt.BrokerAddress
import java.io.IOException

/**
 * `hapticon broker [--port N] [--data DIR]`: runs the embedded MQTT broker on 127.0.0.1 in the foreground
 * until the process is stopped (Ctrl-C). [waitForStop] blocks until then; tests pass their own.
 */
fun runBroker(args: List<String>, console: Console, waitForStop: () -> Unit = { Thread.currentThread().join() }) {
    val arguments = Arguments.parse("broker", args, valueOptions = setOf("port", "data"))
    arguments.requireNoPositionals()
    val port = arguments.int("port", DEFAULT_BROKER_PORT)
    if (port !in 1..65_535) throw UsageException("--port must be in 1..65535, got $port")
    val data = File(arguments.value("data") ?: defaultDataDirectory())
    val broker = EmbeddedBroker(data, port)
    try {
        broker.start()
    } catch (e: IOException) {
        throw UsageException("cannot start the broker: ${e.message}")
    }
    // Ctrl-C ends the JVM through its shutdown hooks; this one closes the store so queued messages are kept.
    val hook = Thread { broker.stop() }
    Runtime.getRuntime().addShutdownHook(hook)
    console.out.println("broker: listening on tcp://${EmbeddedBroker.HOST}:${broker.port}, store in $data; Ctrl-C stops it")
    // The invitation a phone opens (or scans in the app) to fill in this broker: the same link the app shares.
    lanAddress()?.let { console.out.println("invite: ${InviteLink(null, BrokerAddress(it, broker.port))}") }
    console.out.flush()
    try {
        waitForStop()
    } finally {
        Runtime.getRuntime().removeShutdownHook(hook)
        broker.stop()
    }
}

/** The standard MQTT port, which `hapticon broker` uses unless told otherwise. */
const val DEFAULT_BROKER_PORT: Int = 1883

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
