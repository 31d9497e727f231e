package org.hapticon.app.sync

import android.content.Context
import android.net.ConnectivityManager
import android.net.Network

/**
 * Tells the chat sync when the phone's default network (the one apps' connections use) becomes
 * available, so a session waiting out its reconnection backoff tries at once and one made over a network
 * that is gone starts afresh ([ChatSync.networkAvailable]). Android's
 * `ConnectivityManager.registerDefaultNetworkCallback` (API 24) calls [ConnectivityManager.NetworkCallback.onAvailable]
 * once at registration for the current network and again whenever the default network changes; it needs
 * the normal permission `ACCESS_NETWORK_STATE`. Losing a network needs no action: the MQTT client notices
 * the dead connection itself and starts its backoff, which the next network's arrival cuts short.
 */
class NetworkWatcher(context: Context, private val sync: ChatSync) {
    private val connectivity = context.getSystemService(ConnectivityManager::class.java)

    private val callback = object : ConnectivityManager.NetworkCallback() {
        // Network.toString() is its netId, which differs between networks (wifi and mobile, or a new wifi).
        override fun onAvailable(network: Network) = sync.networkAvailable(network.toString())
    }

    @Volatile
    private var registered = false

    /** Starts listening (once); without a connectivity service (some test devices) there is nothing to hear. */
    @Synchronized
    fun start() {
        if (registered || connectivity == null) return
        try {
            connectivity.registerDefaultNetworkCallback(callback)
            registered = true
        } catch (e: RuntimeException) {
            // SecurityException without the permission, or too many callbacks: reconnection falls back to the backoff.
            android.util.Log.w("NetworkWatcher", "cannot watch the network: ${e.message}")
        }
    }

    @Synchronized
    fun stop() {
        if (!registered) return
        registered = false
        runCatching { connectivity?.unregisterNetworkCallback(callback) }
    }
}
