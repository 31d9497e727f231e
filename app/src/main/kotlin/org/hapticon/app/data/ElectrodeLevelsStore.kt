package org.hapticon.app.data

import org.hapticon.app.gesture.replaceFile
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.CalibrationFileException
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import java.io.File
import java.util.Locale
import java.time.format.DateTimeFormatter
import java.time.ZoneOffset
import java.time.Instant

/**
 * The last finished electrotactile calibration, so the compliance study stimulates at the person's levels. It is kept
 * in [file] in the calibration file format `hapticon.electrotactile-calibration` v1 ([CalibrationFile], sensor-bridge):
 * the same file `hapticon board calibrate --save` writes and `board set --calibration` reads, so a calibration moves
 * between the phone and the laptop unchanged ([stored] is what an export writes, [import] reads one in).
 *
 * Every step is checked against 0..200 (2.7 mA) on the way in and on the way out: a damaged file reads as no
 * calibration, never as a stronger one. [legacyFile] is the app's earlier one-line `s0,s1,…,s8` file, read (with the
 * same checks) only while [file] does not exist yet, so an update keeps a person's levels until they calibrate again.
 */
class ElectrodeLevelsStore(
    private val file: File,
    private val legacyFile: File? = null,
    private val clock: () -> Instant = Instant::now,
) {
    /** The stored steps of electrodes 1..9, or null when there are none or the file is damaged. */
    fun load(): List<Int>? = stored()?.result?.steps

    /** The stored calibration with its time and participant, or null when there is none or the file is damaged. */
    fun stored(): StoredCalibration? {
        if (!file.isFile) return legacy()
        if (file.length() > CalibrationFile.MAX_BYTES) return null
        return try {
            CalibrationFile.decode(file.readBytes())
        } catch (e: CalibrationFileException) {
            null
        }
    }

    /**
     * Stores [steps], calibrated now, replacing the previous calibration; returns what was stored.
     * @throws org.hapticon.sensor.safety.SafetyLimitException for a step outside 0..200 ([ElectrotactileCalibrationResult]
     *   checks the count and every step).
     */
    fun save(steps: List<Int>): StoredCalibration = StoredCalibration(ElectrotactileCalibrationResult(steps), clock()).also(::write)

    /**
     * Reads a calibration file's [bytes] (from the CLI or another phone) and, when it is valid, stores it as is (its
     * time and participant kept); otherwise the stored calibration is left untouched.
     * @throws CalibrationFileException naming the member at fault.
     */
    fun import(bytes: ByteArray): StoredCalibration = CalibrationFile.decode(bytes).also(::write)

    private fun write(calibration: StoredCalibration) = replaceFile(file, CalibrationFile.encode(calibration))

    private fun legacy(): StoredCalibration? {
        val old = legacyFile?.takeIf { it.isFile && it.length() < 1024 } ?: return null
        val steps = old.readText().trim().split(',').map { it.trim().toIntOrNull() ?: return null }
        // Not nine steps in 0..200 (ElectrotactileCalibrationResult's own checks): read as none.
        val result = try {
            ElectrotactileCalibrationResult(steps)
        } catch (e: IllegalArgumentException) {
            return null
        }
        return StoredCalibration(result, Instant.ofEpochMilli(old.lastModified()))
    }

    companion object {
        /**
         * "P07's calibration of 2026-11-27 00:12 UTC (0.810–1.215 mA)", or "the calibration of …" without a participant:
         * whose, when, and its range of currents.
         */
        fun describe(calibration: StoredCalibration): String {
            val at = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm", Locale.ROOT).withZone(ZoneOffset.UTC).format(calibration.calibratedAt)
            val milliamps = calibration.result.milliamps
            val (low, high) = milliamps.min() to milliamps.max()
            val range = if (low == high) String.format(Locale.ROOT, "%.3f mA", low) else String.format(Locale.ROOT, "%.3f–%.3f mA", low, high)
            val whose = calibration.participant?.let { "$it's calibration" } ?: "the calibration"
            return "$whose of $at UTC ($range)"
        }

        /** The file name under the app's files directory. */
        const val FILE_NAME: String = "electrotactile-calibration.json"

        /** The earlier one-line format's name, read until the first save in the new format. */
        const val LEGACY_FILE_NAME: String = "electrode-levels.txt"

        /** The store in the app's files directory [dir], reading the earlier file there while the new one is missing. */
        fun inFolder(dir: File): ElectrodeLevelsStore = ElectrodeLevelsStore(File(dir, FILE_NAME), File(dir, LEGACY_FILE_NAME))
    }
}
