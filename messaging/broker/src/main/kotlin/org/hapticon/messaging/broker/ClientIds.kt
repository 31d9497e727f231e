package org.hapticon.messaging.broker

/**
 * The client ids the embedded broker accepts: `USER:DEVICE`, the authenticated user's name, a colon and 32
 * lowercase hex digits (128 random bits the device made once and keeps: `org.hapticon.messaging.mqtt.DeviceId`,
 * which the messaging tests hold to this rule). Each device of a user has its own persistent session; nobody
 * can present another user's client id (refused), nor guess another device's of the same user.
 */
internal object ClientIds {
    private val DEVICE = Regex("[0-9a-f]{32}")

    /** True when [clientId] is one of [user]'s device ids. */
    fun isDeviceOf(user: String, clientId: String): Boolean =
        clientId.length == user.length + 33 && clientId.startsWith(user) && clientId[user.length] == ':' &&
            DEVICE.matches(clientId.substring(user.length + 1))

    /** The user of a client id the broker accepted ([isDeviceOf] held when it connected), or null for another form. */
    fun userOf(clientId: String): String? {
        val colon = clientId.length - 33
        if (colon < 1 || clientId[colon] != ':' || !DEVICE.matches(clientId.substring(colon + 1))) return null
        return clientId.substring(0, colon)
    }
}
