package org.hapticon.app.sync

import android.app.AlarmManager
import android.app.Application
import android.app.Notification
import android.app.NotificationManager
import android.content.Context
import android.content.Intent
import android.os.Looper
import android.os.PowerManager
import android.os.SystemClock
import android.os.Vibrator
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.HapticonApplication
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.Robolectric
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.shadows.ShadowAlarmManager

/**
 * "Stay reachable" through Android's own paths: the boot broadcast delivered by the framework to the manifest's
 * receiver starts the service, which posts its ongoing notification and schedules the keep-alive alarm; the
 * alarm, fired, reaches the manifest's keep-alive receiver, which schedules the next one; what Doze allows
 * decides the kind of alarm; and the sync's keep-alive pings, reconnects or starts afresh.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class KeepAliveTest {
    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val alarms get() = shadowOf(app.getSystemService(AlarmManager::class.java))
    private val power get() = shadowOf(app.getSystemService(PowerManager::class.java))

    @Before
    fun setUp() {
        ShadowAlarmManager.setCanScheduleExactAlarms(false)
        shadowOf(app).clearStartedServices()
    }

    @After
    fun tearDown() {
        app.container.chat!!.settings.update { ChatPreferences() }
    }

    private fun stayReachable(afterBoot: Boolean) =
        app.container.chat!!.settings.update { it.copy(stayReachable = true, reachableAfterBoot = afterBoot) }

    @Test
    fun manifest_registersTheBootAndKeepAliveReceivers() {
        val boot = app.packageManager.queryBroadcastReceivers(Intent(Intent.ACTION_BOOT_COMPLETED).setPackage(app.packageName), 0)
        assertEquals(listOf(BootReceiver::class.java.name), boot.map { it.activityInfo.name })
        val update = app.packageManager.queryBroadcastReceivers(Intent(Intent.ACTION_MY_PACKAGE_REPLACED).setPackage(app.packageName), 0)
        assertEquals(listOf(BootReceiver::class.java.name), update.map { it.activityInfo.name })
        val keepAlive = app.packageManager.getReceiverInfo(android.content.ComponentName(app, KeepAliveReceiver::class.java), 0)
        assertFalse(keepAlive.exported)
    }

    @Test
    fun bootCompleted_broadcast_startsTheServiceWhichPostsItsNotificationAndSchedulesTheKeepAlive() {
        stayReachable(afterBoot = true)
        power.setIgnoringBatteryOptimizations(app.packageName, true)

        // As Android does after a restart: the broadcast goes to whatever the manifest registered for it.
        app.sendBroadcast(Intent(Intent.ACTION_BOOT_COMPLETED))
        shadowOf(Looper.getMainLooper()).idle()

        val started = shadowOf(app).nextStartedService
        assertEquals(ReachableService::class.java.name, started?.component?.className)
        // The service Android would now create from that very intent.
        val controller = Robolectric.buildService(ReachableService::class.java, started).create().startCommand(0, 1)
        val service = shadowOf(controller.get())
        val notification = service.lastForegroundNotification
        assertEquals(ReachableService.ONGOING_ID, service.lastForegroundNotificationId)
        assertEquals(ReachableService.CHANNEL, notification.channelId)
        assertEquals("Reachable for haptic messages", notification.extras.getString(Notification.EXTRA_TITLE))
        assertTrue((notification.flags and Notification.FLAG_ONGOING_EVENT) != 0)
        assertNotNull(shadowOf(app.getSystemService(NotificationManager::class.java)).getNotification(ReachableService.ONGOING_ID))
        assertTrue(ReachableService.running)

        // Exempt from battery optimisation: an exact while-idle wake-up a minute from now.
        val alarm = alarms.peekNextScheduledAlarm()!!
        assertEquals(AlarmManager.ELAPSED_REALTIME_WAKEUP, alarm.type)
        assertTrue(alarm.isAllowWhileIdle)
        assertEquals(ShadowAlarmManager.WINDOW_EXACT, alarm.windowLengthMs)
        assertEquals(SystemClock.elapsedRealtime() + KeepAlive.INTERVAL_MILLIS, alarm.triggerAtTime)

        controller.destroy()
        assertFalse(ReachableService.running)
        assertNull("the keep-alive ends with the service", alarms.peekNextScheduledAlarm())
    }

    @Test
    fun bootCompleted_withoutRestartsChosen_startsNothing() {
        stayReachable(afterBoot = false)
        app.sendBroadcast(Intent(Intent.ACTION_BOOT_COMPLETED))
        shadowOf(Looper.getMainLooper()).idle()
        assertNull(shadowOf(app).nextStartedService)
    }

    @Test
    fun appUpdated_broadcast_startsTheServiceAgainWhenStayReachableIsOn() {
        stayReachable(afterBoot = false)
        app.sendBroadcast(Intent(Intent.ACTION_MY_PACKAGE_REPLACED).setPackage(app.packageName))
        shadowOf(Looper.getMainLooper()).idle()
        assertEquals(ReachableService::class.java.name, shadowOf(app).nextStartedService?.component?.className)
    }

    @Test
    fun mode_followsWhatDozeAllows() {
        assertEquals(KeepAlive.Mode.INEXACT, KeepAlive.mode(app))
        ShadowAlarmManager.setCanScheduleExactAlarms(true)
        assertEquals(KeepAlive.Mode.EXACT, KeepAlive.mode(app))
        power.setIgnoringBatteryOptimizations(app.packageName, true)
        assertEquals(KeepAlive.Mode.UNRESTRICTED, KeepAlive.mode(app))
    }

    @Test
    fun batteryOptimised_withoutExactAlarms_schedulesAnInexactWhileIdleAlarm() {
        KeepAlive.schedule(app, nowElapsed = 1_000)
        val alarm = alarms.peekNextScheduledAlarm()!!
        assertEquals(AlarmManager.ELAPSED_REALTIME_WAKEUP, alarm.type)
        assertTrue(alarm.isAllowWhileIdle)
        assertEquals(ShadowAlarmManager.WINDOW_HEURISTIC, alarm.windowLengthMs)
        assertEquals(1_000 + KeepAlive.INTERVAL_MILLIS, alarm.triggerAtTime)
    }

    @Test
    fun interval_keepsTheBrokerHearingFromThePhone() {
        // The broker closes a connection silent for 1.5 × its keep-alive (MQTT 3.1.1 §3.1.2.10).
        assertTrue(KeepAlive.INTERVAL_MILLIS < 1_500L * KeepAlive.MQTT_KEEP_ALIVE_SECONDS)
        assertEquals(
            KeepAlive.MQTT_KEEP_ALIVE_SECONDS,
            ChatComponent.mqttSettings("alice", "tcp://192.168.1.20:1883", "alice-secret", org.hapticon.messaging.mqtt.DeviceId.generate(), null).keepAliveSeconds,
        )
        assertTrue(KeepAlive.ROUND_TRIP_TIMEOUT_MILLIS < KeepAlive.INTERVAL_MILLIS)
    }

    @Test
    fun firedAlarm_reachesTheReceiverWhichSchedulesTheNext() {
        stayReachable(afterBoot = true)
        power.setIgnoringBatteryOptimizations(app.packageName, true)
        KeepAlive.schedule(app, nowElapsed = 0)
        val first = alarms.peekNextScheduledAlarm()!!

        // AlarmManager sends the PendingIntent's broadcast; Android delivers it to the manifest's receiver.
        alarms.fireAlarm(first)
        shadowOf(Looper.getMainLooper()).idle()

        val next = alarms.peekNextScheduledAlarm()
        assertNotNull("the receiver scheduled the next keep-alive", next)
        assertEquals(SystemClock.elapsedRealtime() + KeepAlive.INTERVAL_MILLIS, next!!.triggerAtTime)
        // The service was not running (no activity, no boot here): the alarm starts it again.
        assertEquals(ReachableService::class.java.name, shadowOf(app).nextStartedService?.component?.className)
    }

    @Test
    fun firedAlarm_afterStayReachableWentOff_endsTheChain() {
        KeepAlive.schedule(app, nowElapsed = 0)
        alarms.fireAlarm(alarms.peekNextScheduledAlarm()!!)
        shadowOf(Looper.getMainLooper()).idle()
        assertNull(alarms.peekNextScheduledAlarm())
        assertNull(shadowOf(app).nextStartedService)
    }
}

/** [ChatSync.keepAlive] on a messenger in memory. */
@RunWith(RobolectricTestRunner::class)
class ChatSyncKeepAliveTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
    private val repository = OfflineFirstChatRepository(db)
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val made = mutableListOf<TestMessenger>()
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val sync = ChatSync(
        repository, repository, InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883")),
        { user, _, _ -> TestMessenger(user).also { synchronized(made) { made += it } } },
        AdaptiveHapticPlayer(context.getSystemService(Vibrator::class.java), { device }, { null }), VibrationRateLimiter(Clock.MONOTONIC),
        { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        retryPolicy = RetryPolicy(initialDelayMillis = 10, maxDelayMillis = 10, jitter = 0.0),
    )

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    private fun connected(): TestMessenger = runBlocking {
        withTimeout(5_000) {
            sync.connection.first { it == ConnectionState.Connected }
            synchronized(made) { made.last() }
        }
    }

    @Test
    fun connected_oneRoundTrip_sessionKept() = runBlocking {
        sync.start()
        val messenger = connected()
        assertTrue(sync.keepAlive())
        assertEquals(1, messenger.pings)
        assertEquals(1, synchronized(made) { made.size })
    }

    @Test
    fun connectionDeadUnnoticed_noAnswer_freshSession() = runBlocking {
        sync.start()
        val first = connected()
        first.answersPing = false
        assertFalse(sync.keepAlive())
        withTimeout(5_000) { while (synchronized(made) { made.size } < 2) delay(10) }
        val second = connected()
        assertTrue(second !== first)
        assertTrue(sync.keepAlive())
    }

    @Test
    fun waitingToReconnect_reconnectsNow() = runBlocking {
        sync.start()
        val messenger = connected()
        messenger.setConnection(ConnectionState.Connecting("connection lost"))
        assertFalse(sync.keepAlive())
        assertEquals(1, messenger.nudges)
        assertEquals(0, messenger.pings)
    }
}
