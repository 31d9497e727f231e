package org.hapticon.gesture.recognition

/** The four touch gestures a recogniser tells apart (each also has an [Intensity]). */
public enum class Gesture {
    STROKE, HIT, KNOCK, HUG;

    /** The lower-case spelling used in files and on the command line, e.g. `stroke`. */
    public val id: String get() = name.lowercase()
}

/** How strongly a [Gesture] was performed. */
public enum class Intensity {
    GENTLE, ENERGETIC;

    /** The lower-case spelling, e.g. `gentle`. */
    public val id: String get() = name.lowercase()
}

/**
 * What a window of touch data shows: a [gesture] at an [intensity], or [NONE] (no gesture, and then no
 * intensity). There are nine labels, listed in [ALL]; [id] spells one as `stroke-gentle` or `none`.
 */
public class GestureLabel private constructor(
    /** The gesture, or null for [NONE]. */
    public val gesture: Gesture?,
    /** The intensity, or null for [NONE]. */
    public val intensity: Intensity?,
) {
    /** True for [NONE]. */
    public val isNone: Boolean get() = gesture == null

    /** `gesture-intensity`, e.g. `knock-energetic`, or `none`. */
    public val id: String get() = if (gesture == null) NONE_ID else "${gesture.id}-${intensity!!.id}"

    /** The position of this label in [ALL]: 0 for [NONE], then gestures × intensities in declaration order. */
    public val index: Int get() = if (gesture == null) 0 else 1 + gesture.ordinal * Intensity.entries.size + intensity!!.ordinal

    override fun equals(other: Any?): Boolean = other is GestureLabel && other.gesture == gesture && other.intensity == intensity
    override fun hashCode(): Int = index
    override fun toString(): String = id

    public companion object {
        private const val NONE_ID = "none"

        /** No gesture: rest, noise or drift. */
        public val NONE: GestureLabel = GestureLabel(null, null)

        /** All nine labels in [index] order: [NONE] first. */
        public val ALL: List<GestureLabel> = listOf(NONE) +
            Gesture.entries.flatMap { g -> Intensity.entries.map { i -> GestureLabel(g, i) } }

        /** [gesture] performed at [intensity]. */
        public fun of(gesture: Gesture, intensity: Intensity): GestureLabel = ALL[1 + gesture.ordinal * Intensity.entries.size + intensity.ordinal]

        /** The label spelled [id] (case-insensitive, `_` accepted for `-`), or null when it is none of the nine. */
        public fun parseOrNull(id: String): GestureLabel? {
            val wanted = id.trim().lowercase().replace('_', '-')
            return ALL.firstOrNull { it.id == wanted }
        }

        /** The label spelled [id]; [IllegalArgumentException] listing the valid spellings when it is unknown. */
        public fun parse(id: String): GestureLabel = parseOrNull(id)
            ?: throw IllegalArgumentException("unknown gesture label '$id'; expected one of ${ALL.joinToString { it.id }}")
    }
}
