package org.hapticon.sensor.electrotactile

import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows

/** Asserts that [call] is refused by the electrotactile current limit (not by any other safety limit). */
fun assertCurrentRefused(call: () -> Unit) {
    assertEquals("electrotactileCurrent", assertThrows(SafetyLimitException::class.java) { call() }.limit)
}
