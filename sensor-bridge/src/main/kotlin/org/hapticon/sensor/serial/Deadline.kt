package org.hapticon.sensor.serial

/** One deadline for a whole read or write, however many transfers it takes. 0 ms means none. */
internal class Deadline(private val clock: MonotonicClock, timeoutMillis: Int) {
    val isForever: Boolean = timeoutMillis == 0
    private val endMillis = clock.nowMillis() + timeoutMillis

    fun expired(): Boolean = !isForever && clock.nowMillis() >= endMillis

    /** The timeout to give the next transfer: 0 (for ever) or what is left, at least 1 ms. */
    fun transferTimeoutMillis(): Int =
        if (isForever) 0 else (endMillis - clock.nowMillis()).coerceIn(1L, Int.MAX_VALUE.toLong()).toInt()
}
