package org.hapticon.app.sync

import android.app.Activity
import android.content.Context

/**
 * What the chat's entry points outside any screen (the notification actions, "Stay reachable", the boot
 * receiver) need from the application: the chat component, and the activity a notification opens. The
 * application implements it, so this package reads them without importing the root package that builds them
 * (docs/architecture.md, "Packages do not import each other in a cycle").
 */
interface ChatHost {
    /** The chat component; null in an app built without chat. */
    val chat: ChatComponent?

    /** The activity a tap on a chat notification opens. */
    val launchActivity: Class<out Activity>
}

/** The application as [ChatHost]; Android hands receivers and services the application's own context. */
internal val Context.chatHost: ChatHost get() = applicationContext as ChatHost
