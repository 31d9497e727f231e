package org.hapticon.companion.chat.load

import org.hapticon.companion.cli
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

class BrokerLoadTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun run_fiveUsersThroughTheEmbeddedBroker_accountsForEveryMessageAndReceipt() {
        val load = BrokerLoad(users = 5, durationMillis = 3_000, minIntervalMillis = 200, maxIntervalMillis = 500, burst = 2, baselineSamples = 10)
        val progress = ArrayList<String>()
        val result = load.run(temp.root, ::InProcessEmbeddedBroker) { progress += it }
        val tally = result.tally
        // Five users, each sending every 0.2-0.5 s for 3 s, plus two bursts of 2 each.
        assertTrue(tally.toString(), tally.sent >= 5 * 5 + 20)
        assertEquals(20, tally.burstMillis.count)
        assertEquals(tally.toString(), tally.sent, tally.delivered)
        assertEquals(tally.sent, tally.acknowledged)
        assertEquals(0, tally.lost)
        assertEquals(0, tally.duplicates)
        assertEquals(0, tally.unexpected)
        assertEquals(0, tally.misrouted)
        assertTrue(tally.allAccountedFor)
        assertEquals(tally.delivered, tally.allMillis.count)
        // Each message was answered by a delivered receipt, which reached its sender.
        assertEquals(tally.delivered, result.receiptsSent)
        assertEquals(tally.delivered, result.receiptsReceived)
        assertEquals(5, result.connectionsHeld)
        assertEquals(0, result.drops)
        assertEquals(10, result.baselineMillis.count)
        assertTrue(progress.toString(), progress.any { it.startsWith("embedded: 5 of 5 users connected in ") })
    }

    @Test
    fun benchBrokerLoad_badOptions_areOneLineUsageErrors() {
        for ((args, message) in listOf(
            listOf("--users", "1") to "--users takes numbers in 2..100000 separated by commas, got '1'",
            listOf("--interval", "30-10") to "--interval takes MIN-MAX seconds between one user's messages, 1 <= MIN <= MAX <= 3600, got '30-10'",
            listOf("--broker", "emqx") to "--broker takes embedded, mosquitto or both, got 'emqx'",
        )) {
            val result = cli(*(listOf("bench", "--broker-load") + args).toTypedArray())
            assertEquals(result.toString(), 2, result.exitCode)
            assertTrue(result.stderr, result.stderr.contains(message))
        }
        val stray = cli("bench", "--users", "100")
        assertTrue(stray.stderr, stray.stderr.contains("--users goes with --broker-load"))
    }
}
