package org.hapticon.messaging

/**
 * A source of the current time in milliseconds. Everything here that depends on time (rate limiting,
 * retry schedules, message timestamps) takes a clock, so tests drive time by hand.
 */
public fun interface Clock {
    /** The current time in milliseconds. Does not block or throw. */
    public fun nowMillis(): Long

    public companion object {
        /**
         * Wall-clock time (milliseconds since the Unix epoch): for message timestamps and schedules that
         * are stored, such as the outbox's next-attempt times. It can jump when the user changes the time.
         */
        public val SYSTEM: Clock = Clock { System.currentTimeMillis() }

        /**
         * Monotonic time with an arbitrary origin: for in-memory intervals such as the vibration limits,
         * which must not be fooled by a clock change. (On Android, `SystemClock.elapsedRealtime()` is as good.)
         */
        public val MONOTONIC: Clock = Clock { System.nanoTime() / 1_000_000 }
    }
}
