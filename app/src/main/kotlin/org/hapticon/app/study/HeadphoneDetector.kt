package org.hapticon.app.study

import android.content.Context
import android.media.AudioDeviceInfo
import android.media.AudioManager

/** Whether the participant wears headphones, so that masking noise stays out of the room. */
fun interface HeadphoneDetector {
    /** True when a wired, USB or Bluetooth headset or headphones are connected. */
    fun headphonesConnected(): Boolean
}

/** [HeadphoneDetector] from AudioManager's output devices. */
class AudioManagerHeadphoneDetector(context: Context) : HeadphoneDetector {
    private val audio = context.getSystemService(AudioManager::class.java)

    override fun headphonesConnected(): Boolean =
        audio?.getDevices(AudioManager.GET_DEVICES_OUTPUTS).orEmpty().any { it.type in HEADPHONE_TYPES }

    companion object {
        /** The output device types that count as headphones. */
        val HEADPHONE_TYPES: Set<Int> = setOf(
            AudioDeviceInfo.TYPE_WIRED_HEADPHONES,
            AudioDeviceInfo.TYPE_WIRED_HEADSET,
            AudioDeviceInfo.TYPE_BLUETOOTH_A2DP,
            AudioDeviceInfo.TYPE_USB_HEADSET,
            AudioDeviceInfo.TYPE_BLE_HEADSET,
        )
    }
}
