package org.hapticon.sensor.protocol.lucid

import org.hapticon.sensor.protocol.stream.checkRange
import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.sensor.safety.SafetyLimits

/**
 * Encodes host-to-glove force-feedback commands of the LucidGloves alpha encoding:
 * `A<n>B<n>C<n>D<n>E<n>\n`, one servo value per finger thumb..pinky, each in
 * [SafetyLimits.SERVO_MIN]..[SafetyLimits.SERVO_MAX] (0 no force .. 1000 full force), which the
 * glove firmware maps linearly onto its servos' travel.
 */
public object LucidForceFeedback {
    /** The longest command: `A1000B1000C1000D1000E1000\n`. */
    public const val MAX_LENGTH: Int = 26

    /**
     * Writes the command for [values] (five values, thumb..pinky) into [destination] from [offset]
     * and returns its length in bytes. Nothing is written if a check fails.
     * @throws SafetyLimitException if a value is outside the servo range.
     * @throws IllegalArgumentException if [values] does not hold exactly five values.
     * @throws IndexOutOfBoundsException if fewer than [MAX_LENGTH] bytes are left from [offset].
     */
    public fun encode(values: IntArray, destination: ByteArray, offset: Int = 0): Int {
        require(values.size == LucidGloveFrame.FINGERS) { "need ${LucidGloveFrame.FINGERS} values, got ${values.size}" }
        checkRange(destination.size, offset, MAX_LENGTH)
        for (v in values) SafetyLimits.requireServoValue(v)
        var p = offset
        for (finger in 0 until LucidGloveFrame.FINGERS) {
            destination[p++] = ('A' + finger).code.toByte()
            p = writeDecimal(values[finger], destination, p)
        }
        destination[p++] = '\n'.code.toByte()
        return p - offset
    }

    /**
     * The command for [values] as a new array; see [encode].
     * @throws SafetyLimitException if a value is outside the servo range.
     * @throws IllegalArgumentException if [values] does not hold exactly five values.
     */
    public fun encode(values: IntArray): ByteArray {
        val buffer = ByteArray(MAX_LENGTH)
        return buffer.copyOf(encode(values, buffer))
    }

    private fun writeDecimal(value: Int, destination: ByteArray, offset: Int): Int {
        var divisor = 1
        while (divisor * 10 <= value) divisor *= 10
        var p = offset
        var rest = value
        while (divisor > 0) {
            destination[p++] = ('0'.code + rest / divisor).toByte()
            rest %= divisor
            divisor /= 10
        }
        return p
    }
}
