package org.hapticon.app

import android.app.Activity
import android.app.Application
import android.content.pm.ApplicationInfo
import android.os.StrictMode
import org.hapticon.app.di.AppContainer
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.sync.ChatHost

/**
 * Holds the app's long-lived objects; tests replace them through [container]. As the [ChatHost] it hands the
 * chat's notification actions and services the chat component and the activity to open, so they need not
 * import this package.
 */
class HapticonApplication : Application(), ChatHost {
    lateinit var container: AppContainer

    override val chat: ChatComponent? get() = container.chat
    override val launchActivity: Class<out Activity> get() = MainActivity::class.java

    override fun onCreate() {
        super.onCreate()
        // Debug builds log disk, network and rendering work on the main thread (a phone's logcat shows each).
        if (applicationInfo.flags and ApplicationInfo.FLAG_DEBUGGABLE != 0) {
            StrictMode.setThreadPolicy(mainThreadPolicy().penaltyLog().build())
        }
        container = AppContainer.create(this)
        // The chat sync runs in the application's scope from start-up: it drains the outbox and receives.
        // "Stay reachable" is started by the activity, the boot receiver and the keep-alive alarm, not here: a
        // process started for BOOT_COMPLETED must follow the user's "after a restart" choice.
        container.chat?.sync?.start()
    }
}
