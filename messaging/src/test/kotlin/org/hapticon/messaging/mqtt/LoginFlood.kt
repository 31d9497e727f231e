package org.hapticon.messaging.mqtt

import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import java.io.DataInputStream
import java.io.IOException
import java.net.Socket
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.concurrent.atomic.AtomicInteger

/**
 * The wrong-password flood: [connections] threads, each sending MQTT 3.1.1 CONNECTs as [victim] with a wrong password
 * and a client id of the victim's form (`victim:` and 32 new hex digits: a device the broker has never seen), one
 * after the other as fast as the broker answers, from [start] to [stop]. Raw sockets, so the attackers cost this JVM
 * next to nothing.
 */
class LoginFlood(private val host: String, private val port: Int, private val victim: String, private val connections: Int = 32) {
    private val running = AtomicBoolean()
    private val threads = mutableListOf<Thread>()

    /** CONNACK return codes the flood got, by code (-1: the broker closed the connection without one). */
    val replies: MutableMap<Int, AtomicInteger> = ConcurrentHashMap()

    fun start() {
        running.set(true)
        repeat(connections) { n ->
            threads += Thread({
                var attempt = 0
                while (running.get()) {
                    val code = connect("$victim:${DeviceId.generate().value}", "wrong-$n-${attempt++}")
                    replies.computeIfAbsent(code) { AtomicInteger() }.incrementAndGet()
                }
            }, "login-flood-$n").apply { isDaemon = true; start() }
        }
    }

    /** Stops the attackers, waiting for each one's answer in flight; returns [replies] as plain numbers. */
    fun stop(): Map<Int, Int> {
        running.set(false)
        threads.forEach { it.join(60_000) }
        return replies.mapValues { it.value.get() }.toSortedMap()
    }

    /** One CONNECT; the CONNACK return code, or -1 when the broker closed the connection or did not answer. */
    private fun connect(clientId: String, password: String): Int = try {
        Socket(host, port).use { socket ->
            socket.soTimeout = 60_000
            fun field(text: String): ByteArray = text.toByteArray().let { byteArrayOf((it.size shr 8).toByte(), it.size.toByte()) + it }
            // protocol "MQTT" level 4 (3.1.1), flags: user name, password, clean session; keep-alive 30 s
            val body = field("MQTT") + byteArrayOf(4, 0xC2.toByte(), 0, 30) + field(clientId) + field(victim) + field(password)
            check(body.size < 128) { "one-byte remaining length" }
            socket.getOutputStream().write(byteArrayOf(0x10, body.size.toByte()) + body)
            val reply = DataInputStream(socket.getInputStream())
            if (reply.read() != 0x20) -1 else reply.readNBytes(3)[2].toInt()
        }
    } catch (e: IOException) {
        -1
    }

    companion object {
        const val BAD_USER_NAME_OR_PASSWORD = 4
        const val SERVER_UNAVAILABLE = 3

        /**
         * Sends bob [count] messages from [alice], one at a time, 100 ms apart, and returns each one's latency in ms: from
         * the send to [bobInbox] (a queue [inboxListener] fills) holding it.
         */
        fun latencies(alice: MqttMessenger, bob: String, bobInbox: LinkedBlockingQueue<Pair<InboxEvent, Long>>, count: Int): List<Double> =
            List(count) { i ->
                val message = ChatMessage.compose(alice.user, "latency probe $i")
                val sent = System.nanoTime()
                runBlocking { alice.send(bob, message) }
                var arrived: Pair<InboxEvent, Long>
                do {
                    arrived = bobInbox.poll(120, TimeUnit.SECONDS) ?: throw AssertionError("probe $i did not arrive")
                } while (arrived.first != InboxEvent.MessageReceived(message))
                Thread.sleep(100)
                (arrived.second - sent) / 1e6
            }

        /** A listener that puts every event into [queue] with the time it arrived. */
        fun inboxListener(queue: LinkedBlockingQueue<Pair<InboxEvent, Long>>): InboxListener = InboxListener { queue.put(it to System.nanoTime()) }

        /** "median X ms, max Y ms" of [latencies]. */
        fun summary(latencies: List<Double>): String {
            val sorted = latencies.sorted()
            return "median %.1f ms, max %.1f ms (%d messages)".format(sorted[sorted.size / 2], sorted.last(), sorted.size)
        }
    }
}
