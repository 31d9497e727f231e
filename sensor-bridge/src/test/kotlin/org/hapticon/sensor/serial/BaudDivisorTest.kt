package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.junit.Assert.assertEquals
import org.junit.Test

class BaudDivisorTest {
    private fun unsupportedMessage(block: () -> Unit): String? = try {
        block()
        null
    } catch (e: UnsupportedSettingException) {
        e.message
    }

    @Test
    fun ftdiBaudDivisor_commonRates_matchFtdiTables() {
        assertEquals(FtdiBaudDivisor(0x001A, 0, 115_385), ftdiBaudDivisor(115_200))
        assertEquals(FtdiBaudDivisor(0x4138, 0, 9600), ftdiBaudDivisor(9600))
        assertEquals(FtdiBaudDivisor(0x000D, 0, 230_769), ftdiBaudDivisor(230_400))
        assertEquals(FtdiBaudDivisor(0x8003, 0, 923_077), ftdiBaudDivisor(921_600))
        assertEquals(FtdiBaudDivisor(0x0000, 0, 3_000_000), ftdiBaudDivisor(3_000_000))
        assertEquals(FtdiBaudDivisor(0x0001, 0, 2_000_000), ftdiBaudDivisor(2_000_000))
    }

    @Test
    fun ftdiBaudDivisor_threeEighths_setsTheIndexBit() {
        assertEquals(FtdiBaudDivisor(0x0139, 1, 9573), ftdiBaudDivisor(9573))
    }

    @Test
    fun ftdiBaudDivisor_ratesTheChipCannotHit_throwUnsupported() {
        assertEquals("FTDI chips cannot do 2500000 baud: the nearest is 3000000", unsupportedMessage { ftdiBaudDivisor(2_500_000) })
        assertEquals("FTDI chips cannot do 1600000 baud: the nearest is 1500000", unsupportedMessage { ftdiBaudDivisor(1_600_000) })
        assertEquals("FTDI chips run at least 183 baud, not 150", unsupportedMessage { ftdiBaudDivisor(150) })
        assertEquals("FTDI chips run at most 3000000 baud, not 4000000", unsupportedMessage { ftdiBaudDivisor(4_000_000) })
    }

    @Test
    fun ch34xBaudDivisor_commonRates_matchTheKnownRegisterValues() {
        assertEquals(0xD901, ch34xBaudDivisor(2400))
        assertEquals(0x6402, ch34xBaudDivisor(4800))
        assertEquals(0xB202, ch34xBaudDivisor(9600))
        assertEquals(0xD902, ch34xBaudDivisor(19_200))
        assertEquals(0x6403, ch34xBaudDivisor(38_400))
        assertEquals(0x9803, ch34xBaudDivisor(57_600))
        assertEquals(0xCC03, ch34xBaudDivisor(115_200))
        assertEquals(0xF307, ch34xBaudDivisor(921_600))
        assertEquals(0xFD03, ch34xBaudDivisor(2_000_000))
    }

    @Test
    fun ch34xBaudDivisor_ratesTheChipCannotHit_throwUnsupported() {
        assertEquals("CH34x chips cannot do 2500000 baud: the nearest is 2000000", unsupportedMessage { ch34xBaudDivisor(2_500_000) })
        assertEquals("CH34x chips run at 46 to 3000000 baud, not 45", unsupportedMessage { ch34xBaudDivisor(45) })
        assertEquals("CH34x chips run at 46 to 3000000 baud, not 4000000", unsupportedMessage { ch34xBaudDivisor(4_000_000) })
    }
}
