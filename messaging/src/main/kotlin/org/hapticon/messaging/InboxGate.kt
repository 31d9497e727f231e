package org.hapticon.messaging

/**
 * What a receiver does with a [ChatMessage] before showing it: drop repeats ([Deduplicator]) and decide
 * whether its icon may vibrate ([VibrationRateLimiter]). The app and the command-line chat both use it, so
 * they treat floods and repeats alike. Thread-safe when its parts are; never throws.
 */
public class InboxGate(
    private val deduplicator: Deduplicator,
    private val rateLimiter: VibrationRateLimiter,
) {
    /** Admits [message]: [Admission.Duplicate] when its id was seen before, else [Admission.New] with the vibration decision. */
    public fun admit(message: ChatMessage): Admission {
        if (!deduplicator.firstSeen(message.id)) return Admission.Duplicate
        // A pattern drives the actuator like an icon: it counts against the same limits.
        val seconds = message.icon?.duration ?: message.pattern?.duration ?: return Admission.New(message, vibration = null)
        // Rounded, not ceiled: 3 · 2.6 + 3 is 10.800000000000001 s in binary, and that stroke lasts 10 800 ms.
        return Admission.New(message, rateLimiter.tryAcquire(message.sender, Math.round(seconds * 1000.0)))
    }
}

/** The outcome of [InboxGate.admit]. */
public sealed interface Admission {
    /** Seen before: ignore it (it took effect the first time). */
    public data object Duplicate : Admission

    /**
     * A message to store and show.
     *
     * @property message the message.
     * @property vibration whether to play its icon now; null when it has none. Anything but
     *   [VibrationDecision.VIBRATE] means show the icon without playing it.
     */
    public data class New(val message: ChatMessage, val vibration: VibrationDecision?) : Admission
}
