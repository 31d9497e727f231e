package org.hapticon.devicecheck.dumpsys

import java.time.LocalDateTime
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test

class VibratorDumpTest {
    private fun sample(name: String): String =
        requireNotNull(javaClass.getResource("/dumpsys/$name")) { "missing sample $name" }.readText()

    // The knock as haptics-core's VibrationWaveform renders it (timings [20, 250, 20, 250, 20], amplitudes 96/0/96/0/96),
    // as the Android 14+ debug string writes 96/255: "0.38".
    private val knockDebug = listOf(Step(20, 0.38f), Step(250, 0f), Step(20, 0.38f), Step(250, 0f), Step(20, 0.38f))

    @Test
    fun android15_compactLines_eachVibrationWithStatusUsageCallerAndEffects() {
        val dump = VibratorDump.parse(sample("vibrator_manager-android15.txt"), 2026)

        assertEquals(4, dump.vibrations.size)
        val knock = dump.of("org.hapticon.app").first { it.status == "finished" }
        assertEquals(LocalDateTime.of(2026, 11, 26, 14, 3, 7, 412_000_000), knock.createdAt)
        assertEquals("COMMUNICATION_REQUEST", knock.usage)
        assertEquals(10234, knock.uid)
        assertEquals(560L, knock.durationMillis)
        assertFalse(knock.external)
        assertTrue(knock.played)
        assertEquals("null", knock.reason)
        assertEquals(knockDebug, knock.originalSteps)
        // The played effect is scaled by the user's intensity; the original is what the app asked for.
        assertEquals(0.45f, Step.parse(knock.playedEffect)!!.first().amplitude)
    }

    @Test
    fun android15_refusedVibration_keepsItsStatusAndUsage() {
        val dump = VibratorDump.parse(sample("vibrator_manager-android15.txt"), 2026)

        val refused = dump.of("org.hapticon.app").single { !it.played }
        assertEquals("ignored_background", refused.status)
        assertEquals("UNKNOWN", refused.usage)
        assertEquals(LocalDateTime.of(2026, 11, 26, 14, 1, 40, 201_000_000), refused.createdAt)
    }

    @Test
    fun android15_notificationAlert_isTheSystemsVibrationNamingTheApp() {
        val dump = VibratorDump.parse(sample("vibrator_manager-android15.txt"), 2026)

        val alert = dump.notificationAlertsOf("org.hapticon.app").single()
        assertEquals("android", alert.packageName)
        assertEquals(1000, alert.uid)
        assertEquals("NOTIFICATION", alert.usage)
        assertEquals("cancelled_superseded", alert.status)
        assertEquals(listOf(0, 250, 250, 250), alert.originalSteps!!.map { it.durationMillis })
        assertEquals(-1f, alert.originalSteps!![1].amplitude)
    }

    @Test
    fun android15_prebakedEffect_hasNoSteps() {
        val touch = VibratorDump.parse(sample("vibrator_manager-android15.txt"), 2026).of("com.android.systemui").single()
        assertEquals("TOUCH", touch.usage)
        assertNull(touch.originalSteps)
    }

    @Test
    fun android15_processStateCache_perUid() {
        val dump = VibratorDump.parse(sample("vibrator_manager-android15.txt"), 2026)
        assertEquals(mapOf(1000 to 0, 10152 to 2, 10234 to 4, 10301 to 4), dump.processStates)
    }

    @Test
    fun android13_debugInfoLines_sameFieldsFromTheLongFormat() {
        val dump = VibratorDump.parse(sample("vibrator_manager-android13.txt"), 2026)

        assertEquals(3, dump.vibrations.size)
        val knock = dump.of("org.hapticon.app").single { it.played }
        assertEquals("COMMUNICATION_REQUEST", knock.usage)
        assertEquals(LocalDateTime.of(2026, 11, 26, 14, 3, 7, 412_000_000), knock.createdAt)
        assertEquals(563L, knock.durationMillis)
        assertEquals(listOf(20, 250, 20, 250, 20), knock.originalSteps!!.map { it.durationMillis })
        assertEquals(96 / 255f, knock.originalSteps!![0].amplitude, 1e-6f)
        assertEquals("ignored_background", dump.of("org.hapticon.app").single { !it.played }.status)
        assertEquals("Notification (org.hapticon.app 10234)", dump.notificationAlertsOf("org.hapticon.app").single().reason)
        assertEquals(mapOf(10234 to 12, 10152 to 2), dump.processStates)
    }

    @Test
    fun steps_commaDecimalLocale_readAsNumbers() {
        // String.format without a locale writes the phone's decimal separator: "0,38" on a German phone.
        assertEquals(listOf(Step(20, 0.38f), Step(250, 0f)), Step.parse("[Step=20ms(amplitude=0,38),Step=250ms(amplitude=0,00)]"))
        assertEquals(listOf(Step(30, 1f)), Step.parse("Step=30ms(amplitude=1.00 @ 150.0Hz)"))
    }

    @Test
    fun notAVibrationLine_isSkipped() {
        val dump = VibratorDump.parse("Recent vibrations:\n  COMMUNICATION_REQUEST:\n    nothing | here\n", 2026)
        assertTrue(dump.vibrations.isEmpty())
        assertTrue(dump.processStates.isEmpty())
    }
}
