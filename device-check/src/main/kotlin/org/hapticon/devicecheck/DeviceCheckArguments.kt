package org.hapticon.devicecheck

import android.os.Bundle

/**
 * What `./build device-check` passes with `am instrument -e NAME VALUE`: the broker as the phone reaches it
 * (`tcp://127.0.0.1:1883` through `adb reverse`), the account the app runs as and the peer this suite sends as. Both
 * accounts are throwaway users of a broker started for the run; the app's data is replaced with them.
 */
data class DeviceCheckArguments(
    val broker: String,
    val user: String,
    val password: String,
    val peer: String,
    val peerPassword: String,
) {
    override fun toString(): String = "DeviceCheckArguments(broker=$broker, user=$user, peer=$peer)" // never the passwords

    companion object {
        val NAMES: List<String> = listOf("broker", "user", "password", "peer", "peerPassword")

        /** Reads them from the instrumentation's arguments; a missing one says how to run the check. */
        fun from(arguments: Bundle): DeviceCheckArguments {
            val value = { name: String ->
                requireNotNull(arguments.getString(name)?.takeIf { it.isNotBlank() }) {
                    "missing instrumentation argument -e $name: run the suite with ./build device-check (docs/device-check.md)"
                }
            }
            return DeviceCheckArguments(value("broker"), value("user"), value("password"), value("peer"), value("peerPassword"))
        }
    }
}
