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
 * Deterministic simulated people touching a 4-channel resistive fabric sensor at 40 Hz, for the NAO preset's
 * 11 classes. Each channel reads R = R0 / (1 + P) kΩ for pressure P ≥ 0 (a piezoresistive fabric's resistance
 * falls as it is pressed; R0 ≈ 10 kΩ varies per person and channel), plus 1 % noise.
 *
 * A session is every class performed [takesPerClass] times in shuffled order, each gesture repeated for 3–5 s
 * (as the paper's participants performed each class for a while) with 1.5–3 s of rest between. Models (times are
 * divided by the person's tempo, pressures multiplied by their force scale; energetic is 1.8× the pressure and
 * 1.5× the pace of gentle; every take varies both by ±20 %):
 * - **hit**: a 0.12 s half-sine of pressure 3 on two neighbouring channels, every 0.7 s;
 * - **poke**: a 0.2 s half-sine of pressure 1.5 on one channel, every 0.8 s;
 * - **squeeze**: pressure 2.5 on all four channels held 1.2 s with a 0.3 s rise and fall, every 1.8 s;
 * - **stroke**: a pressure-1 bump travelling across channels 1→4 in 0.8 s, every 1.2 s;
 * - **tickle**: 0.08 s taps of pressure 0.6 at 6 Hz on channels picked at random.
 * Gentle tickle and gentle poke overlap by design (small, short single-channel touches), as in the paper's
 * confusions.
 */
public object NaoSyntheticPeople {
    /** [count] people, repeatable for a [seed]. */
    public fun sessions(count: Int, takesPerClass: Int = 3, seed: Long = 1L): List<NaoRecording> {
        require(count >= 1 && takesPerClass >= 1) { "need at least one person and one take" }
        val random = SplittableRandom(seed)
        return List(count) { session("p${it + 1}", takesPerClass, random.split()) }
    }

    private fun session(person: String, takes: Int, random: SplittableRandom): NaoRecording {
        val force = 0.7 + 0.6 * random.nextDouble()
        val tempo = 0.8 + 0.4 * random.nextDouble()
        val r0 = DoubleArray(NaoPreset.CHANNELS) { 8.0 + 4.0 * random.nextDouble() }
        val gestures = NaoPreset.LABELS.dropLast(1)
        val order = (0 until takes).flatMap { gestures }.toMutableList()
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        val pressure = ArrayList<DoubleArray>()
        val spans = ArrayList<NaoSpan>()
        fun rest(seconds: Double) = repeat((seconds * NaoPreset.SAMPLE_RATE).toInt()) { pressure += DoubleArray(NaoPreset.CHANNELS) }
        rest(2.0)
        for (label in order) {
            val (gesture, intensity) = label.split('-')
            val energetic = intensity == "energetic"
            val scale = force * (if (energetic) 1.8 else 1.0) * (0.8 + 0.4 * random.nextDouble())
            val pace = tempo * (if (energetic) 1.5 else 1.0) * (0.8 + 0.4 * random.nextDouble())
            val seconds = 3.0 + 2.0 * random.nextDouble()
            val frames = (seconds * NaoPreset.SAMPLE_RATE).toInt()
            val start = pressure.size
            val focus = random.nextInt(NaoPreset.CHANNELS)
            var tickleChannel = focus
            for (k in 0 until frames) {
                val t = k / NaoPreset.SAMPLE_RATE * pace
                val p = DoubleArray(NaoPreset.CHANNELS)
                when (gesture) {
                    "hit" -> { val v = 3.0 * scale * halfSine(t % 0.7, 0.12); p[focus] = v; p[(focus + 1) % 4] = 0.7 * v }
                    "poke" -> p[focus] = 1.5 * scale * halfSine(t % 0.8, 0.2)
                    "squeeze" -> { val v = 2.5 * scale * plateau(t % 1.8, 0.3, 1.2); for (c in 0 until 4) p[c] = v * (0.85 + 0.05 * c) }
                    "stroke" -> { val phase = t % 1.2; for (c in 0 until 4) p[c] = 1.0 * scale * exp(-sq((phase - 0.2 * c - 0.1) / 0.12)) }
                    "tickle" -> {
                        val tap = t % (1.0 / 6.0)
                        if (tap < 1.0 / NaoPreset.SAMPLE_RATE * pace) tickleChannel = random.nextInt(4)
                        p[tickleChannel] = 0.6 * scale * halfSine(tap, 0.08)
                    }
                }
                pressure += p
            }
            spans += NaoSpan(start, pressure.size, label)
            rest(1.5 + 1.5 * random.nextDouble())
        }
        val channels = List(NaoPreset.CHANNELS) { c ->
            DoubleArray(pressure.size) { k -> r0[c] / (1.0 + pressure[k][c]) * (1.0 + 0.01 * gaussian(random)) }
        }
        return NaoRecording(person, channels, spans)
    }

    private fun halfSine(t: Double, length: Double): Double = if (t < length) sin(PI * t / length) else 0.0

    private fun plateau(t: Double, rise: Double, hold: Double): Double = when {
        t < rise -> t / rise
        t < rise + hold -> 1.0
        t < 2 * rise + hold -> 1.0 - (t - rise - hold) / rise
        else -> 0.0
    }

    private fun sq(x: Double) = x * x

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; 1 − u keeps the logarithm finite.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * kotlin.math.ln(u)) * kotlin.math.cos(2 * PI * random.nextDouble())
    }
}
