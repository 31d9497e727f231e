package org.hapticon.messaging

import java.net.URI
import java.net.URISyntaxException
import java.net.URLDecoder
import java.net.URLEncoder

/**
 * An invitation to chat: who invites ([user], null for a bare broker invitation such as the one
 * `hapticon broker` prints) and on which [broker]. Shown as a QR code and shared as a link
 * `hapticon://invite?user=alice&broker=tcp%3A%2F%2F192.168.1.20%3A1883`; opening the link adds [user]
 * as a contact and fills in the broker.
 *
 * A link comes from anyone, so [parse] accepts only this exact form: scheme `hapticon`, host `invite`,
 * no path, user info or fragment, each parameter at most once, a valid user name and a broker address
 * [BrokerAddress.parse] accepts, [MAX_LENGTH] characters at most. Unknown parameters are ignored, so
 * a newer app's links still open here.
 */
public data class InviteLink(val user: String?, val broker: BrokerAddress) {
    init {
        if (user != null) Topics.requireUserName(user)
    }

    /** The link text, which [parse] reads back. */
    override fun toString(): String = buildString {
        append("$SCHEME://$HOST?")
        if (user != null) append("user=").append(encode(user)).append('&')
        append("broker=").append(encode(broker.toString()))
    }

    public companion object {
        /** The URI scheme the app registers for invitations. */
        public const val SCHEME: String = "hapticon"

        /** The URI host of an invitation. */
        public const val HOST: String = "invite"

        /** Longest link accepted; a real one is under 120 characters. */
        public const val MAX_LENGTH: Int = 512

        /** Reads [text] as an invitation, or explains in one line why it is not one. */
        public fun parse(text: String): Result<InviteLink> = runCatching { parseOrThrow(text.trim()) }

        private fun parseOrThrow(text: String): InviteLink {
            require(text.length <= MAX_LENGTH) { "Invite link too long (${text.length} characters, at most $MAX_LENGTH)" }
            require(text.none { it.isISOControl() }) { "Invite link contains control characters" }
            val uri = try {
                URI(text)
            } catch (e: URISyntaxException) {
                throw IllegalArgumentException("Not a link: ${e.reason}")
            }
            require(uri.scheme.equals(SCHEME, ignoreCase = true) && uri.rawAuthority.equals(HOST, ignoreCase = true)) {
                "Not a Hapticon invite (expected $SCHEME://$HOST?…)"
            }
            require(uri.rawPath.isNullOrEmpty() && uri.rawFragment == null) { "Invite link has unexpected parts after \"$HOST\"" }
            val params = HashMap<String, String>()
            for (pair in (uri.rawQuery ?: "").split('&').filter { it.isNotEmpty() }) {
                val key = decode(pair.substringBefore('='))
                val value = decode(pair.substringAfter('=', ""))
                require(params.put(key, value) == null) { "Invite link names \"$key\" twice" }
            }
            val user = params["user"]?.let { name ->
                require(Topics.isValidUserName(name)) { "Invite link's user name is not valid: use 1 to 32 letters, digits, '.', '_' or '-'" }
                name
            }
            val brokerText = params["broker"] ?: throw IllegalArgumentException("Invite link has no broker")
            val broker = try {
                BrokerAddress.parse(brokerText)
            } catch (e: IllegalArgumentException) {
                throw IllegalArgumentException("Invite link's broker is not valid: ${e.message}")
            }
            return InviteLink(user, broker)
        }

        // The String overloads: the Charset ones need Android 13, the app runs from Android 8.
        private fun encode(s: String): String = URLEncoder.encode(s, "UTF-8")

        private fun decode(s: String): String = try {
            URLDecoder.decode(s, "UTF-8")
        } catch (e: IllegalArgumentException) {
            throw IllegalArgumentException("Invite link has a broken %-escape")
        }
    }
}
