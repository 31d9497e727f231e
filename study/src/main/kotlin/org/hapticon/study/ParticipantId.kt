package org.hapticon.study

/**
 * Pseudonymous participant ids: "P", the 0-based participant index zero-padded to three digits, "-", and a check
 * letter, for example `P000-A`, `P007-H`, `P1234-C`. No names: the id carries the index and nothing else.
 *
 * The check letter is the Damm check digit of the index digits (mapped to A..J), which catches every single
 * mistyped digit and every swap of two adjacent digits when an id is copied by hand onto a paper questionnaire.
 */
public object ParticipantId {
    private val FORM = Regex("P([0-9]{3,10})-([A-J])")

    // The Damm operation table: a totally anti-symmetric quasigroup of order 10.
    private val DAMM = arrayOf(
        intArrayOf(0, 3, 1, 7, 5, 9, 8, 6, 4, 2), intArrayOf(7, 0, 9, 2, 1, 5, 4, 8, 6, 3),
        intArrayOf(4, 2, 0, 6, 8, 7, 1, 3, 5, 9), intArrayOf(1, 7, 5, 0, 9, 8, 3, 4, 2, 6),
        intArrayOf(6, 1, 2, 3, 0, 4, 5, 9, 7, 8), intArrayOf(3, 6, 7, 4, 2, 0, 9, 5, 8, 1),
        intArrayOf(5, 8, 6, 9, 7, 2, 0, 1, 3, 4), intArrayOf(8, 9, 4, 5, 3, 6, 2, 0, 1, 7),
        intArrayOf(9, 4, 3, 8, 6, 1, 7, 2, 0, 5), intArrayOf(2, 5, 8, 1, 4, 3, 6, 7, 9, 0),
    )

    /** The id of the participant with 0-based [index]. Throws [IllegalArgumentException] when [index] is negative. */
    public fun of(index: Int): String {
        require(index >= 0) { "participant index must be >= 0, was $index" }
        val digits = index.toString().padStart(3, '0')
        return "P$digits-${checkLetter(digits)}"
    }

    /**
     * The 0-based index in [id]. Throws [IllegalArgumentException] when [id] is not of the form `P000-A` or its
     * check letter does not match (a typo).
     */
    public fun parse(id: String): Int {
        val match = FORM.matchEntire(id) ?: throw IllegalArgumentException("participant id must look like P000-A, got \"${id.take(40)}\"")
        val (digits, letter) = match.destructured
        val index = digits.toLongOrNull()?.takeIf { it <= Int.MAX_VALUE }
            ?: throw IllegalArgumentException("participant id $id: index out of range")
        if (of(index.toInt()) != id) {
            val expected = checkLetter(digits)
            throw IllegalArgumentException(
                if (letter[0] != expected) "participant id $id: check letter should be $expected (mistyped?)" else "participant id $id: index must be zero-padded to 3 digits, no more",
            )
        }
        return index.toInt()
    }

    private fun checkLetter(digits: String): Char {
        var interim = 0
        for (c in digits) interim = DAMM[interim][c - '0']
        return 'A' + interim
    }
}
