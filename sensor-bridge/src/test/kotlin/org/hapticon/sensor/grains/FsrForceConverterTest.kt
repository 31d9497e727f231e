package org.hapticon.sensor.grains

import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class FsrForceConverterTest {
    private val converter = FsrForceConverter()

    private fun force(volts: Double): FsrReading.Force = converter.forceOf(volts) as FsrReading.Force

    @Test
    fun forceOf_halfTheSupply_isOneHundredMicrosiemens() {
        // G = 1000·2.5/(10·2.5) = 100 µS → 100/80 = 1.25 N.
        assertEquals(100.0, force(2.5).microsiemens, 1e-12)
        assertEquals(1.25, force(2.5).newtons, 1e-12)
    }

    @Test
    fun forceOf_fourVolts_isFiveNewtons() {
        // G = 1000·4/(10·1) = 400 µS → 5 N.
        assertEquals(FsrReading.Force(5.0, 400.0), force(4.0))
    }

    @Test
    fun forceOf_aConfiguredSensitivity_scalesTheForce() {
        assertEquals(4.0, (FsrForceConverter(microsiemensPerNewton = 100.0).forceOf(4.0) as FsrReading.Force).newtons, 1e-12)
        // RM = 5 kΩ doubles the conductance: 1000·2.5/(5·2.5) = 200 µS.
        assertEquals(200.0, (FsrForceConverter(measuringKiloohms = 5.0).forceOf(2.5) as FsrReading.Force).microsiemens, 1e-12)
    }

    @Test
    fun forceOf_atOrBelowZeroVolts_isNoTouch() {
        assertEquals(FsrReading.Force(0.0, 0.0), converter.forceOf(0.0))
        assertEquals(FsrReading.Force(0.0, 0.0), converter.forceOf(-0.05))
        assertEquals(FsrReading.Force(0.0, 0.0), converter.forceOf(Double.NEGATIVE_INFINITY))
    }

    @Test
    fun forceOf_atOrAboveTheSupplyOrNan_isAFault() {
        assertEquals(FsrReading.Fault(FsrFault.SHORTED, 5.0), converter.forceOf(5.0))
        assertEquals(FsrReading.Fault(FsrFault.SHORTED, Double.POSITIVE_INFINITY), converter.forceOf(Double.POSITIVE_INFINITY))
        assertEquals(FsrFault.NOT_A_NUMBER, (converter.forceOf(Double.NaN) as FsrReading.Fault).fault)
    }

    @Test
    fun constructor_badParts_areRejected() {
        for (make in listOf({ FsrForceConverter(measuringKiloohms = 0.0) }, { FsrForceConverter(supplyVolts = -5.0) }, { FsrForceConverter(microsiemensPerNewton = 0.0) })) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun newtonsOrNaN_isForceOfsValueOrNaNForEveryFault() {
        val converter = FsrForceConverter()
        val inputs = doubleArrayOf(-1.0, 0.0, 0.5, 2.5, 4.99, 5.0, 9.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)
        for (volts in inputs) {
            val expected = (converter.forceOf(volts) as? FsrReading.Force)?.newtons ?: Double.NaN
            org.junit.Assert.assertEquals("at $volts V", expected, converter.newtonsOrNaN(volts), 0.0)
        }
    }
}
