package org.hapticon.gesture.synthetic

import org.hapticon.gesture.recognition.NaoPreset
import org.hapticon.gesture.recognition.NaoRecording
import org.hapticon.gesture.recognition.NaoSpan
import java.util.SplittableRandom
import kotlin.math.PI
import kotlin.math.exp
import kotlin.math.sin
import kotlin.math.sqrt

/**
 * Deterministic simulated people following the NAO study's touch protocol on its four fabric sensors at 40 Hz, so the
 * NAO preset runs end to end. **Simulated, not the paper's data:** the gestures are our models, and what a forest
 * scores on them says how separable these models are, not how the paper's participants could be told apart.
 *
 * **The protocol, as the paper runs it** (004_7d5078645d142b2a.txt:152): one force intensity for the first half and the
 * other for the second (which comes first is drawn per person: the paper says only that participants were told which
 * they used first, :149); within a half, the sensors one at a time in random order; at each sensor the five gestures
 * in a random order, each performed for [GESTURE_SECONDS] with a [BREAK_SECONDS] break of no touching, the whole
 * round [ROUNDS] times (a new random order each round: the paper does not say whether the order was redrawn), so
 * 2 × 4 × 5 × 3 = 120 performances per person. Each performance is a span from its first to its last touch sample
 * on the sensor it was performed on (the experimenter's button presses marked the paper's, :162).
 *
 * **The sensors** (ours, from the paper's characterisation): each reads R = R0·(1 + overshoot)/(1 + s·P) for pressure
 * P ≥ 0, with R0 the initial resistance measured in the koala suit, hand 11.5, lower arm 18, upper arm 9.5 and
 * shoulder 4.0 kΩ (:267), varied ±10 % per person; the shoulder's sensitivity s is a tenth of the others' (1)
 * (:269, :285); after a release the resistance rises above R0, by [OVERSHOOT] times how far the touch compressed the
 * sensor, and returns with a 1.5 s time constant, the slow return the paper describes (:293); 1 % noise on every
 * sample.
 *
 * **The gestures** (ours; pressures in units of s·P, times divided by the person's tempo and the energetic pace):
 * - **hit**: a 0.1 s half-sine of pressure 4, every 0.8 s;
 * - **poke**: a 0.2 s half-sine of pressure 1.5, every 0.6 s;
 * - **squeeze**: pressure 3 held 1.2 s with a 0.3 s rise and fall, every 2.0 s;
 * - **stroke**: a 0.8 s raised-cosine pressure bump of 1.2 (a hand sliding over the sensor), every 1.1 s;
 * - **tickle**: 0.08 s half-sine taps of pressure 0.5 at 6 Hz.
 *
 * **People** (ours): a force scale 0.6–1.4, a tempo 0.8–1.2 and an energetic-to-gentle force ratio of 1.0–2.4 (the
 * paper saw some people press as hard in both halves, :247); energetic is also 1.3× the pace. Every performance varies
 * its pressure and its pace by ±20 %, and starts 0–0.5 s into its [GESTURE_SECONDS].
 */
public object NaoSyntheticPeople {
    /** How long each gesture is performed: 5 s (004_7d5078645d142b2a.txt:152). */
    public const val GESTURE_SECONDS: Double = 5.0

    /** The break of no touching between gestures: 5 s (004_7d5078645d142b2a.txt:152). */
    public const val BREAK_SECONDS: Double = 5.0

    /** Rounds of the five gestures at each sensor: three trials of each (004_7d5078645d142b2a.txt:152). */
    public const val ROUNDS: Int = 3

    /** Performances per person: 2 intensities × 5 gestures × 4 sensors × 3 repetitions = 120 (004_7d5078645d142b2a.txt:152). */
    public val PERFORMANCES: Int = NaoPreset.INTENSITIES.size * NaoPreset.GESTURES.size * NaoPreset.LOCATIONS.size * ROUNDS

    /** Participants in the paper's study: 15 (004_7d5078645d142b2a.txt:127). */
    public const val PAPER_PARTICIPANTS: Int = 15

    /** Initial resistance of each sensor in the koala suit, kΩ, hand … shoulder (004_7d5078645d142b2a.txt:267). */
    public val INITIAL_KILOOHMS: List<Double> = listOf(11.5, 18.0, 9.5, 4.0)

    /** Sensitivity of each sensor relative to the hand's: the shoulder is "nearly 10 times less sensitive" (004_7d5078645d142b2a.txt:269). */
    public val SENSITIVITY: List<Double> = listOf(1.0, 1.0, 1.0, 0.1)

    /** How far the resistance rises above R0 after a release, per unit of compression 1 − R/R0 (ours, for the slow return of 004_7d5078645d142b2a.txt:293). */
    public const val OVERSHOOT: Double = 0.15

    /** [count] people ("p1" …), each through the whole protocol ([rounds] rounds at each sensor), repeatable for a [seed]. */
    public fun sessions(count: Int, rounds: Int = ROUNDS, seed: Long = 1L): List<NaoRecording> {
        require(count >= 1 && rounds >= 1) { "need at least one person and one round" }
        val random = SplittableRandom(seed)
        return List(count) { session("p${it + 1}", rounds, random.split()) }
    }

    private fun session(person: String, rounds: Int, random: SplittableRandom): NaoRecording {
        val force = 0.6 + 0.8 * random.nextDouble()
        val tempo = 0.8 + 0.4 * random.nextDouble()
        val contrast = 1.0 + 1.4 * random.nextDouble()
        val r0 = DoubleArray(NaoPreset.CHANNELS) { INITIAL_KILOOHMS[it] * (0.9 + 0.2 * random.nextDouble()) }
        val intensities = if (random.nextBoolean()) NaoPreset.INTENSITIES else NaoPreset.INTENSITIES.reversed()
        val pressure = ArrayList<DoubleArray>()
        val spans = ArrayList<NaoSpan>()
        fun rest(seconds: Double) = repeat((seconds * NaoPreset.SAMPLE_RATE).toInt()) { pressure += DoubleArray(NaoPreset.CHANNELS) }
        rest(BREAK_SECONDS)
        for (intensity in intensities) {
            val energetic = intensity == "energetic"
            for (location in shuffled(NaoPreset.LOCATIONS.indices.toList(), random)) {
                repeat(rounds) {
                    for (gesture in shuffled(NaoPreset.GESTURES, random)) {
                        val scale = force * (if (energetic) contrast else 1.0) * (0.8 + 0.4 * random.nextDouble())
                        val pace = tempo * (if (energetic) 1.3 else 1.0) * (0.8 + 0.4 * random.nextDouble())
                        val lead = 0.5 * random.nextDouble()
                        val start = pressure.size
                        val frames = (GESTURE_SECONDS * NaoPreset.SAMPLE_RATE).toInt()
                        var first = -1
                        var last = -1
                        for (k in 0 until frames) {
                            val t = (k / NaoPreset.SAMPLE_RATE - lead) * pace
                            val p = DoubleArray(NaoPreset.CHANNELS)
                            if (t >= 0) p[location] = scale * touch(gesture, t)
                            if (p[location] > 0.0) {
                                if (first < 0) first = start + k
                                last = start + k
                            }
                            pressure += p
                        }
                        if (first >= 0 && last > first) spans += NaoSpan(first, last + 1, "$gesture-$intensity", NaoPreset.LOCATIONS[location])
                        rest(BREAK_SECONDS)
                    }
                }
            }
        }
        val channels = List(NaoPreset.CHANNELS) { c -> resistance(pressure, c, r0[c], random) }
        return NaoRecording(person, channels, spans)
    }

    /** The pressure of [gesture] at [t] seconds (pace applied) into a performance. */
    private fun touch(gesture: String, t: Double): Double = when (gesture) {
        "hit" -> 4.0 * halfSine(t % 0.8, 0.1)
        "poke" -> 1.5 * halfSine(t % 0.6, 0.2)
        "squeeze" -> 3.0 * plateau(t % 2.0, 0.3, 1.2)
        "stroke" -> { val phase = t % 1.1; if (phase < 0.8) 1.2 * 0.5 * (1 - kotlin.math.cos(2 * PI * phase / 0.8)) else 0.0 }
        else -> 0.5 * halfSine(t % (1.0 / 6.0), 0.08)
    }

    /**
     * One channel's resistance over the whole session: R0·(1 + overshoot)/(1 + s·P), 1 % noise. A release raises the
     * overshoot to [OVERSHOOT] times how far the touch had compressed the sensor (1 − R/R0 at its deepest), so a
     * light touch leaves a light rise; it decays with a 1.5 s time constant.
     */
    private fun resistance(pressure: List<DoubleArray>, c: Int, r0: Double, random: SplittableRandom): DoubleArray {
        val decay = exp(-1.0 / (1.5 * NaoPreset.SAMPLE_RATE))
        var overshoot = 0.0
        var deepest = 0.0
        return DoubleArray(pressure.size) { k ->
            val compressed = 1.0 - 1.0 / (1.0 + SENSITIVITY[c] * pressure[k][c])
            if (compressed > 0.0) {
                deepest = maxOf(deepest, compressed)
            } else if (deepest > 0.0) {
                overshoot = maxOf(overshoot, OVERSHOOT * deepest)
                deepest = 0.0
            }
            overshoot *= decay
            r0 * (1.0 + overshoot) * (1.0 - compressed) * (1.0 + 0.01 * gaussian(random))
        }
    }

    private fun <T> shuffled(items: List<T>, random: SplittableRandom): List<T> {
        val order = items.toMutableList()
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        return order
    }

    private fun halfSine(t: Double, length: Double): Double = if (t < length) sin(PI * t / length) else 0.0

    private fun plateau(t: Double, rise: Double, hold: Double): Double = when {
        t < rise -> t / rise
        t < rise + hold -> 1.0
        t < 2 * rise + hold -> 1.0 - (t - rise - hold) / rise
        else -> 0.0
    }

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; 1 − u keeps the logarithm finite.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * kotlin.math.ln(u)) * kotlin.math.cos(2 * PI * random.nextDouble())
    }
}
