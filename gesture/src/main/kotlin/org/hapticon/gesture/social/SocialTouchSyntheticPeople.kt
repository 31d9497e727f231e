package org.hapticon.gesture.social

import java.util.SplittableRandom
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.ln
import kotlin.math.sin
import kotlin.math.sqrt

/** One touch message: [person] gave [label]; [frames] is its contact stream. */
public class SocialTouchMessage(public val person: String, public val label: String, public val frames: List<ContactFrame>)

/**
 * Deterministic simulated people giving the [SocialTouchClasses] on a contact surface sampled at [SAMPLE_RATE]
 * (a touchscreen's rate), for `hapticon replicate 001` and the tests. **Simulated, not the paper's data:** the
 * EIT-skin paper's recordings are not published; these people stand in so the pipeline (13 features, LogitBoost,
 * both evaluations) runs end to end, and the accuracies they give say how separable *these* prototypes are, not
 * how well the paper's participants could be told apart.
 *
 * Each class is a prototype ([Prototype]): a number of touches, each of a duration, peak intensity (0..1 of the
 * sensor's range), contact area (0..1), rise and fall times, a position (x, y in 0..1 along and around the arm), a
 * travel along x (stroking) and a tremor or shake. The prototypes follow the kinds of touch people use for these
 * messages in the social-touch literature the paper builds on (hitting and slapping for anger and animosity,
 * patting and stroking for sympathy and affection, holding for acceptance, pushing away for rejection and
 * disgust, tapping for attention); their numbers are ours. Per person: a force scale 0.6–1.4, a tempo 0.7–1.3
 * and a position bias of ±0.15; per message every duration, intensity and area varies ±40 %, the number of
 * touches is one more or fewer in [TOUCH_COUNT_SLIP] of messages, and every frame's intensity has 3 % noise. A session is every class [takesPerClass] times in shuffled order (the paper's
 * participants gave each class 50 times in random order). [SocialTouchClasses.NO_TOUCH] is [NO_TOUCH_SECONDS] of
 * frames without contact.
 */
public object SocialTouchSyntheticPeople {
    /** Frames per second of the simulated contact stream. */
    public const val SAMPLE_RATE: Double = 100.0

    /** Length of a no-touch message, and the silence before and after every message's touches. */
    public const val NO_TOUCH_SECONDS: Double = 2.0

    /**
     * A class's touches: [touches] touches of [seconds] each, [gapSeconds] apart, at [intensity] over [area], rising
     * in [riseSeconds] and falling in [fallSeconds], centred at ([x], [y]) and travelling [travel] along x during a
     * touch, with a [shakeHz] modulation of relative depth [shakeDepth].
     */
    public class Prototype(
        public val touches: Int,
        public val seconds: Double,
        public val gapSeconds: Double,
        public val intensity: Double,
        public val area: Double,
        public val riseSeconds: Double,
        public val fallSeconds: Double,
        public val x: Double,
        public val y: Double,
        public val travel: Double = 0.0,
        public val shakeHz: Double = 0.0,
        public val shakeDepth: Double = 0.0,
    )

    /** The prototype of each class of [SocialTouchClasses.ALL] except no touch. */
    public val PROTOTYPES: Map<String, Prototype> = mapOf(
        // Emotions.
        "anger" to Prototype(3, 0.15, 0.25, 0.95, 0.55, 0.02, 0.03, 0.5, 0.5),
        "disgust" to Prototype(1, 0.40, 0.0, 0.60, 0.40, 0.05, 0.02, 0.75, 0.5, travel = 0.15),
        "fear" to Prototype(1, 1.50, 0.0, 0.70, 0.60, 0.15, 0.15, 0.4, 0.5, shakeHz = 8.0, shakeDepth = 0.15),
        "happiness" to Prototype(4, 0.12, 0.20, 0.50, 0.30, 0.03, 0.03, 0.5, 0.4),
        "sadness" to Prototype(2, 1.20, 0.50, 0.30, 0.50, 0.40, 0.40, 0.3, 0.5, travel = 0.3),
        "sympathy" to Prototype(3, 0.50, 0.40, 0.35, 0.45, 0.10, 0.10, 0.5, 0.6, travel = 0.1),
        // Social messages.
        "acceptance" to Prototype(1, 2.00, 0.0, 0.40, 0.70, 0.40, 0.40, 0.5, 0.5),
        "affection" to Prototype(3, 0.80, 0.30, 0.30, 0.40, 0.15, 0.15, 0.3, 0.5, travel = 0.4),
        "animosity" to Prototype(2, 0.08, 0.40, 0.90, 0.80, 0.01, 0.02, 0.5, 0.5),
        "attention-getting" to Prototype(3, 0.07, 0.15, 0.45, 0.15, 0.01, 0.01, 0.8, 0.3),
        "greeting" to Prototype(1, 0.90, 0.0, 0.55, 0.60, 0.10, 0.10, 0.85, 0.5, shakeHz = 2.0, shakeDepth = 0.3),
        "rejection" to Prototype(1, 0.30, 0.0, 0.75, 0.50, 0.03, 0.05, 0.6, 0.5, travel = 0.2),
    )

    /**
     * [people] simulated people (`p1`, `p2`, …), each giving every class of [labels] [takesPerClass] times in
     * shuffled order; repeatable for a [seed]. [labels] must be [SocialTouchClasses.ALL] members.
     */
    public fun messages(people: Int, takesPerClass: Int, seed: Long = 1L, labels: List<String> = SocialTouchClasses.ALL): List<SocialTouchMessage> {
        require(people >= 1 && takesPerClass >= 1) { "need at least one person and one take, got $people and $takesPerClass" }
        require(labels.isNotEmpty() && labels.all { it == SocialTouchClasses.NO_TOUCH || it in PROTOTYPES }) {
            "unknown classes: ${labels.filter { it != SocialTouchClasses.NO_TOUCH && it !in PROTOTYPES }}"
        }
        val random = SplittableRandom(seed)
        return (1..people).flatMap { person("p$it", labels, takesPerClass, random.split()) }
    }

    /** The 13 [SocialTouchFeatures] of every message, labelled by its index in [labels], with its person. */
    public fun features(messages: List<SocialTouchMessage>, labels: List<String>): TouchMessages = TouchMessages(
        messages.map { SocialTouchFeatures.of(it.frames.asSequence()) },
        IntArray(messages.size) { i -> labels.indexOf(messages[i].label).also { require(it >= 0) { "label ${messages[i].label} not in $labels" } } },
        messages.map { it.person },
        labels.size,
    )

    private fun person(name: String, labels: List<String>, takes: Int, random: SplittableRandom): List<SocialTouchMessage> {
        val force = 0.6 + 0.8 * random.nextDouble()
        val tempo = 0.7 + 0.6 * random.nextDouble()
        val biasX = 0.3 * random.nextDouble() - 0.15
        val biasY = 0.3 * random.nextDouble() - 0.15
        val order = (0 until takes).flatMap { labels }.toMutableList()
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        return order.map { label ->
            val prototype = PROTOTYPES[label]
            val frames = if (prototype == null) silence(NO_TOUCH_SECONDS) else message(prototype, force, tempo, biasX, biasY, random)
            SocialTouchMessage(name, label, frames)
        }
    }

    private fun silence(seconds: Double): List<ContactFrame> =
        List((seconds * SAMPLE_RATE).toInt()) { ContactFrame(it / SAMPLE_RATE, 0.0, 0.0, 0.0, 0.0) }

    private fun message(p: Prototype, force: Double, tempo: Double, biasX: Double, biasY: Double, random: SplittableRandom): List<ContactFrame> {
        fun vary() = 0.6 + 0.8 * random.nextDouble()
        // One touch more or fewer now and then: people do not count their pats.
        val touches = maxOf(1, p.touches + if (random.nextDouble() < TOUCH_COUNT_SLIP) (if (random.nextBoolean()) 1 else -1) else 0)
        val intensity = (p.intensity * force * vary()).coerceAtMost(1.0)
        val area = (p.area * vary()).coerceAtMost(1.0)
        val seconds = p.seconds / tempo * vary()
        val gap = p.gapSeconds / tempo * vary()
        val rise = minOf(p.riseSeconds / tempo, seconds / 2)
        val fall = minOf(p.fallSeconds / tempo, seconds / 2)
        val frames = ArrayList<ContactFrame>()
        fun at(time: Double) = Math.round(time * SAMPLE_RATE)
        val lead = at(NO_TOUCH_SECONDS / 4)
        for (k in 0 until lead) frames += ContactFrame(k / SAMPLE_RATE, 0.0, 0.0, 0.0, 0.0)
        var t = lead / SAMPLE_RATE
        for (touch in 0 until touches) {
            val n = maxOf(1L, at(seconds))
            for (k in 0 until n) {
                val u = k / SAMPLE_RATE
                val shape = minOf(1.0, (u + 1 / SAMPLE_RATE) / maxOf(rise, 1 / SAMPLE_RATE), (seconds - u) / maxOf(fall, 1 / SAMPLE_RATE)).coerceAtLeast(0.05)
                val shake = 1.0 + p.shakeDepth * sin(2 * PI * p.shakeHz * u)
                val noise = 1.0 + 0.03 * gaussian(random)
                val x = (p.x + biasX + p.travel * (u / seconds - 0.5)).coerceIn(0.0, 1.0)
                val y = (p.y + biasY).coerceIn(0.0, 1.0)
                frames += ContactFrame(t + u, (intensity * shape * shake * noise).coerceAtLeast(1e-3), x, y, area * (0.5 + 0.5 * shape))
            }
            t += n / SAMPLE_RATE
            // The gap (and a final frame of no contact) between touches.
            val pause = if (touch < touches - 1) maxOf(1L, at(gap)) else at(NO_TOUCH_SECONDS / 4)
            for (k in 0 until pause) frames += ContactFrame(t + k / SAMPLE_RATE, 0.0, 0.0, 0.0, 0.0)
            t += pause / SAMPLE_RATE
        }
        return frames
    }

    /** How often a message has one touch more or fewer than its prototype. */
    public const val TOUCH_COUNT_SLIP: Double = 0.3

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; 1 − u keeps the logarithm finite.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * ln(u)) * cos(2 * PI * random.nextDouble())
    }
}
