package org.hapticon.sensor.electrotactile

import java.time.Instant
import org.hapticon.sensor.SensorFormats
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

/**
 * The calibration file `hapticon.electrotactile-calibration` v1: its exact text, a byte-for-byte round trip, and every
 * strict-read refusal in one line naming the member (schema, version, unknown members, electrode count and order,
 * steps past 0..200, a `milliamps` that is not the step's current, NaN, the time, the participant).
 */
class CalibrationFileTest {
    private val steps = listOf(61, 59, 0, 200, 60, 60, 148, 1, 58)
    private val calibration = StoredCalibration(ElectrotactileCalibrationResult(steps), Instant.parse("2026-11-27T00:12:03Z"), "P07")

    private val text = """
        {
          "schema": "hapticon.electrotactile-calibration",
          "version": 1,
          "participant": "P07",
          "calibratedAt": "2026-11-27T00:12:03Z",
          "electrodes": [
            {
              "electrode": 1,
              "step": 61,
              "milliamps": 0.8235
            },
            {
              "electrode": 2,
              "step": 59,
              "milliamps": 0.7965
            },
            {
              "electrode": 3,
              "step": 0,
              "milliamps": 0.0
            },
            {
              "electrode": 4,
              "step": 200,
              "milliamps": 2.7
            },
            {
              "electrode": 5,
              "step": 60,
              "milliamps": 0.81
            },
            {
              "electrode": 6,
              "step": 60,
              "milliamps": 0.81
            },
            {
              "electrode": 7,
              "step": 148,
              "milliamps": 1.998
            },
            {
              "electrode": 8,
              "step": 1,
              "milliamps": 0.0135
            },
            {
              "electrode": 9,
              "step": 58,
              "milliamps": 0.783
            }
          ]
        }
    """.trimIndent() + "\n"

    private fun decode(text: String) = CalibrationFile.decode(text.toByteArray())

    private fun refused(text: String): String = assertThrows(CalibrationFileException::class.java) { decode(text) }.message!!

    @Test
    fun encode_writesTheSchemaVersionParticipantTimeAndEachElectrodesStepAndCurrent() {
        assertEquals(text, CalibrationFile.encode(calibration))
    }

    @Test
    fun roundTrip_isByteForByte_bothWays() {
        val bytes = CalibrationFile.encode(calibration).toByteArray()
        val read = CalibrationFile.decode(bytes)
        assertEquals(calibration, read)
        assertEquals(steps, read.result.steps)
        assertArrayEquals(bytes, CalibrationFile.encode(read).toByteArray())

        val anonymous = StoredCalibration(ElectrotactileCalibrationResult(List(9) { 60 }), Instant.parse("2026-01-02T03:04:05.678Z"))
        val anonymousText = CalibrationFile.encode(anonymous)
        assertEquals(true, "\"participant\": null," in anonymousText)
        assertEquals(anonymous, CalibrationFile.decode(anonymousText.toByteArray()))
        assertEquals(anonymousText, CalibrationFile.encode(CalibrationFile.decode(anonymousText.toByteArray())))
    }

    @Test
    fun milliampsOf_isTheExactFourDecimalCurrent_forEveryStep() {
        for (step in 0..200) assertEquals(String.format(java.util.Locale.ROOT, "%.4f", step * 135 / 10000.0), String.format(java.util.Locale.ROOT, "%.4f", CalibrationFile.milliampsOf(step)))
        assertEquals(0.81, CalibrationFile.milliampsOf(60), 0.0)
        assertEquals(2.7, CalibrationFile.milliampsOf(200), 0.0)
        assertThrows(org.hapticon.sensor.safety.SafetyLimitException::class.java) { CalibrationFile.milliampsOf(201) }
    }

    @Test
    fun strictRead_eachProblemIsOneLineNamingTheMember() {
        val cases = listOf(
            text.replace("\"step\": 58", "\"step\": 201") to "electrodes[8].step: must be in 0..200 (2.7 mA), was 201",
            text.replace("\"step\": 61", "\"step\": -1") to "electrodes[0].step: must be in 0..200 (2.7 mA), was -1",
            text.replace("\"milliamps\": 0.81\n", "\"milliamps\": 2.9\n") to "electrodes[4].milliamps: 2.9 is not the current of step 60 (0.81 mA)",
            text.replace("\"milliamps\": 0.8235", "\"milliamps\": 0.8236") to "electrodes[0].milliamps: 0.8236 is not the current of step 61 (0.8235 mA)",
            text.replace("\"milliamps\": 0.8235", "\"milliamps\": \"NaN\"") to "electrodes[0].milliamps: must be a finite number, was \"NaN\"",
            text.replace("\"step\": 61", "\"step\": 61.5") to "electrodes[0].step: must be a whole number, was 61.5",
            text.replace("hapticon.electrotactile-calibration", "hapticon.pattern") to "schema: must be \"hapticon.electrotactile-calibration\", was \"hapticon.pattern\": not a calibration file",
            text.replace("\"version\": 1", "\"version\": 2") to "version: must be 1, was 2: newer than this build reads",
            text.replace("\"version\": 1", "\"version\": 0") to "version: must be 1, was 0",
            text.replace("  \"version\": 1,\n", "") to "version: missing",
            text.replace("\"participant\": \"P07\",", "\"participant\": \"P07\", \"gain\": 2,") to "gain: unknown member (version 1 has schema, version, participant, calibratedAt, electrodes)",
            text.replace("\"step\": 59,", "\"step\": 59, \"stpe\": 90,") to "electrodes[1].stpe: unknown member (version 1 has electrode, step, milliamps)",
            text.replace("\"electrode\": 3", "\"electrode\": 4") to "electrodes[2].electrode: must be 3 (electrodes 1..9 in order), was 4",
            text.replace("2026-11-27T00:12:03Z", "yesterday") to "calibratedAt: must be an ISO-8601 UTC time such as 2026-11-27T00:12:03Z, was \"yesterday\"",
            text.replace("\"P07\"", "\"P07\\nP08\"") to "participant: must not hold control characters or line breaks",
            text.replace("\"P07\"", "\"\"") to "participant: must not be empty",
            "[]" to "expected a JSON object",
        )
        for ((file, message) in cases) assertEquals(file, message, refused(file))
    }

    @Test
    fun strictRead_electrodeCount_nanAndBrokenJson() {
        val eight = text.substringBefore("    {\n      \"electrode\": 9").trimEnd().removeSuffix(",") + "\n  ]\n}\n"
        assertEquals("electrodes: needs 9 electrodes (1..9), has 8", refused(eight))
        val ten = text.replace("\"milliamps\": 0.783\n    }", "\"milliamps\": 0.783\n    },\n    {\"electrode\": 10, \"step\": 60, \"milliamps\": 0.81}")
        assertEquals("electrodes: needs 9 electrodes (1..9), has 10", refused(ten))
        // JSON has no NaN: the strict reader refuses it where it stands.
        val nan = refused(text.replace("\"milliamps\": 0.8235", "\"milliamps\": NaN"))
        assertEquals(true, nan.startsWith("not valid JSON: ") && nan.contains(" at offset "))
        assertEquals(true, refused(text.dropLast(3)).startsWith("not valid JSON: "))
        val duplicate = refused(text.replace("\"step\": 61,", "\"step\": 61, \"step\": 200,"))
        assertEquals(true, duplicate.startsWith("not valid JSON: "))
        assertEquals("larger than 16384 bytes: not a calibration file", refused(" ".repeat(16 * 1024 + 1)))
    }

    @Test
    fun storedCalibration_refusesABadParticipant_andTheFormatConstantsAreTheFamilys() {
        assertThrows(IllegalArgumentException::class.java) { StoredCalibration(calibration.result, calibration.calibratedAt, "a\tb") }
        assertThrows(IllegalArgumentException::class.java) { StoredCalibration(calibration.result, calibration.calibratedAt, "x".repeat(65)) }
        assertEquals("hapticon.electrotactile-calibration", SensorFormats.CALIBRATION_SCHEMA)
        assertEquals(1, SensorFormats.CALIBRATION_VERSION)
    }
}
