package org.hapticon.messaging.mqtt

import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.MqttGlobalPublishFilter
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3BlockingClient
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.util.concurrent.TimeUnit

/**
 * Why the tests start brokers through [OneBrokerAtATime]: a HiveMQ CE broker started beside a running one
 * resets the process-wide publish counter, and the running one then delivers a payload it holds (mallory's
 * retained key) in place of a new publish. Stopping the first broker before the second starts keeps every
 * payload right.
 */
class OneBrokerAtATimeTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun client(port: Int, id: String, clean: Boolean = true): Mqtt3BlockingClient =
        MqttClient.builder().useMqttVersion3().identifier(id).serverHost(EmbeddedBroker.HOST).serverPort(port).buildBlocking()
            .also { it.connectWith().cleanSession(clean).send() }

    private fun exchange(between: (EmbeddedBroker, EmbeddedBroker) -> Unit): Pair<List<String>, List<String>> {
        val a = EmbeddedBroker(temp.newFolder(), security = BrokerSecurity.AllowAnonymous)
        val b = EmbeddedBroker(temp.newFolder(), security = BrokerSecurity.AllowAnonymous)
        try {
            OneBrokerAtATime.start(a) // stops the shared broker: this test's point is which brokers run at once
            val mallory = client(a.port, "mallory")
            mallory.publishWith().topic("keys/mallory").qos(MqttQos.AT_LEAST_ONCE).retain(true).payload("mallory-key".toByteArray()).send()
            mallory.disconnect()
            between(a, b)
            val bob = client(a.port, "bob", clean = false)
            bob.subscribeWith().topicFilter("inbox/bob").qos(MqttQos.AT_LEAST_ONCE).send()
            bob.disconnect()
            val alice = client(a.port, "alice")
            val sent = (1..20).map { "alice-$it" }
            sent.forEach { alice.publishWith().topic("inbox/bob").qos(MqttQos.AT_LEAST_ONCE).payload(it.toByteArray()).send() }
            alice.disconnect()
            val bobAgain = MqttClient.builder().useMqttVersion3().identifier("bob").serverHost(EmbeddedBroker.HOST).serverPort(a.port).buildBlocking()
            val got = bobAgain.publishes(MqttGlobalPublishFilter.ALL).use { inbox ->
                bobAgain.connectWith().cleanSession(false).send()
                sent.map { String(inbox.receive(10, TimeUnit.SECONDS).get().payloadAsBytes) }
            }
            bobAgain.disconnect()
            return sent to got
        } finally {
            b.stop()
            a.stop()
        }
    }

    @Test
    fun secondBrokerStartedWhileTheFirstRuns_firstDeliversAnOldPayload() {
        // HiveMQ CE 2025.5 behaviour (PublishPayloadRocksDBLocalPersistence.init); when this fails, HiveMQ
        // fixed it and OneBrokerAtATime could go.
        val (sent, got) = exchange { _, b -> b.start() }
        assertTrue("$got", got != sent && "mallory-key" in got)
    }

    @Test
    fun secondBrokerOnlyWhileTheFirstIsStopped_everyPayloadArrivesAsSent() {
        val (sent, got) = exchange { a, b ->
            OneBrokerAtATime.start(b)
            assertEquals(false, a.isRunning)
            OneBrokerAtATime.start(a)
            assertEquals(false, b.isRunning)
        }
        assertEquals(sent, got)
    }
}
