package org.hapticon.core.signal

/**
 * A keyed piecewise-linear amplitude curve: straight lines between consecutive [keys].
 *
 * Two keys at the same time make a step; a sample exactly at the step takes the later key's
 * amplitude, which is how zero-length segments drop out (an attack of 0 s starts at its target).
 * The curve is 0 before t = 0 and after its last key; [length] is the last key's time.
 *
 * @throws IllegalArgumentException if [keys] is empty, the first key is not at t = 0, times
 *   decrease, or any time or amplitude is not finite.
 */
public open class Envelope(keys: List<Key>) : Signal {
    /**
     * One corner of the curve.
     *
     * @property time seconds from the start of the envelope.
     * @property amplitude the value at [time].
     */
    public data class Key(val time: Double, val amplitude: Double)

    /** The corners of the curve in time order (a copy of the constructor argument). */
    public val keys: List<Key> = keys.toList()

    init {
        require(this.keys.isNotEmpty()) { "an envelope needs at least one key" }
        require(this.keys.first().time == 0.0) { "the first key must be at t = 0, was ${this.keys.first().time}" }
        for (key in this.keys) {
            require(key.time.isFinite() && key.amplitude.isFinite()) { "key times and amplitudes must be finite: $key" }
        }
        for (i in 1 until this.keys.size) {
            require(this.keys[i].time >= this.keys[i - 1].time) { "key times must not decrease: ${this.keys}" }
        }
    }

    override val length: Double = this.keys.last().time

    /** The interpolated amplitude at [t]; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        if (t < 0.0 || t > length) return 0.0
        // The last key at or before t, so that at a step the later key wins.
        var i = keys.lastIndex
        while (keys[i].time > t) i--
        if (i == keys.lastIndex) return keys[i].amplitude
        val from = keys[i]
        val to = keys[i + 1]
        return from.amplitude + (to.amplitude - from.amplitude) * (t - from.time) / (to.time - from.time)
    }
}
