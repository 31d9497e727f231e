package org.hapticon.study.design

/**
 * How the order of n items (tasks, or the stimuli of a task) varies with the participant index. See [Counterbalancing].
 *
 * @property jsonName the spelling in protocol JSON and on the command line.
 */
public enum class OrderScheme(public val jsonName: String) {
    /** The listed order for everyone. */
    FIXED("fixed"),

    /**
     * The originating study's alternation, generalised as a cyclic Latin square: participant i gets the list
     * rotated by i mod n. For two items that is A-B, B-A, A-B, ...
     */
    PAPER("paper"),

    /** All n! permutations in lexicographic order, cycled by participant index. */
    FULL("full"),

    /**
     * A Williams design (balanced Latin square): n rows for even n, 2n for odd n (the square and its mirror), in which
     * every item directly precedes every other equally often.
     */
    WILLIAMS("williams"),

    /** A seeded shuffle per participant (SplitMix64 + Fisher-Yates), reproducible on every JVM. */
    RANDOM("random"),
    ;

    public companion object {
        /** The scheme spelled [name] (case-insensitive), or null. */
        public fun fromJsonName(name: String): OrderScheme? = entries.firstOrNull { it.jsonName.equals(name, ignoreCase = true) }
    }
}
