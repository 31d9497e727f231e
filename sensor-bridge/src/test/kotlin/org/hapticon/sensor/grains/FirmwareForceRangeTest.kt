package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test

/** The firmware's grain range comes from the board's device info, so a full press fires the requested grains on any ADC. */
class FirmwareForceRangeTest {
    private fun framed(bits: Int, unit: ChannelUnit = ChannelUnit.RAW) =
        StreamInfo(SensorProtocol.FRAMED, listOf("ch0", "ch1"), listOf(unit, ChannelUnit.RAW), adcBits = bits, sampleRateHz = 1000)

    /** Grain onsets (sample indices) of a 20 s linear press from 0 to [full] counts at 1 kHz, decided as the board does. */
    private fun onsets(params: FirmwareGrainParams, full: Int): List<Int> {
        val decider = GrainDecider(params.deciderSettings(), 1000.0)
        return (0 until 21_000).filter { k -> decider.offer(if (k < 20_000) (k.toLong() * full / 19_999).toDouble() else full.toDouble()) }
    }

    private fun params(grains: Int, range: FirmwareForceRange) = FirmwareGrainParams.of(grains, BinDistribution.LINEAR, range, ElectrodePattern.ALL, List(9) { 100 })

    @Test
    fun fromStream_rawChannel_isTheAdcFullScale() {
        assertEquals(FirmwareForceRange(0, 1023), FirmwareForceRange.fromStream(framed(10)))
        assertEquals(FirmwareForceRange(0, 4095), FirmwareForceRange.fromStream(framed(12)))
        assertEquals(FirmwareForceRange(0, 65535), FirmwareForceRange.fromStream(framed(16)))
        // Physical units have no announced full scale; CSV streams have no device info.
        assertNull(FirmwareForceRange.fromStream(framed(12, ChannelUnit.MILLINEWTON)))
        assertNull(FirmwareForceRange.fromStream(StreamInfo(SensorProtocol.CSV, listOf("fsr"))))
        assertNull(FirmwareForceRange.fromStream(null))
        assertEquals(FirmwareForceRange(0, 4095), FirmwareForceRange.fromStream(framed(12), channel = 1))
        assertNull(FirmwareForceRange.fromStream(framed(12), channel = 2))
    }

    @Test
    fun fullPress_10and12BitSources_fireExactly9_19_39_spreadOverThePress() {
        for (bits in listOf(10, 12)) {
            val full = (1 shl bits) - 1
            val range = FirmwareForceRange.fromStream(framed(bits))!!
            for (grains in listOf(9, 19, 39)) {
                val fired = onsets(params(grains, range), full)
                assertEquals("$bits-bit, $grains grains", grains, fired.size)
                // The last edge is at grains/(grains + 1) of the range: the last grain comes in the press's last tenth.
                assertTrue("$bits-bit, $grains grains: last at ${fired.last()}", fired.last() > 17_500)
            }
        }
    }

    @Test
    fun assumed10BitRange_misplacesTheGrains() {
        // What a hard-coded 0..1023 did: a 12-bit press fires every grain in its first quarter...
        val early = onsets(params(39, FirmwareForceRange(0, 1023)), 4095)
        assertEquals(39, early.size)
        assertTrue("last at ${early.last()}", early.last() < 5_200)
        // ...and a 0..4095 range on a 10-bit board fires a quarter of them.
        assertEquals(9, onsets(params(39, FirmwareForceRange.ofAdcBits(12)), 1023).size)
    }
}
