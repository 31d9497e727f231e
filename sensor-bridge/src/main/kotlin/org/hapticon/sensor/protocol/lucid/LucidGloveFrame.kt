package org.hapticon.sensor.protocol.lucid

/**
 * One decoded LucidGloves line, with the raw integer values the glove sent (0..ANALOG_MAX of its
 * board, e.g. 4095 on an ESP32). The decoder owns and reuses this object: it is valid only until
 * the next frame is delivered, so copy what you keep.
 *
 * Optional values the line did not carry read [ABSENT].
 */
public class LucidGloveFrame internal constructor() {
    /** Finger curl `A`..`E`, indexed [THUMB]..[PINKY]; always present in a delivered frame. */
    public val curl: IntArray = IntArray(FINGERS)

    /** Finger splay `(AB)`..`(EB)`, indexed [THUMB]..[PINKY], or [ABSENT] per finger. */
    public val splay: IntArray = IntArray(FINGERS)

    /**
     * Per-joint curl `(AAA)`..`(EAD)` at `finger * 4 + joint` (joint 0..3), or [ABSENT]; the
     * OpenGloves driver uses the finger's [curl] for an absent joint.
     */
    public val jointCurl: IntArray = IntArray(FINGERS * JOINTS_PER_FINGER)

    /** Joystick X (`F`), or [ABSENT]. */
    public var joystickX: Int = ABSENT
        internal set

    /** Joystick Y (`G`), or [ABSENT]. */
    public var joystickY: Int = ABSENT
        internal set

    /** Analog trigger (`P`), or [ABSENT]. */
    public var trigger: Int = ABSENT
        internal set

    internal var buttons: Int = 0

    /** Whether the line carried [button]'s letter. */
    public fun isPressed(button: LucidButton): Boolean = buttons and (1 shl button.ordinal) != 0

    internal fun clear() {
        splay.fill(ABSENT)
        jointCurl.fill(ABSENT)
        joystickX = ABSENT
        joystickY = ABSENT
        trigger = ABSENT
        buttons = 0
    }

    /** The frame in the encoding it came in (flags in letter order), for tests and logs. Allocates. */
    override fun toString(): String = buildString {
        for (f in 0 until FINGERS) append('A' + f).append(curl[f])
        if (joystickX != ABSENT) append('F').append(joystickX)
        if (joystickY != ABSENT) append('G').append(joystickY)
        if (trigger != ABSENT) append('P').append(trigger)
        for (b in LucidButton.entries) if (isPressed(b)) append(b.key)
        for (f in 0 until FINGERS) if (splay[f] != ABSENT) append('(').append('A' + f).append("B)").append(splay[f])
        for (i in jointCurl.indices) {
            if (jointCurl[i] != ABSENT) append('(').append('A' + i / JOINTS_PER_FINGER).append('A').append('A' + i % JOINTS_PER_FINGER).append(')').append(jointCurl[i])
        }
    }

    /** Finger indices and the absent marker. */
    public companion object {
        /** Marks an optional value the line did not carry. */
        public const val ABSENT: Int = -1

        /** Number of fingers. */
        public const val FINGERS: Int = 5

        /** Joints per finger in [jointCurl]. */
        public const val JOINTS_PER_FINGER: Int = 4

        /** Index of the thumb (`A`). */
        public const val THUMB: Int = 0

        /** Index of the index finger (`B`). */
        public const val INDEX: Int = 1

        /** Index of the middle finger (`C`). */
        public const val MIDDLE: Int = 2

        /** Index of the ring finger (`D`). */
        public const val RING: Int = 3

        /** Index of the pinky (`E`). */
        public const val PINKY: Int = 4
    }
}
