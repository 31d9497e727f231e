package org.hapticon.gesture.social

/**
 * One frame of a contact stream: at [timeSeconds], contact of [intensity] (pressure in the sensor's unit; 0 or
 * less = no contact) centred at ([x], [y]) (normalised 0..1 across the surface) over [area] (the sensor's area
 * unit). A phone's touchscreen gives pressure, position and touch major × minor; a pressure grid gives the sum
 * of its cells, their intensity-weighted centroid and the number of active cells.
 */
public data class ContactFrame(val timeSeconds: Double, val intensity: Double, val x: Double, val y: Double, val area: Double)

/**
 * The 13 features of one touch message, after the EIT-skin social-touch paper's Table 1: its feature groups are
 * pressure intensity (maxima and minima), location, contact area, touch duration, the maximum rates of intensity
 * rise and fall, and the touch count, with the touches of one message averaged. Our 13, in [NAMES] order, each
 * averaged over the message's touches unless it says otherwise:
 *
 *  1. `intensity_max` — a touch's highest intensity;
 *  2. `intensity_min` — a touch's lowest intensity while in contact;
 *  3. `intensity_mean` — a touch's mean intensity;
 *  4. `x`, 5. `y` — a touch's intensity-weighted mean position;
 *  6. `area_max`, 7. `area_mean` — a touch's largest and mean contact area;
 *  8. `duration_s` — from a touch's first to its last contact frame;
 *  9. `rise_max` — a touch's fastest intensity rise, units/s (including the step from no contact);
 * 10. `fall_max` — a touch's fastest intensity fall, units/s (including the step to no contact);
 * 11. `touch_count` — the message's number of touches (not averaged);
 * 12. `message_s` — first contact to last contact of the message (not averaged);
 * 13. `gap_mean_s` — mean time between one touch's end and the next one's start (0 with fewer than 2 touches).
 *
 * The groups are the paper's; the exact split into 13 (which statistics of intensity and area, the two timing
 * features 12–13) is our reading and was not re-checked against the table's rows.
 *
 * A touch is a maximal run of frames with intensity > 0. Frames must come in time order; non-finite frames are
 * skipped and counted. Streaming and O(1) in memory, so an hour-long stream costs nothing more than its frames.
 * An empty stream (or no contact) gives all zeros.
 */
public class SocialTouchFeatures {
    private var touches = 0
    private var inTouch = false
    private var skipped = 0L
    // Per-message sums of per-touch values.
    private val sums = DoubleArray(10)
    // The running touch.
    private var tMax = 0.0; private var tMin = 0.0; private var tSum = 0.0; private var tFrames = 0L
    private var tWx = 0.0; private var tWy = 0.0; private var tW = 0.0; private var tX = 0.0; private var tY = 0.0
    private var tAreaMax = 0.0; private var tAreaSum = 0.0
    private var tStart = 0.0; private var tRise = 0.0; private var tFall = 0.0
    private var lastTime = Double.NaN
    private var lastIntensity = 0.0
    private var firstContact = Double.NaN
    private var lastContact = Double.NaN
    private var gapSum = 0.0

    /** Frames skipped for a non-finite field or for going back in time. */
    public val skippedFrames: Long get() = skipped

    /** Feeds one frame. */
    public fun offer(frame: ContactFrame) {
        val t = frame.timeSeconds
        if (!(t.isFinite() && frame.intensity.isFinite() && frame.x.isFinite() && frame.y.isFinite() && frame.area.isFinite()) || t < lastTime) {
            skipped++
            return
        }
        val dt = if (lastTime.isNaN()) 0.0 else t - lastTime
        val intensity = maxOf(frame.intensity, 0.0)
        if (intensity > 0.0) {
            if (!inTouch) {
                if (!lastContact.isNaN()) gapSum += t - lastContact
                startTouch(t, intensity, frame)
            } else {
                addToTouch(intensity, frame)
            }
            if (dt > 0.0) {
                val rate = (intensity - lastIntensity) / dt
                if (rate > tRise) tRise = rate
                if (-rate > tFall) tFall = -rate
            }
            lastContact = t
        } else if (inTouch) {
            if (dt > 0.0 && lastIntensity / dt > tFall) tFall = lastIntensity / dt
            endTouch()
        }
        lastIntensity = intensity
        lastTime = t
    }

    private fun startTouch(t: Double, intensity: Double, frame: ContactFrame) {
        inTouch = true
        if (firstContact.isNaN()) firstContact = t
        tStart = t
        tMax = intensity; tMin = intensity; tSum = 0.0; tFrames = 0
        tWx = 0.0; tWy = 0.0; tW = 0.0; tAreaMax = 0.0; tAreaSum = 0.0
        // A touch starting from no contact rises by its first intensity over one frame step.
        val dt = if (lastTime.isNaN()) 0.0 else t - lastTime
        tRise = if (dt > 0.0) intensity / dt else 0.0
        tFall = 0.0
        addToTouch(intensity, frame)
    }

    private fun addToTouch(intensity: Double, frame: ContactFrame) {
        if (intensity > tMax) tMax = intensity
        if (intensity < tMin) tMin = intensity
        tSum += intensity
        tFrames++
        tWx += intensity * frame.x; tWy += intensity * frame.y; tW += intensity
        tX = frame.x; tY = frame.y
        if (frame.area > tAreaMax) tAreaMax = frame.area
        tAreaSum += frame.area
    }

    private fun endTouch() {
        inTouch = false
        touches++
        sums[0] += tMax; sums[1] += tMin; sums[2] += tSum / tFrames
        sums[3] += tWx / tW; sums[4] += tWy / tW
        sums[5] += tAreaMax; sums[6] += tAreaSum / tFrames
        sums[7] += lastContact - tStart
        sums[8] += tRise; sums[9] += tFall
    }

    /** The 13 features of everything offered so far (a touch still in contact counts as ended). */
    public fun features(): DoubleArray {
        val out = DoubleArray(COUNT)
        val wasInTouch = inTouch
        val saved = sums.copyOf()
        val savedTouches = touches
        if (wasInTouch) endTouch()
        if (touches > 0) {
            for (k in 0 until 10) out[k] = sums[k] / touches
            out[10] = touches.toDouble()
            out[11] = lastContact - firstContact
            out[12] = if (touches > 1) gapSum / (touches - 1) else 0.0
        }
        // Leave the running state as it was: more frames may follow.
        saved.copyInto(sums)
        touches = savedTouches
        inTouch = wasInTouch
        return out
    }

    public companion object {
        /** Features per message. */
        public const val COUNT: Int = 13

        /** The feature names, in output order. */
        public val NAMES: List<String> = listOf(
            "intensity_max", "intensity_min", "intensity_mean", "x", "y", "area_max", "area_mean",
            "duration_s", "rise_max", "fall_max", "touch_count", "message_s", "gap_mean_s",
        )

        /** The features of a whole [stream]. */
        public fun of(stream: Sequence<ContactFrame>): DoubleArray {
            val features = SocialTouchFeatures()
            for (frame in stream) features.offer(frame)
            return features.features()
        }
    }
}
