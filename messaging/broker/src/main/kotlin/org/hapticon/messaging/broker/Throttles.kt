package org.hapticon.messaging.broker

/**
 * Token buckets by key: each key holds up to [capacity] tokens and regains one every [refillNanos]; [take] spends
 * one. Keys whose bucket is full again are forgotten, so an attacker's many keys cost memory only while they are
 * being punished. Thread-safe.
 */
internal class Buckets(private val capacity: Int, private val refillNanos: Long, private val nanoTime: () -> Long) {
    private class Bucket(var tokens: Double, var stamp: Long)

    private val buckets = HashMap<String, Bucket>()

    /** True when [key] has a token left (nothing is spent). */
    @Synchronized
    fun hasToken(key: String): Boolean = level(key) >= 1.0

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
 * whether a login may have it computed now: not when its client address or (unless it comes from a known device)
 * its user name has spent its failed logins ([BrokerLimits]), not while another hash for the same address or user
 * name is being computed, and not when [BrokerLimits.waitingLogins] already wait. A refused login costs nothing.
 * Thread-safe.
 */
internal class LoginThrottle(private val limits: BrokerLimits, nanoTime: () -> Long = System::nanoTime) {
    private val refill = limits.failedLoginRefillMillis * 1_000_000
    private val sources = Buckets(limits.failedLoginsPerSource, refill, nanoTime)
    private val users = Buckets(limits.failedLoginsPerUser, refill, nanoTime)
    private val busySources = HashSet<String>()
    private val busyUsers = HashSet<String>()
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
    inner class Permit internal constructor(private val source: String, private val user: String?) : Decision {
        private var finished = false

        /** The hash said [success]; a failure is charged to the address and (unless from a known device) the user name. */
        fun finish(success: Boolean) = synchronized(this@LoginThrottle) {
            check(!finished) { "finished twice" }
            finished = true
            waiting--
            busySources -= source
            user?.let { busyUsers -= it }
            if (!success) {
                sources.take(source)
                user?.let(users::take)
            }
        }
    }

    /**
     * A permit for a login of [user] from [source], or why not. [knownDevice]: its client id is one of [user]'s
     * existing sessions, so the per-user limit does not apply.
     */
    @Synchronized
    fun begin(source: String, user: String, knownDevice: Boolean): Decision {
        val perUser = if (knownDevice) null else user
        return when {
            !sources.hasToken(source) -> Refusal.SOURCE
            perUser != null && !users.hasToken(perUser) -> Refusal.USER
            source in busySources || (perUser != null && perUser in busyUsers) || waiting >= limits.waitingLogins -> Refusal.BUSY
            else -> {
                waiting++
                busySources += source
                perUser?.let { busyUsers += it }
                Permit(source, perUser)
            }
        }
    }
}
