package org.hapticon.messaging

/**
 * Makes each message take effect once, by id, although MQTT QoS 1 and the outbox's retries deliver at
 * least once. Implementations must be thread-safe; the MQTT receive path calls them from its own thread.
 */
public interface Deduplicator {
    /**
     * Records [messageId] and returns true the first time it is seen, false for every repeat. May block
     * briefly (a database-backed implementation writes); does not throw for any id.
     */
    public fun firstSeen(messageId: String): Boolean
}

/**
 * A [Deduplicator] remembering the most recent [capacity] ids in memory. An id evicted since it was seen
 * counts as new again; a persistent store (the app's message table, keyed by id) closes that gap.
 */
public class BoundedDeduplicator(private val capacity: Int = 10_000) : Deduplicator {
    init {
        require(capacity >= 1) { "capacity must be >= 1, was $capacity" }
    }

    private val seen = object : LinkedHashMap<String, Unit>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, Unit>): Boolean = size > capacity
    }

    /** Number of ids remembered, at most the capacity. */
    public val size: Int
        @Synchronized get() = seen.size

    /** Returns true the first time [messageId] is seen (or seen again after eviction). Never blocks long; never throws. */
    @Synchronized
    override fun firstSeen(messageId: String): Boolean = seen.put(messageId, Unit) == null
}
