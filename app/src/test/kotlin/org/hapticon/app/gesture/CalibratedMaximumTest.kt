package org.hapticon.app.gesture

import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.grains.GrainConfig
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.extraction.FitOptions
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.LevelReference
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Test

/** The sensor board's calibrated maximum as the recorder's level reference ([SensorSessionGestureSource.calibratedMaximum]). */
class CalibratedMaximumTest {
    private val framed = StreamInfo(SensorProtocol.FRAMED, listOf("fsr", "grams", "angle"), listOf(ChannelUnit.RAW, ChannelUnit.GRAM, ChannelUnit.CENTIDEGREE), adcBits = 12, sampleRateHz = 1000)
    private val csv = StreamInfo(SensorProtocol.CSV, listOf("a", "b"))

    @Test
    fun calibratedMaximum_framedRawChannel_isTheAdcFullScale() {
        assertEquals(4095.0, SensorSessionGestureSource.calibratedMaximum(framed, 0, null)!!, 0.0)
        // A calibrated unit without a grain range, and a CSV stream, state no maximum.
        assertNull(SensorSessionGestureSource.calibratedMaximum(framed, 1, null))
        assertNull(SensorSessionGestureSource.calibratedMaximum(framed, 2, null))
        assertNull(SensorSessionGestureSource.calibratedMaximum(csv, 0, null))
        assertNull(SensorSessionGestureSource.calibratedMaximum(framed, 7, null))
    }

    @Test
    fun calibratedMaximum_grainForceChannel_isTheCalibratedRangeInTheChannelsUnit() {
        val range = GrainSettings(maxNewtons = 10.0)
        // Grams on the framed board: 10 N = 1019.7 g.
        assertEquals(10.0 / 0.00980665, SensorSessionGestureSource.calibratedMaximum(framed, 1, GrainConfig(channel = 1, settings = range))!!, 1e-9)
        // A CSV channel the user said carries newtons or millinewtons.
        assertEquals(10.0, SensorSessionGestureSource.calibratedMaximum(csv, 0, GrainConfig(channel = 0, input = ForceInput.NEWTONS, settings = range))!!, 0.0)
        assertEquals(10_000.0, SensorSessionGestureSource.calibratedMaximum(csv, 0, GrainConfig(channel = 0, input = ForceInput.MILLINEWTONS, settings = range))!!, 0.0)
        // An FSR read as ADC counts over CSV: the configured ADC's full scale; as millivolts, the 5 V supply.
        assertEquals(1023.0, SensorSessionGestureSource.calibratedMaximum(csv, 0, GrainConfig(channel = 0, adcBits = 10, settings = range))!!, 0.0)
        assertEquals(5000.0, SensorSessionGestureSource.calibratedMaximum(csv, 0, GrainConfig(channel = 0, input = ForceInput.FSR_MILLIVOLTS))!!, 0.0)
        // The grain range applies to its own channel only.
        assertNull(SensorSessionGestureSource.calibratedMaximum(csv, 1, GrainConfig(channel = 0, input = ForceInput.NEWTONS, settings = range)))
    }

    @Test
    fun fit_againstTheCalibratedMaximum_keepsALightPressLight() {
        // A 2 N press (0.1 s rise, 0.3 s hold, 0.1 s fall at 100 Hz) on a channel calibrated to 10 N fits level ≈ 0.2, not 1.
        val press = DoubleArray(100) { k ->
            when (k) {
                in 25 until 35 -> 2.0 * (k - 25) / 10.0
                in 35 until 65 -> 2.0
                in 65 until 75 -> 2.0 * (75 - k) / 10.0
                else -> 0.0
            }
        }
        val full = SensorSessionGestureSource.calibratedMaximum(csv, 0, GrainConfig(channel = 0, input = ForceInput.NEWTONS, settings = GrainSettings(maxNewtons = 10.0)))
        val recording = Recording(100.0, listOf(Channel("force", "", press, full)))
        val fit = IconFitter.fit(recording, options = FitOptions(levelReference = LevelReference.FullScale))
        assertEquals(10.0, fit.report.levelReferenceValue, 0.0)
        assertEquals(0.2, fit.icon.level, 0.05)
    }
}
