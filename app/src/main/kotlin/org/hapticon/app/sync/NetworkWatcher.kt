package org.hapticon.app.sync

import android.content.Context
import android.net.ConnectivityManager
import android.net.Network
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

/**
 * Tells the chat sync when the phone's default network (the one apps' connections use) becomes
 * available, so a session waiting out its reconnection backoff tries at once and one made over a network
 * that is gone starts afresh ([ChatSync.networkAvailable]). Android's
 * `ConnectivityManager.registerDefaultNetworkCallback` (API 24) calls [ConnectivityManager.NetworkCallback.onAvailable]
 * once at registration for the current network and again whenever the default network changes; it needs
 * the normal permission `ACCESS_NETWORK_STATE`. Losing a network needs no action from the sync: the MQTT client
 * notices the dead connection itself and starts its backoff, which the next network's arrival cuts short.
 *
 * [online] says whether there is a default network, for the chat screens' "Offline" line. A default-network
 * callback hears `onLost` only when the default network is gone with none to replace it (a switch from wifi to
 * mobile data is an `onAvailable` of the new one), and hears nothing at all when the phone is offline at
 * registration, so the first value is `ConnectivityManager.getActiveNetwork`'s.
 */
class NetworkWatcher(context: Context, private val sync: ChatSync) {
    private val connectivity = context.getSystemService(ConnectivityManager::class.java)

    private val current = MutableStateFlow<Boolean?>(null)

    /** True while the phone has a default network, false without one, null before [start] (or without the service). */
    val online: StateFlow<Boolean?> = current.asStateFlow()

    @Volatile
    private var defaultNetwork: Network? = null

    private val callback = object : ConnectivityManager.NetworkCallback() {
        override fun onAvailable(network: Network) {
            defaultNetwork = network
            current.value = true
            // Network.toString() is its netId, which differs between networks (wifi and mobile, or a new wifi).
            sync.networkAvailable(network.toString())
        }

        override fun onLost(network: Network) {
            // Only the default network's loss: a late onLost of the one it replaced changes nothing.
            if (network == defaultNetwork) {
                defaultNetwork = null
                current.value = false
            }
        }
    }

    @Volatile
    private var registered = false

    /** Starts listening (once); without a connectivity service (some test devices) there is nothing to hear. */
    @Synchronized
    fun start() {
        if (registered || connectivity == null) return
        try {
            if (current.value == null) current.value = connectivity.activeNetwork != null
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
