package org.hapticon.app.sync

import android.content.Context
import org.hapticon.app.playback.usageVibrator
import android.net.ConnectivityManager
import android.os.Vibrator
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.shadows.ShadowNetwork

/**
 * Network changes reach the chat session through Android's default-network callback: the watcher
 * registers with the (shadow) ConnectivityManager, and the tests call the registered callback as Android
 * does when wifi or mobile data comes back. The real client's nudge against the embedded broker is
 * MqttMessengerTest.reconnectNow_brokerBackDuringALongBackoff_connectsAtOnceNotAfterTheBackoff.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class NetworkWatcherTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val connectivity = context.getSystemService(ConnectivityManager::class.java)
    private val vibrator = context.getSystemService(Vibrator::class.java)
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).allowMainThreadQueries().build()
    private val repository = OfflineFirstChatRepository(db)

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    private fun sync(brokerUrl: String, password: String?, factory: (String, String, String?) -> Messenger?) = ChatSync(
        repository, repository, InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = brokerUrl, brokerPassword = password)),
        factory, AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null }), VibrationRateLimiter(Clock.MONOTONIC),
        { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
    )

    /** What Android does when [netId] becomes the default network: every registered callback hears it. */
    private fun networkAvailable(netId: Int) {
        val network = ShadowNetwork.newInstance(netId)
        shadowOf(connectivity).networkCallbacks.forEach { it.onAvailable(network) }
    }

    private fun <T> awaitValue(timeoutMillis: Long, read: () -> T, until: (T) -> Boolean): T = runBlocking {
        kotlinx.coroutines.withTimeoutOrNull(timeoutMillis) {
            while (!until(read())) delay(10)
            read()
        } ?: throw AssertionError("still ${read()} after $timeoutMillis ms")
    }

    @Test
    fun start_registersOneDefaultNetworkCallback_stopRemovesIt() {
        // The application's own watcher (its chat component) is registered already.
        val before = shadowOf(connectivity).networkCallbacks.size
        val watcher = NetworkWatcher(context, sync("tcp://127.0.0.1:1", null) { _, _, _ -> null })
        watcher.start()
        watcher.start()
        assertEquals(before + 1, shadowOf(connectivity).networkCallbacks.size)
        watcher.stop()
        assertEquals(before, shadowOf(connectivity).networkCallbacks.size)
    }

    @Test
    fun networkAvailable_whileWaitingToReconnect_nudgesTheMessengerOnly() {
        val made = CopyOnWriteArrayList<TestMessenger>()
        val sync = sync("tcp://127.0.0.1:1883", null) { user, _, _ -> TestMessenger(user).also { made += it } }
        NetworkWatcher(context, sync).start()
        networkAvailable(100) // Android reports the current network at registration
        sync.start()
        awaitValue(5_000, { sync.connection.value }) { it == ConnectionState.Connected }
        made.single().setConnection(ConnectionState.Connecting(lastFailure = "connection lost"))

        networkAvailable(100)

        assertEquals(1, made.single().nudges)
        assertEquals(1, made.size)
    }

    @Test
    fun networkAvailable_anotherNetworkWhileConnected_startsAFreshSession() {
        val made = CopyOnWriteArrayList<TestMessenger>()
        val sync = sync("tcp://127.0.0.1:1883", null) { user, _, _ -> TestMessenger(user).also { made += it } }
        NetworkWatcher(context, sync).start()
        networkAvailable(100) // wifi, reported at registration
        sync.start()
        awaitValue(5_000, { sync.connection.value }) { it == ConnectionState.Connected }
        networkAvailable(100) // the same network again: the connection stands
        assertEquals(1, made.size)

        networkAvailable(101) // mobile data: the wifi socket is gone with the wifi

        awaitValue(5_000, { made.size }) { it == 2 }
        awaitValue(5_000, { made[0].state.value }) { it == ConnectionState.Disconnected }
        awaitValue(5_000, { sync.connection.value }) { it == ConnectionState.Connected }
        assertEquals(0, made[0].nudges)
    }

    /** What Android does when [netId], the default network, is gone with none to replace it. */
    private fun networkLost(netId: Int) {
        val network = ShadowNetwork.newInstance(netId)
        shadowOf(connectivity).networkCallbacks.forEach { it.onLost(network) }
    }

    /** The chat screens' "Offline" line follows [NetworkWatcher.online]: the default network, and only its loss. */
    @Test
    fun online_followsTheDefaultNetwork_offlineOnlyWhenItGoesWithNoneToReplaceIt() {
        val watcher = NetworkWatcher(context, sync("tcp://127.0.0.1:1", null) { _, _, _ -> null })
        assertEquals(null, watcher.online.value)
        watcher.start()
        assertEquals(true, watcher.online.value) // Robolectric's phone has an active network
        networkAvailable(100)
        networkLost(99) // a network that is not the default one
        assertEquals(true, watcher.online.value)
        networkLost(100)
        assertEquals(false, watcher.online.value)
        networkAvailable(101)
        assertEquals(true, watcher.online.value)
    }

    @Test
    fun online_phoneOfflineWhenTheWatcherStarts_isFalseAtOnce() {
        // No default network: Android then calls no callback at registration at all.
        shadowOf(connectivity).setActiveNetworkInfo(null)
        val watcher = NetworkWatcher(context, sync("tcp://127.0.0.1:1", null) { _, _, _ -> null })
        watcher.start()
        assertEquals(false, watcher.online.value)
    }
}
