package org.hapticon.study.design

/**
 * SplitMix64 (Steele, Lea & Flood 2014), written out so that a seed gives the same orders on every JVM and
 * Android release: java.util.Random and SplittableRandom document their algorithms but not their stream splitting.
 */
internal class SplitMix64(private var state: Long) {
    fun nextLong(): Long {
        state += GOLDEN_GAMMA
        return mix(state)
    }

    /** Uniform in 0 until [bound] (> 0), by rejection so that no value is favoured. */
    fun nextInt(bound: Int): Int {
        require(bound > 0) { "bound must be > 0, was $bound" }
        val limit = (1L shl 32) - (1L shl 32) % bound
        while (true) {
            val r = nextLong() ushr 32
            if (r < limit) return (r % bound).toInt()
        }
    }

    companion object {
        private const val GOLDEN_GAMMA: Long = -0x61c8864680b583ebL

        /** The SplitMix64 finaliser: a bijection on longs that spreads every input bit over the output. */
        fun mix(value: Long): Long {
            var z = value
            z = (z xor (z ushr 30)) * -0x40a7b892e31b1a47L
            z = (z xor (z ushr 27)) * -0x6b2fb644ecceee15L
            return z xor (z ushr 31)
        }
    }
}
