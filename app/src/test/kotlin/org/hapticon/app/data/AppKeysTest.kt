package org.hapticon.app.data

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.sync.BrokerProcess
import org.hapticon.app.sync.ChatComponent
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.fail
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.io.File
import java.security.GeneralSecurityException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/** The phone's end-to-end keys: Keystore-wrapped in app storage, and a sealed chat with a JVM peer over a real broker. */
@RunWith(RobolectricTestRunner::class)
class AppKeysTest {
    @get:Rule val temp = TemporaryFolder()
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val dir get() = File(context.filesDir, "e2e-test")

    @Before
    fun installKeystore() {
        TestAndroidKeyStore.install()
        dir.deleteRecursively()
    }

    @After
    fun removeKeystore() = TestAndroidKeyStore.uninstall()

    @Test
    fun keys_madeOnce_storedWrappedByTheKeystoreKey() {
        val first = AppKeys(dir).endToEnd("alice").identity.bundle
        assertEquals(first, AppKeys(dir).endToEnd("alice").identity.bundle)
        val file = File(dir, "alice.keys").readBytes()
        try {
            Identity.deserialize("alice", file, null) // without the Keystore key the file opens nothing
            fail("the key file opened without the Keystore key")
        } catch (e: GeneralSecurityException) {
            assertEquals("the keys of alice are wrapped and no wrapping key was given", e.message)
        }
        TestAndroidKeyStore.keys.clear() // the Keystore key is gone: the messenger is not made at all
        assertEquals(null, ChatComponent.mqttMessenger("alice", "tcp://127.0.0.1:1", "alice-secret", AppKeys(dir), File(dir, "devices")))
    }

    @Test
    fun sealedChat_phoneAndJvmPeer_overARealBroker() = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).use { broker ->
        broker.start()
        val url = "tcp://${EmbeddedBroker.HOST}:${broker.port}"
        val phoneEvents = LinkedBlockingQueue<InboxEvent>()
        val phoneKeys = AppKeys(dir).endToEnd("alice")
        val phone: Messenger = ChatComponent.mqttMessenger("alice", url, "alice-secret", AppKeys(dir), File(dir, "devices"))!!
        val bobE2e = EndToEnd(Identity.generate("bob"), TestKeyPins())
        val bobEvents = LinkedBlockingQueue<InboxEvent>()
        val bob = MqttMessenger(MqttSettings(BrokerAddress.parse(url), "bob", "bob-secret", DeviceId.generate()), bobE2e)
        runBlocking {
            withTimeout(20_000) {
                bob.connect(InboxListener { bobEvents.put(it) })
                phone.connect(InboxListener { phoneEvents.put(it) })
            }
        }
        try {
            val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20)
            while (bobE2e.safetyNumber("alice") == null || phoneKeys.safetyNumber("bob") == null) {
                if (System.nanoTime() > deadline) fail("keys were not exchanged")
                Thread.sleep(10)
            }
            val hello = ChatMessage.compose("alice", "sealed from the phone")
            runBlocking { phone.send("bob", hello) }
            assertEquals(InboxEvent.MessageReceived(hello), bobEvents.nextChat())
            val reply = ChatMessage.compose("bob", "sealed from the laptop")
            runBlocking { bob.send("alice", reply) }
            assertEquals(InboxEvent.MessageReceived(reply), phoneEvents.nextChat())
            // Both sides see one safety number: the phone's pins (in app storage) hold bob's real key.
            assertEquals(bobE2e.safetyNumber("alice"), AppKeys(dir).endToEnd("alice").safetyNumber("bob"))
            assertFalse(File(dir, "pins-alice/bob.pub").readBytes().isEmpty())
        } finally {
            runBlocking {
                phone.disconnect()
                bob.disconnect()
            }
        }
    }

    private fun LinkedBlockingQueue<InboxEvent>.nextChat(): InboxEvent {
        while (true) {
            val event = poll(20, TimeUnit.SECONDS) ?: throw AssertionError("nothing arrived")
            if (event !is InboxEvent.CapabilitiesReceived) return event
        }
    }
}
