package org.hapticon.app.sync

import androidx.room.Room
import org.hapticon.app.playback.usageVibrator
import androidx.test.core.app.ApplicationProvider
import android.content.Context
import android.os.Vibrator
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.CoroutineStart
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.async
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import kotlin.coroutines.EmptyCoroutineContext

/**
 * The connection state the screens see follows the real session when the broker (a child JVM) dies while
 * ChatSync is still doing its on-connect work: a QoS 1 publish in flight on a persistent session is kept by
 * the HiveMQ client for the next connection, so its future completes only after the reconnection. ChatSync
 * once forwarded states and did that work in one collector, so the state stayed Connected through the whole
 * backoff (two minutes here).
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class ChatSyncReconnectTest {
    @get:Rule
    val temp = TemporaryFolder()

    // Every messenger ChatSync makes is this phone's: one session across reconnections.
    private val phoneDevice = DeviceId.generate()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val twoMinutes = RetryPolicy(initialDelayMillis = 120_000, maxDelayMillis = 120_000, jitter = 0.0)
    private lateinit var broker: BrokerProcess
    private lateinit var db: HapticonDatabase

    @After
    fun tearDown() = runBlocking {
        scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin()
        if (::db.isInitialized) db.close()
        if (::broker.isInitialized) broker.stop()
    }

    /** The real messenger; its first capabilities publish is still in flight when the broker is killed. */
    private inner class KilledMidPublish(private val real: MqttMessenger) : Messenger by real {
        @Volatile var killed = false

        override suspend fun publishCapabilities(capabilities: Capabilities) = coroutineScope {
            val publishing = async(start = CoroutineStart.UNDISPATCHED) { real.publishCapabilities(capabilities) }
            if (!killed) {
                killed = true
                broker.kill()
            }
            publishing.await()
        }
    }

    /**
     * A broker in a child JVM, alice's account on it, and a started [ChatSync] whose every messenger is this phone's
     * real one (two-minute backoff) as [wrap] returns it.
     */
    private fun startedSync(wrap: (MqttMessenger) -> Messenger): Pair<ChatSync, InMemoryChatSettings> {
        broker = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).also { it.start() }
        val address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
        val repository = OfflineFirstChatRepository(db)
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = address.toString(), brokerPassword = "alice-secret"))
        val vibrator = context.getSystemService(Vibrator::class.java)
        val sync = ChatSync(
            repository, repository, settings,
            { user, url, password -> wrap(MqttMessenger(MqttSettings(BrokerAddress.parse(url), user, password, phoneDevice, reconnectPolicy = twoMinutes))) },
            AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null }, renderContext = EmptyCoroutineContext), VibrationRateLimiter(Clock.MONOTONIC),
            { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        )
        sync.start()
        return sync to settings
    }

    @Test
    fun brokerKilledDuringOnConnectWork_stateLeavesConnected_andReturnsAfterRestartAndNudge() = runBlocking {
        val made = kotlinx.coroutines.CompletableDeferred<KilledMidPublish>()
        val (sync, _) = startedSync { real -> KilledMidPublish(real).also { made.complete(it) } }
        val messenger = withTimeout(20_000) { made.await() }

        // Connected, then the on-connect capabilities publish kills the broker: the messenger knows at once.
        withTimeout(20_000) { messenger.state.first { it is ConnectionState.Connecting && it.lastFailure != null } }
        assertEquals(true, messenger.killed)
        withTimeout(5_000) { sync.connection.first { it is ConnectionState.Connecting && it.lastFailure != null } }

        // Back: a nudge ends the two-minute backoff, and the screens see Connected again.
        broker.start()
        messenger.reconnectNow()
        withTimeout(20_000) { sync.connection.first { it == ConnectionState.Connected } }
        assertEquals(ConnectionState.Connected, messenger.state.value)
    }

    /**
     * A fresh session (keep-alive unanswered, network changed, certificate changed) ends the previous client: left
     * running under the same client id, it would take the session back from the new one at its next reconnection.
     * Removing the account ends the last one, and the screens read Disconnected.
     */
    @Test
    fun restartSession_previousClientDisconnected_accountRemoved_connectionReadsDisconnected() = runBlocking {
        val made = java.util.concurrent.CopyOnWriteArrayList<MqttMessenger>()
        val (sync, settings) = startedSync { real -> real.also { made += it } }
        withTimeout(20_000) { sync.connection.first { it == ConnectionState.Connected } }

        sync.restartSession()
        withTimeout(20_000) { while (made.size < 2 || made[1].state.value != ConnectionState.Connected) kotlinx.coroutines.delay(20) }
        withTimeout(5_000) { made[0].state.first { it == ConnectionState.Disconnected } }
        assertEquals(mapOf("alice:${phoneDevice.value}" to true), broker.sessions())

        settings.update { it.copy(userName = null) }
        withTimeout(5_000) { sync.connection.first { it == ConnectionState.Disconnected } }
        withTimeout(5_000) { made[1].state.first { it == ConnectionState.Disconnected } }
        assertEquals(2, made.size)
    }
}
