package org.hapticon.app.feature.sensors

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandHandle
import org.hapticon.sensor.live.describeProblem
import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.app.sensors.StimulatorLink
import java.util.Locale

/** What the electrotactile calibration screen shows: one electrode, the whole-array check, or the result. */
sealed interface ElectrotactileUiState {
    /** Whether a framed board is streaming (the whole-array check can be sent to it). */
    val boardReady: Boolean

    /** Every electrode's step so far, electrodes 0..8 row by row. */
    val steps: List<Int>

    /** A refusal or a confirmation for the researcher. */
    val message: String?

    /** True when [message] says something went wrong on the board (refused, unanswered): shown as an error. */
    val problem: Boolean

    /** Calibrating [electrode] (0..8): the next 200 ms stimulus is [step] ([milliamps]). */
    data class Electrode(
        val electrode: Int,
        val step: Int,
        val milliamps: Double,
        /** True at step 200 (2.7 mA): "not yet" cannot raise it further. */
        val atCap: Boolean,
        override val steps: List<Int>,
        override val boardReady: Boolean,
        override val message: String?,
        override val problem: Boolean = false,
    ) : ElectrotactileUiState

    /** All nine electrodes at their levels while the person presses, [ElectrotactileCalibration.CHECK_GRAINS] grains per press. */
    data class WholeArrayCheck(
        /** Whether the check's SET_GRAINS command was queued for the board since the levels last changed. */
        val sent: Boolean,
        override val steps: List<Int>,
        override val boardReady: Boolean,
        override val message: String?,
        override val problem: Boolean = false,
    ) : ElectrotactileUiState

    /** Calibration finished: each electrode's current and the person's limit (the highest, at most 2.7 mA). */
    data class Done(
        /** Null when every electrode was lowered to 0 mA: no stimulation is allowed for this person. */
        val limitMilliamps: Double?,
        override val steps: List<Int>,
        override val boardReady: Boolean,
        override val message: String?,
        override val problem: Boolean = false,
    ) : ElectrotactileUiState
}

/**
 * Drives Shaping Compliance's per-person electrotactile calibration ([ElectrotactileCalibration], sensor-bridge):
 * each electrode from step 60 (0.81 mA) up one hardware step (13.5 µA) per "not yet" until clear and pain-free,
 * then the whole-array check with 39 grains on all nine electrodes. The 2.7 mA cap is enforced three times over:
 * the state machine never raises past step 200, [AmplitudeSteps.requireStep] refuses anything else, and
 * [FirmwareGrainParams] and [FirmwareStimulus] check every step before a command exists. Each electrode's 200 ms
 * stimulus ([giveStimulus]) and the check go to the board through [link], and a NACK (with the firmware's reason) or a
 * missing ack replaces the message with a one-line error; [onCalibrated] gets the finished steps (kept for the compliance study).
 * Not thread-safe: call from the main thread.
 */
class ElectrotactileCalibrationViewModel(
    private val link: StimulatorLink,
    private val onCalibrated: (List<Int>) -> Unit = {},
) : ViewModel() {
    private var calibration = ElectrotactileCalibration()

    /** Bumped after every change to [calibration] (it is mutable, so the flow needs a new value). */
    private val progress = MutableStateFlow(Progress(0, sent = false, message = null, problem = false))

    /** What the screen shows. */
    val uiState: StateFlow<ElectrotactileUiState> = combine(progress, link.ready) { p, ready -> snapshot(p, ready) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, snapshot(progress.value, ready = false))

    /** Not clear yet: the next stimulus of this electrode is one step stronger, never past 2.7 mA. */
    fun notYet() = change {
        val before = calibration.steps()[calibration.currentElectrode ?: return@change null]
        calibration.notYet()
        if (before == AmplitudeSteps.STEPS) "Already at the 2.7 mA cap: it cannot go higher" else null
    }

    /** Clear and pain-free: the electrode keeps its step; on to the next electrode or the whole-array check. */
    fun clearAndPainFree() = change {
        if (calibration.currentElectrode == null) return@change null
        calibration.clearAndPainFree()
        null
    }

    /** Too strong: one step weaker (every electrode during the whole-array check). */
    fun tooStrong() = change {
        if (calibration.isDone) return@change null
        calibration.tooStrong()
        null
    }

    /** The whole-array check felt right: calibration is done. */
    fun wholeArrayOk() = change {
        if (!calibration.isCheckingWholeArray) return@change null
        calibration.wholeArrayOk()
        onCalibrated(calibration.result().steps)
        "Saved: the compliance study stimulates at these levels"
    }

    /**
     * Gives the current electrode's next stimulus on the board: STIMULATE with that electrode alone at its step for
     * 200 ms ([FirmwareStimulus]); the person then answers with not yet, too strong, or clear and pain-free.
     */
    fun giveStimulus() {
        if (calibration.currentElectrode == null) return
        val stimulus = FirmwareStimulus.of(calibration.stimulus() ?: return)
        val handle = link.stimulate(stimulus)
        progress.update {
            it.copy(
                problem = false,
                message = if (handle != null) {
                    String.format(
                        Locale.ROOT, "Gave %d ms at %.3f mA on electrode %d: how did it feel?",
                        stimulus.durationMillis, AmplitudeSteps.milliampsOf(stimulus.step), stimulus.electrode + 1,
                    )
                } else {
                    StimulatorLink.NO_BOARD
                },
            )
        }
        handle?.let(::reportProblems)
    }

    /**
     * Sends the whole-array check to the board: SET_GRAINS with [ElectrotactileCalibration.CHECK_GRAINS] grains,
     * all nine electrodes at their steps, over the force range the board announced ([StimulatorLink.forceRange]).
     */
    fun sendWholeArrayCheck() {
        if (!calibration.isCheckingWholeArray) return
        val range = link.forceRange()
            ?: return progress.update { it.copy(sent = false, message = if (link.isReady()) StimulatorLink.NO_FORCE_RANGE else StimulatorLink.NO_BOARD) }
        val params = try {
            FirmwareGrainParams.wholeArrayCheck(calibration.steps(), range)
        } catch (e: SafetyLimitException) {
            // Unreachable while the state machine caps at step 200; kept so a future bug refuses instead of stimulating.
            progress.update { it.copy(message = e.message, problem = true) }
            return
        }
        val handle = link.send(params)
        progress.update {
            it.copy(sent = handle != null, problem = false, message = if (handle != null) "Sent: press the sensor and feel the grains" else StimulatorLink.NO_BOARD)
        }
        handle?.let(::reportProblems)
    }

    /**
     * Waits for [handle]'s outcome and, when the board refused it, never answered, or it could not be written, shows
     * why as an error (and the check as not sent), unless the levels changed meanwhile.
     */
    private fun reportProblems(handle: CommandHandle) {
        val revision = progress.value.revision
        viewModelScope.launch {
            val outcome = handle.state.first { it.isFinal }
            val problem = describeProblem(handle.description, outcome) ?: return@launch
            progress.update { if (it.revision == revision) it.copy(sent = false, message = problem, problem = true) else it }
        }
    }

    /** Starts again from electrode 0 at step 60. */
    fun restart() {
        calibration = ElectrotactileCalibration()
        progress.update { Progress(it.revision + 1, sent = false, message = null, problem = false) }
    }

    private fun change(action: () -> String?) {
        val message = action()
        // Any level change makes what the board has stale.
        progress.update { Progress(it.revision + 1, sent = false, message = message, problem = false) }
    }

    private fun snapshot(p: Progress, ready: Boolean): ElectrotactileUiState {
        val steps = calibration.steps()
        val electrode = calibration.currentElectrode
        return when {
            electrode != null -> {
                val step = steps[electrode]
                ElectrotactileUiState.Electrode(electrode, step, AmplitudeSteps.milliampsOf(step), step == AmplitudeSteps.STEPS, steps, ready, p.message, p.problem)
            }
            calibration.isCheckingWholeArray -> ElectrotactileUiState.WholeArrayCheck(p.sent, steps, ready, p.message, p.problem)
            else -> {
                val result = calibration.result()
                val limit = if (result.steps.all { it == 0 }) null else result.userLimit().maxMilliamps
                ElectrotactileUiState.Done(limit, steps, ready, p.message, p.problem)
            }
        }
    }

    private data class Progress(val revision: Int, val sent: Boolean, val message: String?, val problem: Boolean)
}
