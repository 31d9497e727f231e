package org.hapticon.sensor.usb

import android.app.PendingIntent
import android.content.BroadcastReceiver
import android.content.Context
import android.content.Intent
import android.content.IntentFilter
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import android.os.Build
import androidx.core.content.ContextCompat
import androidx.core.content.IntentCompat
import kotlinx.coroutines.suspendCancellableCoroutine
import java.io.Closeable
import java.util.concurrent.atomic.AtomicBoolean
import kotlin.coroutines.resume

/**
 * Asks the user for access to a USB device (the system dialog), and delivers the answer once.
 *
 * The answer comes back as a broadcast of our own [PendingIntent], received by a receiver that is
 * registered for the one request and not exported, so other apps can neither see nor fake it.
 *
 * @param askSystem shows the dialog; [UsbManager.requestPermission] unless a test replaces it.
 */
class UsbPermissionRequester(
    context: Context,
    private val usbManager: UsbManager = context.getSystemService(UsbManager::class.java),
    private val askSystem: (UsbDevice, PendingIntent) -> Unit = usbManager::requestPermission,
) {
    // The application context: a request may outlive the activity that made it.
    private val context: Context = context.applicationContext ?: context

    /**
     * Calls [onResult] on the main thread with whether access to [device] was granted: at once if it
     * already is, else after the user answered. Closing the returned handle abandons the request
     * ([onResult] is then not called).
     */
    fun request(device: UsbDevice, onResult: (granted: Boolean) -> Unit): Closeable {
        if (usbManager.hasPermission(device)) {
            onResult(true)
            return Closeable {}
        }
        val finished = AtomicBoolean(false)
        val receiver = object : BroadcastReceiver() {
            override fun onReceive(receiverContext: Context, intent: Intent) {
                val answered = IntentCompat.getParcelableExtra(intent, UsbManager.EXTRA_DEVICE, UsbDevice::class.java)
                if (answered != null && answered.deviceName != device.deviceName) return // another request's answer
                if (!finished.compareAndSet(false, true)) return
                context.unregisterReceiver(this)
                onResult(intent.getBooleanExtra(UsbManager.EXTRA_PERMISSION_GRANTED, false))
            }
        }
        ContextCompat.registerReceiver(context, receiver, IntentFilter(ACTION_USB_PERMISSION), ContextCompat.RECEIVER_NOT_EXPORTED)
        askSystem(device, permissionIntent(device))
        return Closeable { if (finished.compareAndSet(false, true)) context.unregisterReceiver(receiver) }
    }

    /** Suspends until the user answered; true if access to [device] is granted. Cancelling abandons the request. */
    suspend fun awaitPermission(device: UsbDevice): Boolean = suspendCancellableCoroutine { continuation ->
        val pending = request(device) { granted -> continuation.resume(granted) }
        continuation.invokeOnCancellation { pending.close() }
    }

    private fun permissionIntent(device: UsbDevice): PendingIntent {
        // Explicit (setPackage): Android 14 rejects a mutable PendingIntent around an implicit intent,
        // and the answer should reach only this app.
        val intent = Intent(ACTION_USB_PERMISSION).setPackage(context.packageName)
        // Mutable from Android 12 on, where immutability became a required choice: the system adds
        // EXTRA_DEVICE and EXTRA_PERMISSION_GRANTED to it, which an immutable intent would drop.
        val flags = if (Build.VERSION.SDK_INT >= Build.VERSION_CODES.S) PendingIntent.FLAG_MUTABLE else 0
        return PendingIntent.getBroadcast(context, device.deviceId, intent, flags)
    }

    /** The broadcast action of the permission answer. */
    companion object {
        /** Action of the intent the system sends back with the user's answer. */
        const val ACTION_USB_PERMISSION = "org.hapticon.sensor.usb.USB_PERMISSION"
    }
}
