package org.hapticon.messaging.broker

/**
 * Token buckets by key: each key holds up to [capacity] tokens and regains one every [refillNanos]; [take] spends
 * one. Keys whose bucket is full again are forgotten, so an attacker's many keys cost memory only while they are
 * being punished. Thread-safe.
 */
internal class Buckets(private val capacity: Int, private val refillNanos: Long, private val nanoTime: () -> Long) {
    private class Bucket(var tokens: Double, var stamp: Long)

    private val buckets = HashMap<String, Bucket>()

    /** The tokens [key] has now, fractions included (nothing is spent). */
    @Synchronized
    fun tokens(key: String): Double = level(key)

    /** Spends one of [key]'s tokens; returns false (and spends nothing) when it has none. */
    @Synchronized
    fun take(key: String): Boolean {
        val level = level(key)
        if (level < 1.0) return false
        buckets[key] = Bucket(level - 1.0, nanoTime())
        if (buckets.size > PRUNE_ABOVE) prune()
        return true
    }

    private fun level(key: String): Double {
        val bucket = buckets[key] ?: return capacity.toDouble()
        val level = minOf(capacity.toDouble(), bucket.tokens + (nanoTime() - bucket.stamp).toDouble() / refillNanos)
        if (level >= capacity) buckets.remove(key)
        return level
    }

    private fun prune() {
        buckets.keys.toList().forEach(::level)
    }

    private companion object {
        const val PRUNE_ABOVE = 10_000
    }
}

/**
 * Decides, before the expensive password hash (210,000 PBKDF2 rounds take a core about a quarter of a second),
 * whether a login may have it computed now: only while its client address and its user name have failed logins left
 * ([BrokerLimits]) beyond the logins of theirs being hashed right now (each reserves one, given back on success), and
 * while fewer than [BrokerLimits.waitingLogins] wait. So 32 wrong passwords sent at once from one address cost at most
 * its 5 hashes, and then one a minute. A refused login costs nothing. A login from a known device (its
 * client id is an existing session of that user, a secret: OWASP's "device cookie") is never refused, so an attacker who
 * guesses at a user's password, or shares an address with the user, cannot lock the user's own devices out; it
 * waits its turn for the hash like every other. Thread-safe.
 */
internal class LoginThrottle(private val limits: BrokerLimits, nanoTime: () -> Long = System::nanoTime) {
    private val refill = limits.failedLoginRefillMillis * 1_000_000
    private val sources = Buckets(limits.failedLoginsPerSource, refill, nanoTime)
    private val users = Buckets(limits.failedLoginsPerUser, refill, nanoTime)
    private val hashingFor = HashMap<String, Int>() // "s:ADDRESS" and "u:USER" -> logins being hashed
    private var waiting = 0

    /** What [begin] decided. */
    sealed interface Decision

    /** Why a login was refused before hashing. */
    enum class Refusal(val reason: String) : Decision {
        SOURCE("too many failed logins from this address; try again later"),
        USER("too many failed logins for this user name; try again later"),
        BUSY("too many logins at once; try again"),
    }

    /** One login allowed to be hashed; [finish] must be called exactly once with the outcome. */
    inner class Permit internal constructor(private val source: String?, private val user: String?) : Decision {
        private var finished = false

        /** The hash said [success]; a failure of an unknown device is charged to its address and user name. */
        fun finish(success: Boolean) = synchronized(this@LoginThrottle) {
            check(!finished) { "finished twice" }
            finished = true
            if (source == null || user == null) return@synchronized
            waiting--
            release("s:$source")
            release("u:$user")
            if (!success) {
                sources.take(source)
                users.take(user)
            }
        }
    }

    /** A permit for a login of [user] from [source], or why not. [knownDevice]: its client id is one of [user]'s existing sessions. */
    @Synchronized
    fun begin(source: String, user: String, knownDevice: Boolean): Decision {
        if (knownDevice) return Permit(null, null)
        val sourceLeft = sources.tokens(source)
        val userLeft = users.tokens(user)
        return when {
            sourceLeft < 1.0 -> Refusal.SOURCE
            userLeft < 1.0 -> Refusal.USER
            sourceLeft - hashing("s:$source") < 1.0 || userLeft - hashing("u:$user") < 1.0 || waiting >= limits.waitingLogins -> Refusal.BUSY
            else -> {
                waiting++
                hashingFor.merge("s:$source", 1, Int::plus)
                hashingFor.merge("u:$user", 1, Int::plus)
                Permit(source, user)
            }
        }
    }

    private fun hashing(key: String): Int = hashingFor[key] ?: 0

    private fun release(key: String) {
        val left = hashing(key) - 1
        if (left <= 0) hashingFor.remove(key) else hashingFor[key] = left
    }
}
