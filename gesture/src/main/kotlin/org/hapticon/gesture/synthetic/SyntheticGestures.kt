package org.hapticon.gesture.synthetic

import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.Gesture
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.Intensity
import org.hapticon.gesture.recognition.LabelledRecording
import org.hapticon.gesture.recognition.LabelledSpan
import java.util.SplittableRandom
import kotlin.math.PI
import kotlin.math.exp
import kotlin.math.sin
import kotlin.math.sqrt

/**
 * One simulated person's style: [forceScale] multiplies every force, [tempo] every speed (> 1 is quicker),
 * [forceNoise] (N) and [accelNoise] (g) are the white-noise levels of the sensors, and a physiological tremor
 * of [tremorHz] Hz and [tremorNewtons] N rides on every touch. [tilt] is how the device lies in their hand
 * (the gravity direction, x and y components in g). Their habits: strokes swell at [strokeHz] and taps
 * (hit, knock) last [tapSeconds] at their own tempo. [seed] makes their recordings repeatable.
 */
public class SimulatedPerson(
    public val id: Int,
    public val forceScale: Double,
    public val tempo: Double,
    public val forceNoise: Double,
    public val accelNoise: Double,
    public val tremorHz: Double,
    public val tremorNewtons: Double,
    public val tilt: Pair<Double, Double>,
    public val strokeHz: Double,
    public val tapSeconds: Double,
    public val seed: Long,
) {
    override fun toString(): String = "person $id (force ×%.2f, tempo ×%.2f)".format(forceScale, tempo)
}

/** One synthetic take: the labelled recording, and where the gesture starts (frame) — NONE takes have none. */
public class SyntheticTake(public val labelled: LabelledRecording, public val label: GestureLabel, public val onsetFrame: Int?)

/**
 * Deterministic touch gestures of simulated people, sampled at [SAMPLE_RATE] Hz as [CHANNELS]: an FSR force
 * in N (never negative, saturating at [FSR_MAX_NEWTONS]) and a three-axis accelerometer in g (gravity plus
 * motion). How each label is modelled (times are divided by the person's tempo and by [ENERGETIC_SPEED]
 * when energetic; forces are multiplied by the person's force scale and by [ENERGETIC_FORCE] when energetic;
 * every take varies force by −20..+25 % and speed by −15..+20 %, so a strong person's gentle gesture can
 * be as forceful as a weak person's energetic one):
 * - **stroke**: ~2.4 s of moderate force (2.5 N) that rises and falls over 0.3 s and swells ±30 % at the
 *   person's slow stroke rate (0.5–1.2 Hz), while the hand slides back and forth (0.15 g sinusoid on x);
 * - **hit**: one or two short, high peaks (half-sines of 1.5 × the person's tap length, 12 N) 0.2 s apart,
 *   each with a hard jolt on z (−0.8 g) ringing at 15 Hz;
 * - **knock**: 2–4 sharp taps (half-sines of the person's tap length, 30–80 ms, 4 N) 0.25 s apart, each
 *   with a small z jolt (0.3 g);
 * - **hug**: a long high plateau (10 N for ~2.2 s, 0.4 s rise and fall) with a slow sway (0.04 g on y);
 * - **none**: 3 s of the hand resting: sensor noise, a slow random drift of the force baseline (< 0.5 N)
 *   and of the tilt, handling sway (0.03 g) and 0–2 soft grip adjustments (0.3–1.5 N over 0.3–0.8 s).
 * Tremor (force) and sensor noise are added to every take, rest included.
 */
public object SyntheticGestures {
    public const val SAMPLE_RATE: Double = 100.0
    public const val FSR_MAX_NEWTONS: Double = 40.0

    /** Energetic gestures are this much stronger than gentle ones... */
    public const val ENERGETIC_FORCE: Double = 1.8

    /** ...and this much quicker. */
    public const val ENERGETIC_SPEED: Double = 1.4
    public val CHANNELS: List<String> = listOf("force", "accel_x", "accel_y", "accel_z")

    /** [count] people with styles drawn from [seed]. */
    public fun people(count: Int, seed: Long = 1L): List<SimulatedPerson> {
        require(count >= 1) { "need at least one person, was $count" }
        val random = SplittableRandom(seed)
        return List(count) { id ->
            SimulatedPerson(
                id = id,
                forceScale = random.nextDouble(0.7, 1.4),
                tempo = random.nextDouble(0.7, 1.4),
                forceNoise = random.nextDouble(0.05, 0.3),
                accelNoise = random.nextDouble(0.01, 0.04),
                tremorHz = random.nextDouble(4.0, 9.0),
                tremorNewtons = random.nextDouble(0.05, 0.5),
                tilt = random.nextDouble(-0.3, 0.3) to random.nextDouble(-0.3, 0.3),
                strokeHz = random.nextDouble(0.5, 1.2),
                tapSeconds = random.nextDouble(0.03, 0.08),
                seed = random.nextLong(),
            )
        }
    }

    /**
     * Take number [take] of [person] performing [label], with rest before (0.6–1.0 s) and after (at least
     * [minRestAfterSeconds]); a NONE take is 3 s of rest. The same arguments always give the same samples.
     */
    public fun perform(person: SimulatedPerson, label: GestureLabel, take: Int, minRestAfterSeconds: Double = 0.6): SyntheticTake {
        val random = SplittableRandom(person.seed * 1_000_003L + label.index * 7919L + take)
        val before = random.nextDouble(0.6, 1.0)
        val gesture = label.gesture
        val energetic = label.intensity == Intensity.ENERGETIC
        val speed = person.tempo * (if (energetic) ENERGETIC_SPEED else 1.0) * random.nextDouble(0.85, 1.2)
        val force = person.forceScale * (if (energetic) ENERGETIC_FORCE else 1.0) * random.nextDouble(0.8, 1.25)
        val shape = if (gesture == null) GripAdjustments(3.0, person.forceScale, random) else GestureShape.of(gesture, person, speed, force, random)
        val active = if (gesture == null) 0.0 else shape.seconds
        val total = if (gesture == null) 3.0 else before + active + minRestAfterSeconds + random.nextDouble(0.0, 0.4)
        val frames = (total * SAMPLE_RATE).toInt()
        val onset = if (gesture == null) 0 else (before * SAMPLE_RATE).toInt()
        val recording = record(person, frames, onset, shape, random)
        val spans = if (gesture == null) emptyList() else listOf(LabelledSpan(onset, minOf(frames, onset + maxOf(1, (active * SAMPLE_RATE).toInt())), label))
        return SyntheticTake(LabelledRecording(recording, spans), label, onset.takeIf { gesture != null })
    }

    /** [takes] takes of every one of the nine labels by [person]. */
    public fun takesOf(person: SimulatedPerson, takes: Int): List<SyntheticTake> =
        GestureLabel.ALL.flatMap { label -> (0 until takes).map { perform(person, label, it) } }

    /** [takes] one after another as a single stream, with each gesture's span shifted into it. */
    public fun concatenate(takes: List<SyntheticTake>): LabelledRecording {
        require(takes.isNotEmpty()) { "nothing to concatenate" }
        val channels = CHANNELS.indices.map { c ->
            val first = takes[0].labelled.recording.channels[c]
            Channel(first.name, first.unit, takes.flatMap { it.labelled.recording.channels[c].toDoubleArray().asList() }.toDoubleArray())
        }
        val spans = ArrayList<LabelledSpan>()
        var offset = 0
        for (take in takes) {
            for (span in take.labelled.spans) spans += LabelledSpan(offset + span.from, offset + span.to, span.label)
            offset += take.labelled.recording.frameCount
        }
        return LabelledRecording(Recording(SAMPLE_RATE, channels), spans)
    }

    private fun record(person: SimulatedPerson, frames: Int, onset: Int, shape: GestureShape, random: SplittableRandom): Recording {
        val force = DoubleArray(frames)
        val ax = DoubleArray(frames)
        val ay = DoubleArray(frames)
        val az = DoubleArray(frames)
        var drift = 0.0
        var tiltDrift = 0.0
        val tremorPhase = random.nextDouble(0.0, 2 * PI)
        for (i in 0 until frames) {
            val t = i / SAMPLE_RATE
            drift = (drift + gaussian(random) * 0.01).coerceIn(0.0, 0.5)
            tiltDrift = (tiltDrift + gaussian(random) * 0.002).coerceIn(-0.05, 0.05)
            val local = (i - onset) / SAMPLE_RATE
            val motion = if (local >= 0.0 && local < shape.seconds) shape.at(local) else Sample.REST
            val touching = motion.force > 0.05
            val tremor = if (touching) person.tremorNewtons * sin(2 * PI * person.tremorHz * t + tremorPhase) else 0.0
            force[i] = (drift + motion.force + tremor + gaussian(random) * person.forceNoise).coerceIn(0.0, FSR_MAX_NEWTONS)
            val (gx, gy) = person.tilt
            ax[i] = gx + tiltDrift + motion.x + gaussian(random) * person.accelNoise
            ay[i] = gy + motion.y + gaussian(random) * person.accelNoise
            az[i] = sqrt(1.0 - gx * gx - gy * gy) + motion.z + gaussian(random) * person.accelNoise
        }
        return Recording(
            SAMPLE_RATE,
            listOf(Channel(CHANNELS[0], "N", force), Channel(CHANNELS[1], "g", ax), Channel(CHANNELS[2], "g", ay), Channel(CHANNELS[3], "g", az)),
        )
    }

    private fun gaussian(random: SplittableRandom): Double {
        // Box–Muller; one of the pair is enough here.
        val u = 1.0 - random.nextDouble()
        return sqrt(-2.0 * kotlin.math.ln(u)) * kotlin.math.cos(2 * PI * random.nextDouble())
    }
}

/** Force (N) and motion acceleration (g) at one instant of a gesture. */
internal class Sample(val force: Double, val x: Double, val y: Double, val z: Double) {
    companion object {
        val REST = Sample(0.0, 0.0, 0.0, 0.0)
    }
}

/** A gesture's time course: [seconds] long, [at] gives the force and motion at a time into it. */
internal abstract class GestureShape(val seconds: Double) {
    abstract fun at(t: Double): Sample

    companion object {
        fun of(gesture: Gesture, person: SimulatedPerson, speed: Double, force: Double, random: SplittableRandom): GestureShape = when (gesture) {
            Gesture.STROKE -> Stroke(2.4 / speed, person.strokeHz * speed, force)
            Gesture.HIT -> Taps(count = 1 + random.nextInt(2), spacing = 0.2 / speed, width = 1.5 * person.tapSeconds / speed, peak = 12.0 * force, jolt = -0.8 * force, ring = 15.0)
            Gesture.KNOCK -> Taps(count = 2 + random.nextInt(3), spacing = 0.25 / speed, width = person.tapSeconds / speed, peak = 4.0 * force, jolt = -0.3 * force, ring = 25.0)
            Gesture.HUG -> Hug(rise = 0.4 / speed, plateau = 2.2 / speed, force = 10.0 * force, speed = speed)
        }
    }
}

private fun ramp(t: Double, seconds: Double, rise: Double): Double = when {
    t < rise -> t / rise
    t > seconds - rise -> ((seconds - t) / rise).coerceAtLeast(0.0)
    else -> 1.0
}

private class Stroke(seconds: Double, private val hz: Double, private val force: Double) : GestureShape(seconds) {
    override fun at(t: Double): Sample {
        val phase = 2 * PI * hz * t
        val envelope = ramp(t, seconds, 0.3)
        return Sample(2.5 * force * envelope * (1 + 0.3 * sin(phase)), 0.15 * force * envelope * sin(phase), 0.0, 0.0)
    }
}

private class Taps(
    private val count: Int,
    private val spacing: Double,
    private val width: Double,
    private val peak: Double,
    private val jolt: Double,
    private val ring: Double,
) : GestureShape((count - 1) * spacing + width + 0.15) {
    override fun at(t: Double): Sample {
        var force = 0.0
        var z = 0.0
        for (k in 0 until count) {
            val local = t - k * spacing
            if (local < 0.0) continue
            if (local < width) force += peak * sin(PI * local / width)
            z += jolt * exp(-local / 0.04) * kotlin.math.cos(2 * PI * ring * local)
        }
        return Sample(force, 0.0, 0.0, z)
    }
}

/** The hand resting on the device: 0–2 soft grip adjustments (0.3–1.5 N for 0.3–0.8 s) and slight handling motion. */
private class GripAdjustments(seconds: Double, forceScale: Double, random: SplittableRandom) : GestureShape(seconds) {
    private val starts = DoubleArray(random.nextInt(3)) { random.nextDouble(0.0, seconds - 0.8) }
    private val lengths = DoubleArray(starts.size) { random.nextDouble(0.3, 0.8) }
    private val forces = DoubleArray(starts.size) { random.nextDouble(0.3, 1.5) * forceScale }
    private val swayHz = random.nextDouble(0.2, 1.0)

    override fun at(t: Double): Sample {
        var force = 0.0
        for (k in starts.indices) {
            val local = t - starts[k]
            if (local >= 0.0 && local < lengths[k]) force += forces[k] * sin(PI * local / lengths[k])
        }
        return Sample(force, 0.03 * sin(2 * PI * swayHz * t), 0.02 * sin(2 * PI * swayHz * 0.7 * t + 1.0), 0.0)
    }
}

private class Hug(private val rise: Double, plateau: Double, private val force: Double, private val speed: Double) :
    GestureShape(2 * rise + plateau) {
    override fun at(t: Double): Sample {
        val envelope = ramp(t, seconds, rise)
        return Sample(force * envelope, 0.0, 0.04 * envelope * sin(2 * PI * 0.5 * speed * t), 0.0)
    }
}
