package org.hapticon.app.feature.sensors

import org.hapticon.app.gesture.replaceFile
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import java.io.File

/**
 * The last finished electrotactile calibration: the amplitude step of electrodes 0..8 in [file], one line
 * `s0,s1,…,s8`, so the compliance study stimulates at the person's levels. Every step is checked against 0..200
 * (2.7 mA) on the way in and on the way out: a damaged file reads as no calibration, never as a stronger one.
 */
class ElectrodeLevelsStore(private val file: File) {
    /** The stored steps, or null when there are none or the file is not nine steps in 0..200. */
    fun load(): List<Int>? {
        if (!file.isFile) return null
        val steps = file.readText().trim().split(',').map { it.trim().toIntOrNull() ?: return null }
        if (steps.size != ElectrotactileCalibration.ELECTRODES || steps.any { it !in 0..AmplitudeSteps.STEPS }) return null
        return steps
    }

    /**
     * Stores [steps], replacing the previous calibration.
     * @throws org.hapticon.sensor.safety.SafetyLimitException for a step outside 0..200.
     */
    fun save(steps: List<Int>) {
        require(steps.size == ElectrotactileCalibration.ELECTRODES) { "need ${ElectrotactileCalibration.ELECTRODES} steps, got ${steps.size}" }
        steps.forEach { AmplitudeSteps.requireStep(it) }
        replaceFile(file, steps.joinToString(","))
    }

    companion object {
        /** The file name under the app's files directory. */
        const val FILE_NAME: String = "electrode-levels.txt"
    }
}
