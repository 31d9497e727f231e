package org.hapticon.messaging

/**
 * The MQTT topics of protocol version 1 and the user names they embed.
 *
 * Every user has one inbox, `hapticon/v1/inbox/<user>/+`: what `sender` sends `user` (messages, receipts,
 * hand poses) goes to `hapticon/v1/inbox/<user>/<sender>`. The topic carries the sender because MQTT
 * 3.1.1 does not tell a receiver who published: the broker's ACL lets an authenticated user publish only
 * to topics ending in its own name and read only its own inbox (companion/mosquitto/aclfile, enforced alike
 * by Mosquitto and the embedded broker), so the last level is the broker's word for who sent it, and a
 * payload naming someone else is dropped. Every user also has one retained capabilities message at
 * `hapticon/v1/capabilities/<user>`, which only its owner writes and anyone reads.
 */
public object Topics {
    /** The prefix of every topic of this protocol version. */
    public const val ROOT: String = "hapticon/v1"

    /** The filter that matches every user's capabilities topic. */
    public const val ALL_CAPABILITIES: String = "$ROOT/capabilities/+"

    /** The filter that matches every user's public-key topic (end-to-end protection, [keys]). */
    public const val ALL_KEYS: String = "$ROOT/keys/+"

    /** Longest user name: short enough for MQTT client ids and file names. */
    public const val MAX_USER_NAME_LENGTH: Int = 32

    private const val INBOX_PREFIX = "$ROOT/inbox/"
    private const val CAPABILITIES_PREFIX = "$ROOT/capabilities/"
    private const val KEYS_PREFIX = "$ROOT/keys/"

    // Letters, digits, '.', '_' and '-': no MQTT wildcards ('+', '#'), no level separator ('/'), nothing a
    // terminal or a file system would interpret. Must start with a letter or digit (no "." or "..").
    private val USER_NAME = Regex("[A-Za-z0-9][A-Za-z0-9._-]{0,${MAX_USER_NAME_LENGTH - 1}}")

    /** True when [name] can be a user name: 1..[MAX_USER_NAME_LENGTH] of letters, digits, `.`, `_`, `-`, starting with a letter or digit. */
    public fun isValidUserName(name: String): Boolean = USER_NAME.matches(name)

    /**
     * `hapticon/v1/inbox/<recipient>/<sender>`: where [sender] publishes to [recipient]. Throws
     * [IllegalArgumentException] when either is not a valid user name.
     */
    public fun inbox(recipient: String, sender: String): String = INBOX_PREFIX + requireUserName(recipient) + "/" + requireUserName(sender)

    /** `hapticon/v1/inbox/<user>/+`: the filter that [user] subscribes to. Throws as [inbox] does. */
    public fun inboxFilter(user: String): String = INBOX_PREFIX + requireUserName(user) + "/+"

    /**
     * The sender of a message that arrived on [topic] in [user]'s inbox, or null when [topic] is not
     * `hapticon/v1/inbox/<user>/<valid sender>`.
     */
    public fun inboxSender(user: String, topic: String): String? {
        val prefix = INBOX_PREFIX + user + "/"
        return topic.removePrefix(prefix).takeIf { topic.startsWith(prefix) && isValidUserName(it) }
    }

    /** `hapticon/v1/capabilities/<user>`. Throws [IllegalArgumentException] when [user] is not a valid user name. */
    public fun capabilities(user: String): String = CAPABILITIES_PREFIX + requireUserName(user)

    /** The user whose capabilities [topic] holds, or null when [topic] is not a capabilities topic of a valid user. */
    public fun capabilitiesOwner(topic: String): String? =
        topic.removePrefix(CAPABILITIES_PREFIX).takeIf { topic.startsWith(CAPABILITIES_PREFIX) && isValidUserName(it) }

    /**
     * `hapticon/v1/keys/<user>`: [user]'s retained public keys (`org.hapticon.messaging.e2e.KeyBundle`), which
     * only [user] may write (ACL). Throws [IllegalArgumentException] when [user] is not a valid user name.
     */
    public fun keys(user: String): String = KEYS_PREFIX + requireUserName(user)

    /** The user whose keys [topic] holds, or null when [topic] is not a key topic of a valid user. */
    public fun keysOwner(topic: String): String? =
        topic.removePrefix(KEYS_PREFIX).takeIf { topic.startsWith(KEYS_PREFIX) && isValidUserName(it) }

    /** Returns [name]; throws [IllegalArgumentException] when it is not a valid user name. */
    public fun requireUserName(name: String): String {
        require(isValidUserName(name)) {
            "user name must be 1..$MAX_USER_NAME_LENGTH letters, digits, '.', '_' or '-', starting with a letter or digit; was \"$name\""
        }
        return name
    }
}
