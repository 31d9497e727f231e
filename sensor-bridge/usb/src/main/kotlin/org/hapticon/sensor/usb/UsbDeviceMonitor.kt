package org.hapticon.sensor.usb

import android.content.BroadcastReceiver
import android.content.Context
import android.content.Intent
import android.content.IntentFilter
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import androidx.core.content.ContextCompat
import androidx.core.content.IntentCompat
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.sensor.serial.UsbSerialDriver
import org.hapticon.sensor.serial.UsbSerialProber
import java.io.Closeable
import java.util.concurrent.CopyOnWriteArrayList

/** A plugged-in USB device that a serial driver can drive. */
data class AttachedSerialDevice(
    /** The Android device, for permission requests and opening. */
    val device: UsbDevice,
    /** The driver the prober chose for it. */
    val driver: UsbSerialDriver,
)

/**
 * Watches USB attach and detach broadcasts and keeps [devices], the plugged-in devices that a serial
 * driver can drive, up to date. Call [start] once; [close] stops watching.
 */
class UsbDeviceMonitor(
    context: Context,
    private val usbManager: UsbManager = context.getSystemService(UsbManager::class.java),
    private val prober: UsbSerialProber = UsbSerialProber(),
) : Closeable {
    private val context: Context = context.applicationContext ?: context
    private val attached = MutableStateFlow<List<AttachedSerialDevice>>(emptyList())
    private val detachListeners = CopyOnWriteArrayList<(UsbDevice) -> Unit>()
    private var started = false

    /** The serial-capable devices plugged in now, in the order the system lists them. */
    val devices: StateFlow<List<AttachedSerialDevice>> = attached.asStateFlow()

    private val receiver = object : BroadcastReceiver() {
        override fun onReceive(receiverContext: Context, intent: Intent) {
            when (intent.action) {
                UsbManager.ACTION_USB_DEVICE_ATTACHED -> refresh()
                UsbManager.ACTION_USB_DEVICE_DETACHED -> {
                    val device = IntentCompat.getParcelableExtra(intent, UsbManager.EXTRA_DEVICE, UsbDevice::class.java)
                    refresh(gone = device?.deviceName)
                    if (device != null) detachListeners.forEach { it(device) }
                }
            }
        }
    }

    /** Starts watching (no-op if already started) and lists what is plugged in now. Call on the main thread. */
    fun start() {
        if (started) return
        started = true
        val filter = IntentFilter().apply {
            addAction(UsbManager.ACTION_USB_DEVICE_ATTACHED)
            addAction(UsbManager.ACTION_USB_DEVICE_DETACHED)
        }
        // Not exported: these broadcasts come from the system, which reaches unexported receivers too.
        ContextCompat.registerReceiver(context, receiver, filter, ContextCompat.RECEIVER_NOT_EXPORTED)
        refresh(gone = null)
    }

    /**
     * Calls [listener] on the main thread with each device that is unplugged while this monitor is
     * started. Close the returned handle to stop.
     */
    fun addDetachListener(listener: (UsbDevice) -> Unit): Closeable {
        detachListeners += listener
        return Closeable { detachListeners -= listener }
    }

    /** Stops watching; [devices] keeps its last value. */
    override fun close() {
        if (!started) return
        started = false
        context.unregisterReceiver(receiver)
    }

    /**
     * Re-reads the system's device list now (a "rescan" button: some hubs announce a board late), starting
     * the monitor if it is not running. Call on the main thread.
     */
    fun refresh() {
        if (!started) start() else refresh(gone = null)
    }

    /** Re-reads the system's device list; [gone] is left out even if the list still has it (detach races). */
    private fun refresh(gone: String?) {
        attached.value = usbManager.deviceList.values
            .filter { it.deviceName != gone }
            .mapNotNull { device -> prober.probe(device.toDescription())?.let { AttachedSerialDevice(device, it) } }
    }
}
