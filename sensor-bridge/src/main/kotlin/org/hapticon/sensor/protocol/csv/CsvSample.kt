package org.hapticon.sensor.protocol.csv

/**
 * One decoded CSV line. The decoder owns and reuses this object: it is valid only until the next
 * sample is delivered, so copy what you keep.
 */
public class CsvSample internal constructor(maxFields: Int) {
    /** Number of values in this line. */
    public var fieldCount: Int = 0
        internal set

    /**
     * The values, in `0 until fieldCount`; entries beyond are stale. Doubles rather than floats so
     * that integer columns such as a `millis()` timestamp stay exact up to 2^53.
     */
    public val values: DoubleArray = DoubleArray(maxFields)

    /**
     * The value of field [index].
     * @throws IndexOutOfBoundsException unless [index] is in `0 until fieldCount`.
     */
    public operator fun get(index: Int): Double {
        if (index !in 0 until fieldCount) throw IndexOutOfBoundsException("field $index of $fieldCount")
        return values[index]
    }

    /** The values as a list, for tests and logs. Allocates. */
    override fun toString(): String = values.copyOf(fieldCount).joinToString(",", "CsvSample(", ")")
}
