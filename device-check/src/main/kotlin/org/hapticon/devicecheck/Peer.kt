package org.hapticon.devicecheck

import android.os.SystemClock
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.messaging.e2e.KeyBundle
import org.hapticon.messaging.e2e.KeyPins
import kotlinx.coroutines.delay
import org.hapticon.messaging.mqtt.MqttSettings

/**
 * The other person in the chat: the app's own messaging (wire format, receipts, the HiveMQ client) running in the
 * suite's process as [DeviceCheckArguments.peer]. It sends messages to the app's user and records every receipt that
 * comes back, with the moment it arrived.
 */
class Peer(private val args: DeviceCheckArguments) : AutoCloseable {
    // Sealed end to end, as the app (encrypting by default) accepts; a device id of its own, as every client has.
    private val messenger = MqttMessenger(
        MqttSettings(BrokerAddress.parse(args.broker), args.peer, args.peerPassword, DeviceId.generate()),
        EndToEnd(Identity.generate(args.peer), PeerKeyPins()),
    )
    private val receipts = CopyOnWriteArrayList<Arrived>()
    private val capabilities = ConcurrentHashMap<String, Capabilities>()

    /** A receipt and when it arrived here (uptime milliseconds). */
    data class Arrived(val receipt: Receipt, val atUptimeMillis: Long)

    fun connect() = runBlocking {
        withTimeout(CONNECT_TIMEOUT_MILLIS) {
            messenger.connect { event ->
                when (event) {
                    is InboxEvent.ReceiptReceived -> receipts += Arrived(event.receipt, SystemClock.uptimeMillis())
                    is InboxEvent.CapabilitiesReceived -> capabilities[event.capabilities.user] = event.capabilities
                    else -> Unit
                }
            }
        }
    }

    /**
     * Sends [text] with [icon] to the app's user; returns the message sent. Sealing needs the user's key, retained on
     * the broker and arriving just after connecting: until it is there, sending is refused and tried again.
     */
    fun send(text: String, icon: HapticIcon? = null): ChatMessage {
        val message = ChatMessage.compose(args.peer, text, icon = icon)
        val deadline = SystemClock.uptimeMillis() + CONNECT_TIMEOUT_MILLIS
        runBlocking {
            while (true) {
                try {
                    messenger.send(args.user, message)
                    break
                } catch (e: MessagingException) {
                    if (SystemClock.uptimeMillis() > deadline) throw e
                    delay(50)
                }
            }
        }
        return message
    }

    /** The first [state] receipt for [message] within [millis], or null. */
    fun await(message: ChatMessage, state: ReceiptState, millis: Long): Arrived? {
        AppUnderTest.waitFor(millis) { find(message, state) != null }
        return find(message, state)
    }

    fun find(message: ChatMessage, state: ReceiptState): Arrived? =
        receipts.firstOrNull { it.receipt.messageId == message.id && it.receipt.state == state }

    /** What the app's user published about its phone (retained on the broker), or null. */
    fun capabilitiesOf(user: String): Capabilities? = capabilities[user]

    override fun close() = runBlocking { messenger.disconnect() }

    private companion object {
        const val CONNECT_TIMEOUT_MILLIS = 20_000L
    }
}

/** The peer's key pins: held for one run of the suite, as its identity is (a new one each run). */
private class PeerKeyPins : KeyPins {
    private val byUser = ConcurrentHashMap<String, KeyBundle>()
    override fun pinned(user: String): KeyBundle? = byUser[user]
    override fun pin(bundle: KeyBundle) = byUser.set(bundle.user, bundle)
}
