package org.hapticon.app.sync

import android.app.NotificationChannel
import android.app.NotificationManager
import android.app.PendingIntent
import android.app.Service
import android.content.BroadcastReceiver
import android.content.Context
import android.content.Intent
import android.content.pm.ServiceInfo
import android.os.Build
import android.os.IBinder
import androidx.core.app.NotificationCompat
import androidx.core.app.NotificationManagerCompat
import androidx.core.app.ServiceCompat
import androidx.core.content.ContextCompat
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancel
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.launch
import org.hapticon.app.R
import org.hapticon.messaging.ConnectionState

/**
 * "Stay reachable": a foreground service that keeps the app's process, and with it the chat sync's
 * MQTT session, alive while no screen is open, as ntfy and Conversations do for self-hosted messaging
 * without a vendor push service. The sync itself (started by the application) owns the connection and
 * reconnects with backoff ([org.hapticon.messaging.mqtt.MqttSettings.reconnectPolicy]); this service
 * only keeps it running and shows its ongoing notification: which broker, and whether it is connected.
 *
 * Type `remoteMessaging` (Android 14+): `dataSync` would be stopped after 6 hours a day on Android 15
 * and may not be started from BOOT_COMPLETED there; `remoteMessaging` has neither limit.
 * START_STICKY: if Android kills the process, it restarts the service, and the application restarts
 * the sync. While it runs, the keep-alive alarm ([KeepAlive]) wakes the phone once a minute so that the
 * broker keeps hearing from it in Doze.
 *
 * Started by the user (Settings, the first-launch offer, the chat list's note), by the activity when the app
 * opens with it chosen, after a restart or an app update ([BootReceiver], when the user chose restarts too),
 * and by the keep-alive alarm should Android have stopped it. Android 12+ forbids starting a foreground service
 * from the background except in listed cases; BOOT_COMPLETED and MY_PACKAGE_REPLACED are among them, and so are
 * an exact alarm's broadcast and an app exempt from battery optimisation.
 */
class ReachableService : Service() {
    private var scope: CoroutineScope? = null

    override fun onBind(intent: Intent?): IBinder? = null

    override fun onCreate() {
        super.onCreate()
        running = true
        ensureChannel(this)
        val chat = chatHost.chat
        startInForeground(notification(this, chat?.settings?.preferences?.value?.brokerUrl.orEmpty(), ConnectionState.Disconnected))
        if (chat == null) return
        chat.sync.start()
        KeepAlive.schedule(this)
        scope = CoroutineScope(SupervisorJob() + Dispatchers.Main.immediate).also { scope ->
            scope.launch {
                combine(chat.sync.connection, chat.settings.preferences) { state, prefs -> prefs.brokerUrl to state }
                    .collect { (broker, state) -> update(notification(this@ReachableService, broker, state)) }
            }
        }
    }

    override fun onStartCommand(intent: Intent?, flags: Int, startId: Int): Int = START_STICKY

    override fun onDestroy() {
        running = false
        KeepAlive.cancel(this)
        scope?.cancel()
        scope = null
        super.onDestroy()
    }

    private fun startInForeground(notification: android.app.Notification) {
        val type = if (Build.VERSION.SDK_INT >= 34) ServiceInfo.FOREGROUND_SERVICE_TYPE_REMOTE_MESSAGING else 0
        ServiceCompat.startForeground(this, ONGOING_ID, notification, type)
    }

    @Suppress("MissingPermission") // Without the permission Android drops the update; the service runs on.
    private fun update(notification: android.app.Notification) {
        NotificationManagerCompat.from(this).notify(ONGOING_ID, notification)
    }

    companion object {
        const val ONGOING_ID: Int = 2
        const val CHANNEL: String = "reachable"

        /** True between the service's onCreate and onDestroy in this process. */
        @Volatile
        var running: Boolean = false
            private set

        fun start(context: Context) {
            ContextCompat.startForegroundService(context, Intent(context, ReachableService::class.java))
        }

        /**
         * Starts the service when the user chose "Stay reachable" and it is not running; false when Android
         * refused (a background start it does not allow now), logged.
         */
        fun startIfChosen(context: Context): Boolean {
            val chosen = context.chatHost.chat?.settings?.preferences?.value?.stayReachable == true
            if (!chosen || running) return chosen
            return runCatching { start(context) }
                .onFailure { android.util.Log.w("ReachableService", "cannot start Stay reachable now: ${it.message}") }
                .isSuccess
        }

        fun stop(context: Context) {
            context.stopService(Intent(context, ReachableService::class.java))
        }

        /** The ongoing notification's text for [state] on [broker]. */
        fun statusText(broker: String, state: ConnectionState): String = when (state) {
            ConnectionState.Connected -> "Connected to $broker"
            is ConnectionState.Connecting -> "Connecting to $broker…" + (state.lastFailure?.let { " ($it)" } ?: "")
            ConnectionState.Disconnected -> "Not connected to ${broker.ifEmpty { "a broker" }}"
            is ConnectionState.Failed -> "Refused by $broker: ${state.reason}"
        }

        private fun ensureChannel(context: Context) {
            if (Build.VERSION.SDK_INT < 26) return
            val manager = context.getSystemService(NotificationManager::class.java)
            if (manager.getNotificationChannel(CHANNEL) != null) return
            // Low importance: always there, never makes a sound.
            manager.createNotificationChannel(NotificationChannel(CHANNEL, "Stay reachable", NotificationManager.IMPORTANCE_LOW))
        }

        private fun notification(context: Context, broker: String, state: ConnectionState): android.app.Notification {
            val open = PendingIntent.getActivity(
                context, 0, Intent(context, context.chatHost.launchActivity), PendingIntent.FLAG_IMMUTABLE,
            )
            return NotificationCompat.Builder(context, CHANNEL)
                .setSmallIcon(R.drawable.ic_notification)
                .setContentTitle("Reachable for haptic messages")
                .setContentText(statusText(broker, state))
                .setOngoing(true)
                .setOnlyAlertOnce(true)
                .setCategory(NotificationCompat.CATEGORY_SERVICE)
                .setContentIntent(open)
                .build()
        }
    }
}

/**
 * Starts "Stay reachable" again after the phone restarts, when the user chose restarts too, and after an update
 * of the app (which stops its services), when Stay reachable was on.
 */
class BootReceiver : BroadcastReceiver() {
    override fun onReceive(context: Context, intent: Intent) {
        val prefs = context.chatHost.chat?.settings?.preferences?.value ?: return
        val start = when (intent.action) {
            Intent.ACTION_BOOT_COMPLETED -> prefs.stayReachable && prefs.reachableAfterBoot
            Intent.ACTION_MY_PACKAGE_REPLACED -> prefs.stayReachable
            else -> false
        }
        if (start) ReachableService.startIfChosen(context)
    }
}
