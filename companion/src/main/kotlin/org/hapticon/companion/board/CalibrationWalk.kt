package org.hapticon.companion.board

import java.io.PrintStream
import java.util.Locale
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus

/** One key at a time from the terminal (or a script in tests): a character code, or -1 when input ended. */
fun interface KeyInput {
    /** The next key; blocks until one comes; -1 at the end of input. */
    fun next(): Int
}

/**
 * Shaping Compliance's per-person calibration (003_8ca1dc8f53472543.txt:152) walked on the
 * terminal, one key per answer, through the same state machine the app uses ([ElectrotactileCalibration]): each
 * electrode of the 3×3 array gets a 200 ms stimulus starting at 0.8 mA (step 60, 0.81 mA) and rising one hardware
 * step (13.5 µA) per "not yet" until the person calls it clear and pain-free; then the whole-array check, 39 grains
 * on all nine electrodes at their levels while the person presses the sensor, adjusted until the sensation is uniform
 * (003_8ca1dc8f53472543.txt:152): one electrode that stands out goes a step weaker or stronger, or all go a step down.
 *
 * Every stimulus goes to the board through [link] (STIMULATE, then SET_GRAINS for the check) and its ack or refusal
 * is printed as one line. The 2.7 mA cap holds three times over: the state machine never raises past step 200 (a
 * key past it prints that it cannot go higher and gives no stimulus), and [FirmwareStimulus] /
 * [FirmwareGrainParams] and the command queue refuse any step past 200 before a byte is written.
 *
 * Keys: `u`, `+` or space = not yet (one step up, stimulus again); `d` or `-` = too strong (one step down, again);
 * `r` = the same stimulus again; `y` or Enter = clear and pain-free (next electrode; in the check: done);
 * in the check, `1`–`9` = pick the electrode that stands out, then `w` = that one weaker, `s` = that one stronger;
 * `q` = stop without a result.
 *
 * @param rangeOverride the force range for the check when the board announces none (a channel in physical units).
 */
class CalibrationWalk(
    private val link: BoardLink,
    private val keys: KeyInput,
    private val out: PrintStream,
    private val rangeOverride: FirmwareForceRange? = null,
) {
    private val calibration = ElectrotactileCalibration()

    /** The electrode picked in the whole-array check (0..8), or null before one is. */
    private var picked: Int? = null

    /** Walks the calibration; returns the result, or null when the person stopped (q) or input ended first. */
    fun run(): ElectrotactileCalibrationResult? {
        out.println("Shaping Compliance calibration (CHI 2024): each electrode alone, a 200 ms stimulus from 0.8 mA,")
        out.println("one step (0.0135 mA) up per 'not yet' until clear and pain-free; then all nine while you press. Cap 2.7 mA.")
        out.println("keys: u/+/space not yet, d/- too strong, r again, y/Enter clear and pain-free, q stop")
        giveStimulus()
        while (!calibration.isDone) {
            val key = keys.next()
            if (key == -1 || key == 'q'.code) {
                out.println("stopped: calibration not finished, nothing kept")
                return null
            }
            if (calibration.isCheckingWholeArray) onCheckKey(key.toChar()) else onElectrodeKey(key.toChar())
        }
        val result = calibration.result()
        out.println("calibrated steps (electrodes 1-9): ${result.steps.joinToString(",")}")
        out.println("calibrated mA: ${result.milliamps.joinToString(",") { ma(it) }}")
        out.println("use them: hapticon board set --port PORT --grains N --shape SHAPE --steps ${result.steps.joinToString(",")}")
        return result
    }

    private fun onElectrodeKey(key: Char) {
        val electrode = calibration.currentElectrode ?: return
        when (key) {
            'u', '+', ' ' -> {
                if (calibration.steps()[electrode] == AmplitudeSteps.STEPS) {
                    out.println("electrode ${electrode + 1}: already at the 2.7 mA cap (step 200): it cannot go higher")
                    return
                }
                calibration.notYet()
                giveStimulus()
            }
            'd', '-' -> {
                calibration.tooStrong()
                giveStimulus()
            }
            'r' -> giveStimulus()
            'y', '\n', '\r' -> {
                out.println("electrode ${electrode + 1}: kept at ${ma(AmplitudeSteps.milliampsOf(calibration.steps()[electrode]))} mA (step ${calibration.steps()[electrode]})")
                calibration.clearAndPainFree()
                if (calibration.isCheckingWholeArray) sendCheck() else giveStimulus()
            }
            else -> out.println(KEY_HELP)
        }
    }

    private fun onCheckKey(key: Char) {
        when (key) {
            'y', '\n', '\r' -> calibration.wholeArrayOk()
            'd', '-' -> {
                calibration.tooStrong()
                sendCheck()
            }
            'r' -> sendCheck()
            in '1'..'9' -> {
                picked = key - '1'
                out.println("electrode $key picked: w weaker, s stronger")
            }
            'w', 's' -> {
                val electrode = picked ?: return out.println("pick the electrode that stands out first: 1-9")
                if (key == 'w') calibration.weaker(electrode) else calibration.stronger(electrode)
                val step = calibration.steps()[electrode]
                out.println("electrode ${electrode + 1}: step $step = ${ma(AmplitudeSteps.milliampsOf(step))} mA")
                sendCheck()
            }
            else -> out.println(CHECK_HELP)
        }
    }

    private fun giveStimulus() {
        val stimulus = FirmwareStimulus.of(calibration.stimulus() ?: return)
        val outcome = link.stimulate(stimulus)
        out.println("electrode ${stimulus.electrode + 1}: step ${stimulus.step} = ${ma(AmplitudeSteps.milliampsOf(stimulus.step))} mA: ${verdict(outcome)}")
    }

    private fun sendCheck() {
        val range = link.forceRange() ?: rangeOverride
        if (range == null) {
            out.println("whole-array check: not sent: the board announced no raw force range; give --range MIN:MAX")
            return
        }
        val outcome = link.send(FirmwareGrainParams.wholeArrayCheck(calibration.steps(), range))
        out.println("whole-array check, ${ElectrotactileCalibration.CHECK_GRAINS} grains on all 9 electrodes: ${verdict(outcome)}")
        if (outcome.accepted) out.println("press the sensor and feel the grains: y/Enter uniform and pain-free, d/- all too strong, 1-9 then w/s one electrode")
    }

    /** `acknowledged`, or the app's one-line problem ("The board refused …: reason"). */
    private fun verdict(outcome: BoardLink.Outcome): String = if (outcome.accepted) "acknowledged" else outcome.line()

    private fun ma(milliamps: Double): String = String.format(Locale.ROOT, "%.4f", milliamps)

    private companion object {
        const val KEY_HELP = "keys: u/+/space not yet, d/- too strong, r again, y/Enter clear and pain-free, q stop"
        const val CHECK_HELP = "whole-array check: y/Enter uniform and pain-free, d/- too strong (all one step down), " +
            "1-9 pick an electrode then w weaker / s stronger, r send again, q stop"
    }
}
