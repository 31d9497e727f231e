package org.hapticon.app.study

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class PinGateTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val prefs = context.getSharedPreferences("pin-test", Context.MODE_PRIVATE).also { it.edit().clear().commit() }

    @Test
    fun rightPinOpens_wrongPinRefused() {
        val gate = PinGate(prefs)
        assertFalse(gate.isSet)
        assertFalse("no PIN set opens nothing", gate.check("1234"))

        gate.set("2468")

        assertTrue(gate.isSet)
        assertTrue(gate.check("2468"))
        assertFalse(gate.check("2469"))
        assertFalse(gate.check("24680"))
        assertFalse(gate.check(""))
        assertTrue("a new PinGate on the same preferences knows the PIN", PinGate(prefs).check("2468"))
    }

    @Test
    fun storedAsSaltedPbkdf2_neverThePin() {
        val gate = PinGate(prefs)
        gate.set("13579")
        val first = prefs.all.toMap()
        assertEquals(setOf("pin_hash", "pin_salt"), first.keys)
        assertTrue(first.values.none { it.toString().contains("13579") })
        assertEquals(64, (first["pin_hash"] as String).length) // 256-bit PBKDF2 output in hex

        gate.set("13579")
        assertNotEquals("a fresh salt each time", first["pin_salt"], prefs.getString("pin_salt", null))
        assertNotEquals(first["pin_hash"], prefs.getString("pin_hash", null))
        assertTrue(gate.check("13579"))
    }

    @Test
    fun invalidPins_rejectedWithTheRule() {
        val gate = PinGate(prefs)
        for (bad in listOf("", "123", "12a4", "1234567890123", " 1234")) {
            assertEquals(bad, "the PIN must be 4 to 12 digits", assertThrows(IllegalArgumentException::class.java) { gate.set(bad) }.message)
        }
        assertFalse(gate.isSet)
        gate.set("123456789012")
        assertTrue(gate.check("123456789012"))
    }

    @Test
    fun corruptedStorage_opensNothing() {
        prefs.edit().putString("pin_salt", "zz").putString("pin_hash", "abc").commit()
        assertFalse(PinGate(prefs).check("1234"))
    }
}
