package org.hapticon.study

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class ParticipantIdTest {
    @Test
    fun of_padsAndAddsDammCheckLetter() {
        // 572 has Damm check digit 4 (the textbook example), so E.
        assertEquals("P000-A", ParticipantId.of(0))
        assertEquals("P572-E", ParticipantId.of(572))
        assertEquals("P1000", ParticipantId.of(1000).take(5))
        assertEquals(Int.MAX_VALUE, ParticipantId.parse(ParticipantId.of(Int.MAX_VALUE)))
    }

    @Test
    fun parse_roundTrips() {
        for (i in (0..2000) + listOf(99_999, 1_000_000)) assertEquals(i, ParticipantId.parse(ParticipantId.of(i)))
    }

    @Test
    fun parse_catchesEverySingleDigitTypoAndAdjacentSwap() {
        for (i in 0..999) {
            val id = ParticipantId.of(i)
            val digits = id.substring(1, 4)
            for (pos in 0 until 3) for (d in '0'..'9') {
                if (d == digits[pos]) continue
                val typo = "P" + digits.substring(0, pos) + d + digits.substring(pos + 1) + id.substring(4)
                rejects(typo)
            }
            for (pos in 0 until 2) {
                if (digits[pos] == digits[pos + 1]) continue
                val swapped = "P" + digits.substring(0, pos) + digits[pos + 1] + digits[pos] + digits.substring(pos + 2) + id.substring(4)
                rejects(swapped)
            }
        }
    }

    @Test
    fun parse_badForms() {
        expect("participant id must look like P000-A, got \"Alice\"") { ParticipantId.parse("Alice") }
        expect("participant id must look like P000-A, got \"\"") { ParticipantId.parse("") }
        expect("participant id P001-A: check letter should be D (mistyped?)") { ParticipantId.parse("P001-A") }
        expect("participant id P0001-D: index must be zero-padded to 3 digits, no more") { ParticipantId.parse("P0001-D") }
        expect("participant id P9999999999-A: index out of range") { ParticipantId.parse("P9999999999-A") }
        expect("participant index must be >= 0, was -1") { ParticipantId.of(-1) }
    }

    private fun rejects(id: String) {
        assertThrows(id, IllegalArgumentException::class.java) { ParticipantId.parse(id) }
    }

    private fun expect(message: String, block: () -> Unit) =
        assertEquals(message, assertThrows(IllegalArgumentException::class.java) { block() }.message)
}
