package org.hapticon.messaging.broker

import java.io.File
import java.io.IOException

/**
 * A Mosquitto ACL file (`acl_file` in mosquitto.conf), so that the embedded broker enforces exactly the
 * rules the Mosquitto deployment does, from the same file (companion/mosquitto/aclfile, which
 * `hapticon broker` writes from [DEFAULT_TEXT] on first run; a test keeps the two equal).
 *
 * The subset of Mosquitto's format (mosquitto.conf(5), "acl_file") read here:
 * - `topic [read|write|readwrite|deny] TOPIC` — for the user of the preceding `user NAME` line; lines before
 *   any `user` line apply to anonymous clients, as in Mosquitto;
 * - `pattern [read|write|readwrite|deny] TOPIC` — for every client, with `%u` replaced by its user name and
 *   `%c` by its client id (an access without the keyword means readwrite);
 * - `#` comments and blank lines. Anything else is an error naming the line, rather than a rule silently
 *   ignored.
 *
 * Publishing to a topic needs a write rule matching it; subscribing to a filter needs a read rule that
 * covers every topic the filter can match (so `#` or another user's inbox are refused in the SUBACK); a
 * `deny` rule matching it wins over both. Mosquitto 2.0 checks read rules per delivered message rather than
 * at subscription, so there a too-wide subscription is granted but delivers nothing it does not allow: to a
 * client, the same outcome.
 */
public class AclFile private constructor(private val rules: List<Rule>) {
    private enum class Access { READ, WRITE, READWRITE, DENY }

    private class Rule(val user: String?, val anonymousOnly: Boolean, val pattern: Boolean, val access: Access, val topic: String)

    /** True when [user] (null: anonymous) with [clientId] may publish to [topic]. */
    public fun mayPublish(user: String?, clientId: String, topic: String): Boolean {
        if ('+' in topic || '#' in topic) return false
        val applicable = applicable(user, clientId)
        if (applicable.any { (access, filter) -> access == Access.DENY && matches(filter, topic) }) return false
        return applicable.any { (access, filter) -> (access == Access.WRITE || access == Access.READWRITE) && matches(filter, topic) }
    }

    /** True when [user] (null: anonymous) with [clientId] may subscribe to [filter]. */
    public fun maySubscribe(user: String?, clientId: String, filter: String): Boolean {
        val applicable = applicable(user, clientId)
        if (applicable.any { (access, rule) -> access == Access.DENY && overlaps(rule, filter) }) return false
        return applicable.any { (access, rule) -> (access == Access.READ || access == Access.READWRITE) && covers(rule, filter) }
    }

    /** The rules for this client as (access, topic filter), patterns substituted. */
    private fun applicable(user: String?, clientId: String): List<Pair<Access, String>> = rules.mapNotNull { rule ->
        when {
            rule.pattern -> {
                // Mosquitto refuses to substitute a name that would change the filter's structure.
                if ((rule.topic.contains("%u") && (user == null || !isPlainLevel(user))) || (rule.topic.contains("%c") && !isPlainLevel(clientId))) {
                    null
                } else {
                    rule.access to rule.topic.replace("%u", user ?: "").replace("%c", clientId)
                }
            }
            rule.anonymousOnly -> if (user == null) rule.access to rule.topic else null
            else -> if (rule.user == user) rule.access to rule.topic else null
        }
    }

    public companion object {
        /**
         * Hapticon's ACL, the content of companion/mosquitto/aclfile: each user reads only its own inbox and
         * publishes only under its own name (so the topic carries the broker's word for the sender), reads
         * everyone's capabilities and writes only its own.
         */
        public val DEFAULT_TEXT: String = """
            |# Hapticon's topic ACL: Mosquitto's acl_file format, read by Mosquitto (acl_file in mosquitto.conf) and by
            |# the embedded broker of `hapticon broker` alike. Pattern lines apply to every authenticated user; %u is that
            |# user's name. Anything not allowed here is denied: a denied subscription gets a failure in its SUBACK (or,
            |# in Mosquitto 2.0, delivers nothing), a denied publish is dropped.
            |#
            |# Read your own inbox: what others send you arrives on hapticon/v1/inbox/<you>/<sender>.
            |pattern read hapticon/v1/inbox/%u/+
            |# Write into anyone's inbox, but only under your own name: the last level is the broker's word for the sender.
            |pattern write hapticon/v1/inbox/+/%u
            |# Read everyone's capabilities; write (retain) only your own.
            |pattern read hapticon/v1/capabilities/+
            |pattern write hapticon/v1/capabilities/%u
            |# Read everyone's public keys (end-to-end encryption); write (retain) only your own.
            |pattern read hapticon/v1/keys/+
            |pattern write hapticon/v1/keys/%u
            |""".trimMargin()

        /** The rules of [DEFAULT_TEXT]. */
        public val DEFAULT: AclFile = parse(DEFAULT_TEXT)

        /** Reads [file]. Throws [IOException] when it cannot be read or has a line this class does not understand. */
        public fun read(file: File): AclFile = try {
            parse(file.readText())
        } catch (e: IllegalArgumentException) {
            throw IOException("$file: ${e.message}", e)
        }

        /** Parses ACL [text]. Throws [IllegalArgumentException] naming the first line it does not understand. */
        public fun parse(text: String): AclFile {
            val rules = mutableListOf<Rule>()
            var user: String? = null
            var seenUser = false
            text.lines().forEachIndexed { index, raw ->
                val line = raw.trim()
                if (line.isEmpty() || line.startsWith("#")) return@forEachIndexed
                val keyword = line.substringBefore(' ')
                val rest = line.substringAfter(' ', "").trim()
                when (keyword) {
                    "user" -> {
                        require(rest.isNotEmpty()) { "line ${index + 1}: user without a name" }
                        user = rest
                        seenUser = true
                    }
                    "topic", "pattern" -> {
                        val first = rest.substringBefore(' ')
                        val access = Access.entries.firstOrNull { it.name.lowercase() == first }
                        val topic = (if (access != null) rest.substringAfter(' ', "") else rest).trim()
                        require(topic.isNotEmpty() && ' ' !in topic) { "line ${index + 1}: expected '$keyword [read|write|readwrite|deny] TOPIC'" }
                        rules += Rule(user, anonymousOnly = !seenUser, pattern = keyword == "pattern", access ?: Access.READWRITE, topic)
                    }
                    else -> throw IllegalArgumentException("line ${index + 1}: unknown keyword '$keyword'")
                }
            }
            return AclFile(rules)
        }

        private fun isPlainLevel(name: String) = name.isNotEmpty() && name.none { it == '+' || it == '#' || it == '/' }

        /** MQTT topic matching (MQTT 3.1.1 §4.7): does [filter] match the concrete [topic]? */
        internal fun matches(filter: String, topic: String): Boolean {
            val f = filter.split('/')
            val t = topic.split('/')
            // §4.7.2: a filter starting with a wildcard does not match topics starting with '$'.
            if (t[0].startsWith("$") && (f[0] == "+" || f[0] == "#")) return false
            for (i in f.indices) {
                if (f[i] == "#") return true
                if (i >= t.size) return false
                if (f[i] != "+" && f[i] != t[i]) return false
            }
            return f.size == t.size
        }

        /** Does the rule filter [rule] match every topic that [filter] can match? */
        internal fun covers(rule: String, filter: String): Boolean {
            val r = rule.split('/')
            val f = filter.split('/')
            for (i in r.indices) {
                if (r[i] == "#") return true
                if (i >= f.size) return false
                when (r[i]) {
                    "+" -> if (f[i] == "#") return false
                    else -> if (f[i] != r[i]) return false
                }
            }
            return r.size == f.size
        }

        /** Can some topic match both filters? (A deny rule refuses any subscription it overlaps.) */
        internal fun overlaps(a: String, b: String): Boolean {
            val x = a.split('/')
            val y = b.split('/')
            for (i in 0 until maxOf(x.size, y.size)) {
                if (x.getOrNull(i) == "#" || y.getOrNull(i) == "#") return true
                val p = x.getOrNull(i) ?: return false
                val q = y.getOrNull(i) ?: return false
                if (p != "+" && q != "+" && p != q) return false
            }
            return true
        }
    }
}
