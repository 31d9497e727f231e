package org.hapticon.app.sync

import android.app.AlarmManager
import android.app.PendingIntent
import android.content.BroadcastReceiver
import android.content.Context
import android.content.Intent
import android.net.Uri
import android.os.Build
import android.os.PowerManager
import android.os.SystemClock
import android.provider.Settings
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull

/**
 * Keeps the "Stay reachable" broker connection alive while the phone sleeps.
 *
 * With the screen off the CPU suspends, and the MQTT client's own keep-alive timer (HiveMQ's, on
 * `System.nanoTime`, CLOCK_MONOTONIC) does not count suspended time: it sends no PINGREQ, and the broker
 * closes the connection after 1.5 × the keep-alive without a packet (MQTT 3.1.1 §3.1.2.10). The foreground
 * service keeps the network in Doze (NetworkPolicyManagerService lets processes at foreground-service state
 * or better through its idle firewall) and its wake locks honoured, but it does not wake the CPU. An
 * `ELAPSED_REALTIME_WAKEUP` alarm does: every [INTERVAL_MILLIS] it wakes the phone, and [KeepAliveReceiver]
 * sends one round trip to the broker ([ChatSync.keepAlive]) while AlarmManager's wake lock holds the CPU
 * up (it lasts until the broadcast, `goAsync` included, is finished). Signal does the same for its websocket
 * without Google's push (`AlarmSleepTimer`: `setExactAndAllowWhileIdle`, every 60 s in the background).
 *
 * What Doze lets through depends on [mode] (AlarmManagerService, `IAlarmManager.set`; the power-details
 * table of developer.android.com/topic/performance/power/power-details):
 * - the user exempted Hapticon from battery optimisation: every alarm of an app on that allowlist gets
 *   FLAG_ALLOW_WHILE_IDLE_UNRESTRICTED ("go off as normal even while idle, with no timing restrictions"), and
 *   exact alarms need no SCHEDULE_EXACT_ALARM (`isExemptFromExactAlarmPermissionNoLock`);
 * - exact alarms allowed otherwise (Android 8–11, or the user granted "Alarms & reminders"): exact
 *   while-idle alarms, at most 72 an hour in Doze (one a minute fits);
 * - neither: inexact while-idle alarms, at most one per 9 minutes in Doze; the broker drops the connection
 *   in between and queues what arrives (persistent session), delivered at the next wake. The chat list says
 *   so ([org.hapticon.app.feature.chat.ReachableNote.BATTERY_OPTIMISED]) and offers the exemption.
 */
object KeepAlive {
    /**
     * The MQTT keep-alive of the app's session: the broker waits 1.5 × this (90 s) for a packet. Twice the
     * library's 30 s, so that one alarm a minute (Signal's background cadence) keeps the session.
     */
    const val MQTT_KEEP_ALIVE_SECONDS: Int = 60

    /** Time between keep-alive alarms: under the broker's 90 s with room for a late alarm. */
    const val INTERVAL_MILLIS: Long = 60_000

    /** How long a keep-alive round trip may take before the connection counts as dead (Signal waits 20 s). */
    const val ROUND_TRIP_TIMEOUT_MILLIS: Long = 20_000

    const val ACTION: String = "org.hapticon.app.action.KEEP_ALIVE"

    /** What Android lets the keep-alive alarm do in Doze. */
    enum class Mode {
        /** On the user's battery-optimisation allowlist: exact alarms, no limit in Doze. */
        UNRESTRICTED,

        /** Exact while-idle alarms, at most 72 an hour in Doze. */
        EXACT,

        /** Inexact while-idle alarms, at most one per 9 minutes in Doze. */
        INEXACT,
    }

    fun mode(context: Context): Mode = when {
        isBatteryExempt(context) -> Mode.UNRESTRICTED
        Build.VERSION.SDK_INT < 31 || context.getSystemService(AlarmManager::class.java).canScheduleExactAlarms() -> Mode.EXACT
        else -> Mode.INEXACT
    }

    /** Schedules the next keep-alive [INTERVAL_MILLIS] from now, replacing a scheduled one. */
    fun schedule(context: Context, nowElapsed: Long = SystemClock.elapsedRealtime()) {
        val alarms = context.getSystemService(AlarmManager::class.java) ?: return
        val at = nowElapsed + INTERVAL_MILLIS
        when (mode(context)) {
            Mode.UNRESTRICTED, Mode.EXACT -> alarms.setExactAndAllowWhileIdle(AlarmManager.ELAPSED_REALTIME_WAKEUP, at, pendingIntent(context))
            Mode.INEXACT -> alarms.setAndAllowWhileIdle(AlarmManager.ELAPSED_REALTIME_WAKEUP, at, pendingIntent(context))
        }
    }

    fun cancel(context: Context) {
        context.getSystemService(AlarmManager::class.java)?.cancel(pendingIntent(context))
    }

    private fun pendingIntent(context: Context): PendingIntent = PendingIntent.getBroadcast(
        context, 0, Intent(context, KeepAliveReceiver::class.java).setAction(ACTION),
        PendingIntent.FLAG_IMMUTABLE or PendingIntent.FLAG_UPDATE_CURRENT,
    )

    /** True when the user exempted Hapticon from battery optimisation (Android's "Unrestricted" battery use). */
    fun isBatteryExempt(context: Context): Boolean =
        context.getSystemService(PowerManager::class.java)?.isIgnoringBatteryOptimizations(context.packageName) ?: false

    /**
     * Android's dialog that asks the user to exempt Hapticon from battery optimisation
     * (`ACTION_REQUEST_IGNORE_BATTERY_OPTIMIZATIONS`, which needs the normal permission
     * REQUEST_IGNORE_BATTERY_OPTIMIZATIONS), then, for a phone without that dialog, its list of apps. Started in
     * this order until one opens (a launch throws ActivityNotFoundException otherwise; asking the package manager
     * first would need a `<queries>` entry on Android 11+). The action's own documentation reserves it for apps
     * that must control their own execution; the "Optimize for Doze and App Standby" guide's acceptable cases
     * include instant messaging that cannot use Firebase Cloud Messaging, which is Hapticon's case (its own
     * broker, no Google services).
     */
    fun exemptionRequests(context: Context): List<Intent> = listOf(
        Intent(Settings.ACTION_REQUEST_IGNORE_BATTERY_OPTIMIZATIONS, Uri.parse("package:${context.packageName}")),
        Intent(Settings.ACTION_IGNORE_BATTERY_OPTIMIZATION_SETTINGS),
    )
}

/**
 * The keep-alive alarm: one round trip to the broker (or a reconnection now, where the client waits out a
 * backoff that the sleeping CPU stretched), then the next alarm. Only while "Stay reachable" is on; the
 * service cancels the alarm when it stops. Not exported: only Android's AlarmManager sends it, through the
 * app's own PendingIntent.
 */
class KeepAliveReceiver : BroadcastReceiver() {
    override fun onReceive(context: Context, intent: Intent) {
        if (intent.action != KeepAlive.ACTION) return
        val chat = context.chatHost.chat ?: return
        if (!chat.settings.preferences.value.stayReachable) return
        // The next alarm first: a round trip that hangs must not end the chain. Android may have stopped the
        // service meanwhile (it runs on; this alarm lets it start again).
        KeepAlive.schedule(context)
        ReachableService.startIfChosen(context)
        val pending = goAsync()
        SCOPE.launch {
            try {
                withTimeoutOrNull(KeepAlive.ROUND_TRIP_TIMEOUT_MILLIS) { chat.sync.keepAlive() }
            } finally {
                pending.finish()
            }
        }
    }

    private companion object {
        val SCOPE = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    }
}
