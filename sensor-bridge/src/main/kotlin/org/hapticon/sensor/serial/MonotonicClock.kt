package org.hapticon.sensor.serial

/** Milliseconds from an arbitrary origin that never go backwards; injected so deadline tests need no sleeping. */
public fun interface MonotonicClock {
    /** The current time in milliseconds. */
    public fun nowMillis(): Long

    /** The system clock. */
    public companion object {
        /** [System.nanoTime] in milliseconds: immune to wall-clock changes. */
        public val SYSTEM: MonotonicClock = MonotonicClock { System.nanoTime() / 1_000_000 }
    }
}
