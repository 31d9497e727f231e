package org.hapticon.gesture.social

import java.util.SplittableRandom
import kotlin.math.PI
import kotlin.math.exp
import kotlin.math.roundToLong
import kotlin.math.sin

/**
 * One touch message: [person] gave [label]; [frames] regenerates its skin frames (on [SocialTouchSyntheticPeople.LAYOUT])
 * each time it is called, so a session of thousands of messages holds no images.
 */
public class SocialTouchMessage(public val person: String, public val label: String, private val generate: () -> Sequence<SkinFrame>) {
    /** The message's frames, in time order. */
    public fun frames(): Sequence<SkinFrame> = generate()
}

/**
 * Deterministic simulated transmitters touching a simulated EIT skin, following the EIT-skin paper's protocols, for
 * `hapticon replicate 001` and the tests. **Simulated, not the paper's data:** its recordings are not published, so
 * the accuracies these people give say how separable *these* prototypes are, never how well the paper's participants
 * could be told apart; they are printed apart from the paper's figures.
 *
 * From the paper (`001_e790093bbd2e3cd3.txt`): 729 elements (:97), about 40 Hz (:91), the joint sensor (:79), the
 * protocols ([experiment1]: two transmitters × 13 classes × 50 in random order, :160, :164; [experiment2]: 42 × 13 ×
 * 5, :198, :202), the "no touch" class as touches too soft to detect (:152), and what each class looked like where
 * the paper says so (the prototypes' comments cite it). Ours (paper silent): the skin's geometry (a 27 × 27 grid,
 * x from wrist −1 through the elbow 0 to shoulder +1, y from the inner −1 to the outer side +1: the paper gives its
 * dimensions only in Fig. 2a), the image of a touch (a blob of the contact's radius whose surround dips below zero by
 * 30 % of a blob twice as wide, as a smoothed difference image does), every number in [PROTOTYPES], and the
 * variation: per transmitter and class a style — the way of a look-alike class ([LOOK_ALIKES]) [BORROW] of the time,
 * intensity and push ×0.5–1.5, duration ×0.5–1.8, place ±0.5 along and ±0.3 around the arm, one touch more or fewer
 * half the time — after the paper's hypothesis that gestures are "consistent during repetitions from a single
 * individual but quite variable across a range of individuals" (:156), and per message intensity ±25 %, duration
 * ±30 %, place ±0.12, one touch more or fewer in 20 % of messages.
 */
public object SocialTouchSyntheticPeople {
    /** Frames per second: "approximately 40 Hz" (001_e790093bbd2e3cd3.txt:91). */
    public const val SAMPLE_RATE: Double = 40.0

    /** Elements per side of the simulated skin: 27 × 27 = 729, the paper's element count (001_e790093bbd2e3cd3.txt:97). */
    public const val SIDE: Int = 27

    /** The simulated skin: origin at the elbow (001_e790093bbd2e3cd3.txt:108), x along the arm, y around it. */
    public val LAYOUT: SkinLayout = SkinLayout.grid(SIDE, SIDE, -1.0, 1.0, -1.0, 1.0)

    /** No contact before the first and after the last touch of a message. */
    public const val QUIET_SECONDS: Double = 0.5

    /** Intensity of a "no touch" message's contact: below [TouchThresholds.DEFAULT]'s 0.05. */
    public const val NO_TOUCH_INTENSITY: Double = 0.03

    /**
     * A class's touches: [touches] touches of [seconds], [gapSeconds] apart, peaking at [intensity] (0..1 of the
     * skin's range) over a contact of [radius] centred at ([x], [y]) and travelling [travel] along x, with the arm
     * [push]ed (+) or pulled (−) by that share of the intensity (the joint sensor) and a [shakeHz] modulation of
     * relative depth [shakeDepth].
     */
    public class Prototype(
        public val touches: Int,
        public val seconds: Double,
        public val gapSeconds: Double,
        public val intensity: Double,
        public val radius: Double,
        public val x: Double,
        public val y: Double,
        public val travel: Double = 0.0,
        public val push: Double = 0.0,
        public val shakeHz: Double = 0.0,
        public val shakeDepth: Double = 0.0,
    )

    /**
     * Each class's prototype (all but no touch). Every class is given on the outer side of the arm (y > 0:
     * "all social messages and emotions were communicated to the outside of the arm", 001_e790093bbd2e3cd3.txt:288).
     */
    public val PROTOTYPES: Map<String, Prototype> = mapOf(
        // Squeezing and pushing (:301, :303), the highest pressures (:286), short (:289) yet longer than disgust (:303).
        "anger" to Prototype(2, 0.5, 0.3, 0.95, 0.25, 0.2, 0.5, push = 0.6),
        // Squeezing (:301), high pressure (:286), the largest displacements (:287).
        "fear" to Prototype(1, 1.5, 0.0, 0.85, 0.3, -0.2, 0.5, travel = 0.8, shakeHz = 6.0, shakeDepth = 0.2),
        // Stroking and scratching (:301).
        "happiness" to Prototype(3, 0.6, 0.2, 0.4, 0.15, 0.0, 0.6, travel = 0.3, shakeHz = 8.0, shakeDepth = 0.3),
        // Stroking (:301), the largest displacements (:287), a light touch of moderate duration (:35).
        "sadness" to Prototype(1, 2.5, 0.0, 0.3, 0.2, 0.1, 0.5, travel = 0.9),
        // Pushing (:303), short (:289).
        "disgust" to Prototype(1, 0.3, 0.0, 0.6, 0.2, -0.3, 0.4, push = 0.8),
        // Short (:289); the paper says nothing more of surprise: ours, a sudden grab.
        "surprise" to Prototype(1, 0.2, 0.0, 0.7, 0.2, 0.3, 0.5),
        // Tapping and patting (:301) at the shoulder (:290), short (:289), repeated (:291).
        "attention-getting" to Prototype(3, 0.12, 0.2, 0.5, 0.1, 0.85, 0.5),
        // Pulling and squeezing (:301) near the hand (:290).
        "greeting" to Prototype(1, 1.0, 0.0, 0.6, 0.25, -0.85, 0.5, push = -0.6, shakeHz = 2.0, shakeDepth = 0.3),
        // The paper says nothing of how acceptance was given: ours, a gentle hold.
        "acceptance" to Prototype(1, 1.8, 0.0, 0.4, 0.3, -0.5, 0.5),
        // Near the hand (:290), a negative touch (:240): ours, pushing the hand away.
        "rejection" to Prototype(1, 0.4, 0.0, 0.65, 0.2, -0.8, 0.5, push = 0.7),
        // Stroking and scratching (:301), repeated (:291).
        "affection" to Prototype(3, 1.0, 0.3, 0.3, 0.2, 0.0, 0.4, travel = 0.4),
        // A negative touch (:240): ours, hitting.
        "animosity" to Prototype(2, 0.1, 0.4, 0.9, 0.2, 0.1, 0.6, push = 0.4),
    )

    /** Experiment 1: Participants "A" and "B", every class 50 times in random order (001_e790093bbd2e3cd3.txt:160, :164). */
    public fun experiment1(seed: Long = 1L): List<SocialTouchMessage> =
        session(List(SocialTouchClasses.EXPERIMENT_1_TRANSMITTERS) { ('A' + it).toString() }, SocialTouchClasses.EXPERIMENT_1_TAKES_PER_CLASS, seed, SocialTouchClasses.ALL)

    /** Experiment 2: 42 transmitters `t01`…`t42`, every class five times in random order (001_e790093bbd2e3cd3.txt:198, :202). */
    public fun experiment2(seed: Long = 2L): List<SocialTouchMessage> =
        session(List(SocialTouchClasses.EXPERIMENT_2_TRANSMITTERS) { "t%02d".format(it + 1) }, SocialTouchClasses.EXPERIMENT_2_TAKES_PER_CLASS, seed, SocialTouchClasses.ALL)

    /**
     * [people] simulated people (`p1`, `p2`, …), each giving every class of [labels] [takesPerClass] times in shuffled
     * order; repeatable for a [seed]. [labels] must be [SocialTouchClasses.ALL] members.
     */
    public fun messages(people: Int, takesPerClass: Int, seed: Long = 1L, labels: List<String> = SocialTouchClasses.ALL): List<SocialTouchMessage> {
        require(people >= 1) { "need at least one person, got $people" }
        return session(List(people) { "p${it + 1}" }, takesPerClass, seed, labels)
    }

    /** The 13 [SocialTouchFeatures] of every message of a class in [labels] (others are left out), labelled by its index there. */
    public fun features(messages: List<SocialTouchMessage>, labels: List<String>): TouchMessages {
        val kept = messages.filter { it.label in labels }
        return TouchMessages(
            kept.map { SocialTouchFeatures.of(LAYOUT, it.frames()) },
            IntArray(kept.size) { labels.indexOf(kept[it].label) },
            kept.map { it.person },
            labels.size,
        )
    }

    private fun session(names: List<String>, takes: Int, seed: Long, labels: List<String>): List<SocialTouchMessage> {
        require(takes >= 1) { "need at least one take, got $takes" }
        require(labels.isNotEmpty() && labels.all { it == SocialTouchClasses.NO_TOUCH || it in PROTOTYPES }) {
            "unknown classes: ${labels.filter { it != SocialTouchClasses.NO_TOUCH && it !in PROTOTYPES }}"
        }
        val random = SplittableRandom(seed)
        return names.flatMap { person(it, labels, takes, random.split()) }
    }

    /**
     * Classes a transmitter may give the way another gives a look-alike, from the confusions the paper reports: anger,
     * fear and disgust (:240; anger and disgust both pushed, anger and fear both squeezed, :301, :303), rejection and
     * animosity (:240), acceptance and greeting (Participant B, :174), and the stroked happiness, sadness and affection
     * (:301).
     */
    public val LOOK_ALIKES: List<Set<String>> = listOf(
        setOf("anger", "fear", "disgust"),
        setOf("rejection", "animosity"),
        setOf("acceptance", "greeting"),
        setOf("happiness", "sadness", "affection"),
    )

    /** How often a transmitter gives a class the way of one of its [LOOK_ALIKES] (ours). */
    public const val BORROW: Double = 0.35

    /** One transmitter's way of giving a class (ours: see the class KDoc). */
    private class Style(val prototype: Prototype?, val intensity: Double, val seconds: Double, val dx: Double, val dy: Double, val touches: Int, val push: Double)

    private fun person(name: String, labels: List<String>, takes: Int, random: SplittableRandom): List<SocialTouchMessage> {
        val styles = labels.associateWith { label ->
            val alike = LOOK_ALIKES.firstOrNull { label in it }?.minus(label)?.sorted().orEmpty()
            val borrowed = if (alike.isNotEmpty() && random.nextDouble() < BORROW) alike[random.nextInt(alike.size)] else label
            val p = PROTOTYPES[borrowed]
            Style(
                prototype = p,
                intensity = between(random, 0.5, 1.5),
                seconds = between(random, 0.5, 1.8),
                dx = between(random, -0.5, 0.5),
                dy = between(random, -0.3, 0.3),
                touches = if (p != null && random.nextDouble() < 0.5) maxOf(1, p.touches + if (random.nextBoolean()) 1 else -1) else p?.touches ?: 1,
                push = between(random, 0.5, 1.5),
            )
        }
        val order = (0 until takes).flatMap { labels }.toMutableList()
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        return order.map { label ->
            val messageSeed = random.nextLong()
            val style = styles.getValue(label)
            SocialTouchMessage(name, label) {
                val prototype = style.prototype
                if (prototype == null) faint(SplittableRandom(messageSeed)) else message(prototype, style, SplittableRandom(messageSeed))
            }
        }
    }

    private fun between(random: SplittableRandom, a: Double, b: Double) = a + (b - a) * random.nextDouble()

    /** "No touch": a contact too soft to cross the threshold (001_e790093bbd2e3cd3.txt:152). */
    private fun faint(random: SplittableRandom): Sequence<SkinFrame> {
        val touch = Touch(
            start = QUIET_SECONDS, seconds = between(random, 0.3, 1.5), intensity = NO_TOUCH_INTENSITY * between(random, 0.5, 1.0),
            radius = 0.2, x = between(random, -0.8, 0.8), y = between(random, 0.2, 0.8), travel = 0.0, push = 0.0, shakeHz = 0.0, shakeDepth = 0.0,
        )
        return skinFrames(listOf(touch), touch.start + touch.seconds + QUIET_SECONDS)
    }

    private fun message(p: Prototype, style: Style, random: SplittableRandom): Sequence<SkinFrame> {
        val count = maxOf(1, style.touches + if (random.nextDouble() < 0.2) (if (random.nextBoolean()) 1 else -1) else 0)
        val intensity = (p.intensity * style.intensity * between(random, 0.75, 1.25)).coerceAtMost(1.0)
        val seconds = p.seconds * style.seconds * between(random, 0.7, 1.3)
        val gap = p.gapSeconds * style.seconds * between(random, 0.7, 1.3)
        val x = (p.x + style.dx + between(random, -0.12, 0.12)).coerceIn(-1.0, 1.0)
        val y = (p.y + style.dy + between(random, -0.12, 0.12)).coerceIn(-1.0, 1.0)
        var t = QUIET_SECONDS
        val touches = List(count) {
            Touch(t, seconds, intensity, p.radius, x, y, p.travel, p.push * style.push, p.shakeHz, p.shakeDepth).also { t += seconds + maxOf(gap, 2 / SAMPLE_RATE) }
        }
        return skinFrames(touches, touches.last().let { it.start + it.seconds } + QUIET_SECONDS)
    }

    private class Touch(
        val start: Double, val seconds: Double, val intensity: Double, val radius: Double, val x: Double, val y: Double,
        val travel: Double, val push: Double, val shakeHz: Double, val shakeDepth: Double,
    )

    /** Frames at [SAMPLE_RATE] from 0 to [end] s: each touch's blob where it is on, zeros elsewhere. */
    private fun skinFrames(touches: List<Touch>, end: Double): Sequence<SkinFrame> {
        val frames = (end * SAMPLE_RATE).roundToLong()
        return (0L..frames).asSequence().map { k ->
            val t = k / SAMPLE_RATE
            val elements = DoubleArray(LAYOUT.size)
            var joint = 0.0
            for (touch in touches) {
                val u = t - touch.start
                if (u < 0.0 || u > touch.seconds) continue
                // A trapezoid in time: a fifth of the touch (at least one frame) to rise and to fall.
                val ramp = maxOf(touch.seconds / 5, 1 / SAMPLE_RATE)
                val envelope = minOf(1.0, (u + 1 / SAMPLE_RATE) / ramp, (touch.seconds - u + 1 / SAMPLE_RATE) / ramp).coerceAtLeast(0.0)
                val shake = 1.0 + touch.shakeDepth * sin(2 * PI * touch.shakeHz * u)
                val a = touch.intensity * envelope * shake
                val cx = touch.x + touch.travel * (u / touch.seconds - 0.5)
                blob(elements, a, cx, touch.y, touch.radius)
                joint += touch.push * a
            }
            SkinFrame(t, elements, joint)
        }
    }

    /** Adds a blob of peak [a] at ([cx], [cy]) with radius [r], less 30 % of one twice as wide (a separable Gaussian per axis). */
    private fun blob(into: DoubleArray, a: Double, cx: Double, cy: Double, r: Double) {
        val gx = DoubleArray(SIDE); val gy = DoubleArray(SIDE); val hx = DoubleArray(SIDE); val hy = DoubleArray(SIDE)
        for (i in 0 until SIDE) {
            val dx = LAYOUT.x(i) - cx
            val dy = LAYOUT.y(i * SIDE) - cy
            gx[i] = exp(-dx * dx / (2 * r * r)); hx[i] = exp(-dx * dx / (8 * r * r))
            gy[i] = exp(-dy * dy / (2 * r * r)); hy[i] = exp(-dy * dy / (8 * r * r))
        }
        for (row in 0 until SIDE) for (column in 0 until SIDE) {
            into[row * SIDE + column] += a * (gx[column] * gy[row] - 0.3 * hx[column] * hy[row])
        }
    }
}
