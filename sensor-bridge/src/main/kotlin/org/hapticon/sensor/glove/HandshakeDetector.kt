package org.hapticon.sensor.glove

/** What one middle-finger reading did to a [HandshakeDetector]. */
public enum class HandshakeEvent {
    /** Nothing changed. */
    NONE,

    /** The angle rose above the start threshold: the handshake began. */
    STARTED,

    /** The angle fell to or below the end threshold: the handshake ended. */
    ENDED,
}

/**
 * Detects a handshake from one hand's middle-finger angle (the thumb has no threshold: 002_12aacdd60a14fec1.txt:167).
 *
 * It starts when the angle exceeds [startAboveDegrees] (the paper's 30.9°, the smallest of its three following
 * participants' middle-finger angles in a weak face-to-face grip, Table 6, :287-292, chosen at :168-170: "Pressure
 * presentation is triggered when the measured angle exceeds this value") and ends when the angle falls to or below
 * [startAboveDegrees] − [hysteresisDegrees]. The paper is silent on the end; the hysteresis (ours, default 2°, about
 * twice the noise of a settled flex reading, see [SettleCriterion]) keeps a finger resting at the threshold from
 * producing a burst of start/end events; 0 gives a plain threshold. Not thread-safe; allocation-free.
 */
public class HandshakeDetector(
    /** The angle the middle finger must exceed to start a handshake, in degrees. */
    public val startAboveDegrees: Double = START_ABOVE_DEGREES,
    /** How far below the start threshold the angle must fall to end it, in degrees (≥ 0). */
    public val hysteresisDegrees: Double = DEFAULT_HYSTERESIS_DEGREES,
) {
    init {
        require(startAboveDegrees.isFinite()) { "startAboveDegrees must be finite, was $startAboveDegrees" }
        require(hysteresisDegrees >= 0.0 && hysteresisDegrees.isFinite()) {
            "hysteresisDegrees must be finite and >= 0, was $hysteresisDegrees"
        }
    }

    /** The angle at or below which an active handshake ends: start threshold − hysteresis. */
    public val endAtOrBelowDegrees: Double = startAboveDegrees - hysteresisDegrees

    /** Whether a handshake is in progress. */
    public var isActive: Boolean = false
        private set

    /**
     * Feeds one middle-finger angle and returns the event it caused.
     * @throws IllegalArgumentException when [middleDegrees] is not finite.
     */
    public fun update(middleDegrees: Double): HandshakeEvent {
        require(middleDegrees.isFinite()) { "middleDegrees must be finite, was $middleDegrees" }
        if (!isActive && middleDegrees > startAboveDegrees) {
            isActive = true
            return HandshakeEvent.STARTED
        }
        if (isActive && middleDegrees <= endAtOrBelowDegrees) {
            isActive = false
            return HandshakeEvent.ENDED
        }
        return HandshakeEvent.NONE
    }

    /** Forgets any handshake in progress. */
    public fun reset() {
        isActive = false
    }

    public companion object {
        /** The paper's start threshold on the middle finger: 30.9° (002_12aacdd60a14fec1.txt:170, Table 7 :296). */
        public const val START_ABOVE_DEGREES: Double = 30.9

        /** Default hysteresis below the start threshold. */
        public const val DEFAULT_HYSTERESIS_DEGREES: Double = 2.0
    }
}
