package org.hapticon.study.design

import org.junit.Assert.assertEquals
import org.junit.Test

class SplitMix64Test {
    @Test
    fun seedZero_matchesReferenceOutputs() {
        // Reference values of Vigna's splitmix64.c for seed 0.
        val random = SplitMix64(0L)
        assertEquals("e220a8397b1dcdaf", java.lang.Long.toHexString(random.nextLong()))
        assertEquals("6e789e6aa1b965f4", java.lang.Long.toHexString(random.nextLong()))
        assertEquals("6c45d188009454f", java.lang.Long.toHexString(random.nextLong()))
    }
}
