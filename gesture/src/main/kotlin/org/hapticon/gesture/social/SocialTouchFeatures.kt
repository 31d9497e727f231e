package org.hapticon.gesture.social

import kotlin.math.abs
import kotlin.math.sqrt

/**
 * When a touch is on (the EIT-skin paper's segmentation, 001_e790093bbd2e3cd3.txt:101): "the beginning and end of each
 * touch was defined by a change in the intensity above (or below) a pre-defined threshold of a signal from either the
 * artificial skin or the shoulder joint sensor". A frame is in a touch while its largest element exceeds [skin] or the
 * joint's potential change exceeds [joint] in magnitude.
 *
 * The paper does not give the thresholds (paper silent): [DEFAULT] is 5 % of full scale for a skin and a joint scaled
 * 0..1 (above [SocialTouchSyntheticPeople]'s sub-threshold "no touch" contact), [ANY_CONTACT] any contact at all, for a
 * touchscreen, whose pressure is 0 off the glass.
 */
public class TouchThresholds(public val skin: Double, public val joint: Double) {
    init {
        require(skin >= 0.0 && skin.isFinite() && joint >= 0.0 && joint.isFinite()) { "thresholds must be finite and >= 0, got $skin and $joint" }
    }

    /** Whether a frame whose largest element is [skinMax] and whose joint change is [jointChange] is in a touch. */
    public fun on(skinMax: Double, jointChange: Double): Boolean = skinMax > skin || abs(jointChange) > joint

    public companion object {
        /** 0.05 of a 0..1 skin and joint. */
        public val DEFAULT: TouchThresholds = TouchThresholds(0.05, 0.05)

        /** Anything above 0 on the skin or the joint. */
        public val ANY_CONTACT: TouchThresholds = TouchThresholds(0.0, 0.0)
    }
}

/**
 * The 13 features of one touch message: the EIT-skin paper's Table 1, in its order and with its definitions
 * (001_e790093bbd2e3cd3.txt:111–124, defined at :107–110 and :128–130). Features 1–12 are measured per touch and
 * "if multiple touches were used to communicate a message, the average of their values was used"
 * (001_e790093bbd2e3cd3.txt:132); a touch is a run of frames that [thresholds] call on (:101).
 *
 *  1. `max_intensity` — the largest element value over the touch ("maximum … conductivity changes … over all finite
 *     elements", :107);
 *  2. `min_intensity` — the smallest element value over the touch (:107);
 *  3. `max_joint`, 4. `min_joint` — the joint sensor's largest and smallest potential change over the touch (:107);
 *  5. `x`, 6. `y` — the centroid of the elements holding at least 75 % of the image's maximum (:108), at the frame where
 *     the touch's maximum occurs (paper silent on the instant; ours: the same instant as feature 8, :109);
 *  7. `displacement` — the distance "from the initial to final locations of a touch" (:108): the 75 % centroids of the
 *     touch's first and last frames;
 *  8. `spatial_resolution` — at the instant of the maximum intensity, the number of elements holding at least 50 % of
 *     the maximum, as a ratio of all elements (:109, :128);
 *  9. `mean_spatial_resolution` — the same ratio averaged over the touch's frames (:128);
 * 10. `duration_s` — "the time taken from the beginning to the end of the touch" (:130): from the first frame on to the
 *     first frame off (to the last frame on if the stream ends first);
 * 11. `max_rise_rate`, 12. `max_fall_rate` — the largest increase and decrease of any element between adjoining frames,
 *     per second (:130), over the steps into, through and out of the touch;
 * 13. `touch_count` — "the number of sequential touches that constitute a particular message" (:130), not averaged.
 *
 * Paper silent, ours: the centroid counts each qualifying element once (not weighted by intensity, as "the centroid" of
 * the elements reads); an image whose maximum is not above 0 has no location (a touch seen by the joint sensor alone
 * is located at the origin, with resolution 0); a message with no touch gives 13 zeros (nothing crossed the threshold:
 * the paper's "no touch" class, :152).
 *
 * Frames must come in time order with [SkinLayout.size] elements; a frame that is shorter or longer, non-finite or
 * earlier than the last is skipped and counted. Streaming: memory is two frames' elements, whatever the stream's length.
 */
public class SocialTouchFeatures(private val layout: SkinLayout, private val thresholds: TouchThresholds = TouchThresholds.DEFAULT) {
    private val n = layout.size
    private var previous = DoubleArray(n)
    private var havePrevious = false
    private var lastTime = Double.NaN
    private var skipped = 0L

    private var touches = 0
    private val sums = DoubleArray(COUNT - 1)

    // The running touch.
    private var inTouch = false
    private var firstStart = Double.NaN
    private var start = 0.0
    private var lastOn = 0.0
    private var tMax = 0.0
    private var tMin = 0.0
    private var jMax = 0.0
    private var jMin = 0.0
    private var peakX = 0.0
    private var peakY = 0.0
    private var peakResolution = 0.0
    private var located = false
    private var firstX = 0.0
    private var firstY = 0.0
    private var lastX = 0.0
    private var lastY = 0.0
    private var resolutionSum = 0.0
    private var frames = 0L
    private var rise = 0.0
    private var fall = 0.0

    /** Frames skipped for a wrong element count, a non-finite value or going back in time. */
    public val skippedFrames: Long get() = skipped

    /** Touches ended or running so far. */
    public val touchCount: Int get() = touches + if (inTouch) 1 else 0

    /** Whether the last frame was in a touch. */
    public val inContact: Boolean get() = inTouch

    /** From the first touch's first frame to the last frame in a touch, seconds (0 without a touch). */
    public val contactSeconds: Double get() = if (firstStart.isNaN()) 0.0 else lastOn - firstStart

    /** Feeds one frame. */
    public fun offer(frame: SkinFrame) {
        val t = frame.timeSeconds
        val e = frame.elements
        if (e.size != n || !t.isFinite() || !frame.joint.isFinite() || t < lastTime || e.any { !it.isFinite() }) {
            skipped++
            return
        }
        var max = e[0]
        var min = e[0]
        for (k in 1 until n) {
            if (e[k] > max) max = e[k]
            if (e[k] < min) min = e[k]
        }
        val on = thresholds.on(max, frame.joint)
        if (on && !inTouch) startTouch(t)
        if (inTouch && havePrevious && t > lastTime) rates(e, t - lastTime)
        if (on) addFrame(t, e, max, min, frame.joint) else if (inTouch) endTouch(t)
        e.copyInto(previous)
        havePrevious = true
        lastTime = t
    }

    private fun startTouch(t: Double) {
        inTouch = true
        start = t
        if (firstStart.isNaN()) firstStart = t
        tMax = Double.NEGATIVE_INFINITY; tMin = Double.POSITIVE_INFINITY
        jMax = Double.NEGATIVE_INFINITY; jMin = Double.POSITIVE_INFINITY
        peakX = 0.0; peakY = 0.0; peakResolution = 0.0
        located = false
        resolutionSum = 0.0; frames = 0
        rise = 0.0; fall = 0.0
    }

    private fun rates(e: DoubleArray, dt: Double) {
        for (k in 0 until n) {
            val rate = (e[k] - previous[k]) / dt
            if (rate > rise) rise = rate
            if (-rate > fall) fall = -rate
        }
    }

    private fun addFrame(t: Double, e: DoubleArray, max: Double, min: Double, joint: Double) {
        lastOn = t
        if (min < tMin) tMin = min
        if (joint > jMax) jMax = joint
        if (joint < jMin) jMin = joint
        frames++
        if (max <= 0.0) {
            if (max > tMax) tMax = max
            return
        }
        // One pass: the 75 % centroid (:108) and the 50 % element count (:128) of this image.
        val at75 = 0.75 * max
        val at50 = 0.5 * max
        var sx = 0.0
        var sy = 0.0
        var c75 = 0
        var c50 = 0
        for (k in 0 until n) {
            val v = e[k]
            if (v >= at50) c50++
            if (v >= at75) { sx += layout.x(k); sy += layout.y(k); c75++ }
        }
        val cx = sx / c75
        val cy = sy / c75
        val resolution = c50.toDouble() / n
        resolutionSum += resolution
        if (!located) { firstX = cx; firstY = cy; located = true }
        lastX = cx; lastY = cy
        if (max > tMax) {
            tMax = max
            peakX = cx; peakY = cy; peakResolution = resolution
        }
    }

    private fun endTouch(t: Double) {
        add(values(t))
        touches++
        inTouch = false
    }

    private fun add(v: DoubleArray) {
        for (k in v.indices) sums[k] += v[k]
    }

    /** Features 1–12 of the running touch, ending at [end]. */
    private fun values(end: Double): DoubleArray {
        val dx = lastX - firstX
        val dy = lastY - firstY
        return doubleArrayOf(
            tMax, tMin, jMax, jMin, peakX, peakY,
            if (located) sqrt(dx * dx + dy * dy) else 0.0,
            peakResolution, resolutionSum / frames,
            end - start, rise, fall,
        )
    }

    /** The 13 features of everything offered so far (a touch still on counts as ending at its last frame). */
    public fun features(): DoubleArray {
        val out = DoubleArray(COUNT)
        val count = touchCount
        if (count == 0) return out
        val total = sums.copyOf()
        if (inTouch) values(lastOn).forEachIndexed { k, v -> total[k] += v }
        for (k in total.indices) out[k] = total[k] / count
        out[COUNT - 1] = count.toDouble()
        return out
    }

    public companion object {
        /** Features per message (Table 1, 001_e790093bbd2e3cd3.txt:111–124). */
        public const val COUNT: Int = 13

        /** The feature names, in Table 1's order. */
        public val NAMES: List<String> = listOf(
            "max_intensity", "min_intensity", "max_joint", "min_joint", "x", "y", "displacement",
            "spatial_resolution", "mean_spatial_resolution", "duration_s", "max_rise_rate", "max_fall_rate", "touch_count",
        )

        /** The features of a whole [stream] on [layout]. */
        public fun of(layout: SkinLayout, stream: Sequence<SkinFrame>, thresholds: TouchThresholds = TouchThresholds.DEFAULT): DoubleArray {
            val features = SocialTouchFeatures(layout, thresholds)
            for (frame in stream) features.offer(frame)
            return features.features()
        }

        /** The features of a touchscreen [stream], drawn on [pad] and cut at any contact ([TouchThresholds.ANY_CONTACT]). */
        public fun ofContacts(stream: Sequence<ContactFrame>, pad: TouchPadSkin = TouchPadSkin()): DoubleArray =
            of(pad.layout, stream.map(pad::frame), TouchThresholds.ANY_CONTACT)
    }
}
