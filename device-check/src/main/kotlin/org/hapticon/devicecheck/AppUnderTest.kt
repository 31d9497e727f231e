package org.hapticon.devicecheck

import android.app.NotificationManager
import android.content.Context
import android.os.Build
import android.os.SystemClock
import androidx.test.uiautomator.UiDevice
import java.time.LocalDateTime
import org.hapticon.devicecheck.dumpsys.NotificationDump
import org.hapticon.devicecheck.dumpsys.PostedNotification
import org.hapticon.devicecheck.dumpsys.VibratorDump

/**
 * The debug app, driven from outside as a person (and Android) would: started, sent home and killed, the screen
 * switched off, Do Not Disturb switched on; and read through Android's own dumps. The suite runs in its own uid, so
 * none of this makes the app's uid foreground (docs/device-check.md, "Why a test APK of its own").
 */
class AppUnderTest(private val shell: Shell, private val device: UiDevice, private val context: Context) {
    /** The app's uid, which its vibrations and its process state are listed under. */
    val uid: Int get() = context.packageManager.getPackageUid(PACKAGE, 0)

    /**
     * A fresh start as [args.user]: the app stopped, its settings replaced by the account and the two switches a first
     * launch offers, notifications allowed. The settings are written where the app keeps them (SharedPreferences
     * `chat` and `chat_credentials`, through `run-as`, which a debuggable app allows); the password goes in clear, which
     * the app encrypts into Android Keystore on its first read (SharedPreferencesChatSettings), so the check does not
     * depend on the first-launch screen.
     */
    fun prepare(args: DeviceCheckArguments, stayReachable: Boolean, autoPlay: Boolean) {
        shell.run("am force-stop $PACKAGE")
        check(shell.run("run-as $PACKAGE mkdir -p shared_prefs").isBlank()) { "run-as $PACKAGE failed: is the debug APK installed?" }
        writePreferences(
            "chat",
            strings = mapOf("user" to args.user, "broker" to args.broker),
            booleans = mapOf("auto_play" to autoPlay, "stay_reachable" to stayReachable, "felt_receipts" to true, "reachable_offer_pending" to false),
        )
        writePreferences("chat_credentials", strings = mapOf("broker_password" to args.password), booleans = emptyMap())
        if (Build.VERSION.SDK_INT >= 33) shell.run("pm grant $PACKAGE android.permission.POST_NOTIFICATIONS")
    }

    private fun writePreferences(name: String, strings: Map<String, String>, booleans: Map<String, Boolean>) {
        val xml = buildString {
            append("<?xml version='1.0' encoding='utf-8' standalone='yes' ?>\n<map>\n")
            for ((key, value) in strings) append("    <string name=\"$key\">${escape(value)}</string>\n")
            for ((key, value) in booleans) append("    <boolean name=\"$key\" value=\"$value\" />\n")
            append("</map>\n")
        }
        shell.run("run-as $PACKAGE sh -c cat>shared_prefs/$name.xml", xml)
        val written = shell.run("run-as $PACKAGE cat shared_prefs/$name.xml")
        check(written == xml) { "writing the app's $name settings through run-as failed: read back ${written.take(200)}" }
    }

    /** Opens the app on its launcher screen and waits until it is drawn. */
    fun launch() {
        shell.run("am start -W -n $PACKAGE/.MainActivity")
        device.waitForIdle()
    }

    /** Opens the conversation with [peer], as its notification does. */
    fun openConversation(peer: String) {
        shell.run("am start -W -n $PACKAGE/.MainActivity -a $PACKAGE.OPEN_CHAT --es peer $peer")
        device.waitForIdle()
    }

    /**
     * What swiping the app away does to it: HOME, then `am kill`, which ends the app's process unless something keeps
     * it above the cached states (the "Stay reachable" foreground service does; ActivityManagerService
     * killBackgroundProcesses ends only background processes).
     */
    fun swipeAway() {
        device.pressHome()
        device.waitForIdle()
        shell.run("am kill $PACKAGE")
    }

    fun screenOff() {
        shell.run("input keyevent KEYCODE_SLEEP")
        waitFor(5_000) { !device.isScreenOn }
    }

    fun screenOn() {
        shell.run("input keyevent KEYCODE_WAKEUP")
        waitFor(5_000) { device.isScreenOn }
    }

    /**
     * Do Not Disturb on (total silence, `cmd notification set_dnd on`) or off. Shell may set it once it has policy
     * access; the first attempt that does not take grants that (`allow_dnd com.android.shell`) and tries again.
     */
    fun doNotDisturb(on: Boolean) {
        val manager = context.getSystemService(NotificationManager::class.java)
        val wanted = if (on) NotificationManager.INTERRUPTION_FILTER_NONE else NotificationManager.INTERRUPTION_FILTER_ALL
        shell.run("cmd notification set_dnd ${if (on) "on" else "off"}")
        if (!waitFor(3_000) { manager.currentInterruptionFilter == wanted }) {
            shell.run("cmd notification allow_dnd com.android.shell")
            shell.run("cmd notification set_dnd ${if (on) "on" else "off"}")
        }
        check(waitFor(5_000) { manager.currentInterruptionFilter == wanted }) {
            "Do Not Disturb is still ${manager.currentInterruptionFilter} (wanted $wanted): cmd notification set_dnd did not take"
        }
    }

    /** `dumpsys vibrator_manager`, read in this year (the dump writes no year). */
    fun vibrator(): VibratorDump = VibratorDump.parse(shell.run("dumpsys vibrator_manager"), LocalDateTime.now().year)

    /** The app's notifications now (`dumpsys notification --noredact`: message text unredacted). */
    fun notifications(): List<PostedNotification> =
        NotificationDump.parse(shell.run("dumpsys notification --noredact")).filter { it.packageName == PACKAGE }

    companion object {
        const val PACKAGE: String = "org.hapticon.app"

        private fun escape(text: String): String =
            text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")

        /** Polls [condition] every 100 ms until it holds or [millis] pass; whether it held. */
        fun waitFor(millis: Long, condition: () -> Boolean): Boolean {
            val end = SystemClock.uptimeMillis() + millis
            while (true) {
                if (condition()) return true
                if (SystemClock.uptimeMillis() >= end) return false
                SystemClock.sleep(100)
            }
        }
    }
}
