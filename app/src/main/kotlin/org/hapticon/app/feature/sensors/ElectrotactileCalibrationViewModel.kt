package org.hapticon.app.feature.sensors

import org.hapticon.app.data.ElectrodeLevelsStore
import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import java.io.IOException
import java.io.InputStream
import java.io.OutputStream
import org.hapticon.sensor.electrotactile.CalibrationFile
import org.hapticon.sensor.electrotactile.StoredCalibration
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

    /** True when [message] says something went wrong (the board refused or did not answer, a file was refused): shown as an error. */
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

    /**
     * All nine electrodes at their levels while the person presses, [ElectrotactileCalibration.CHECK_GRAINS] grains per
     * press, adjusted until the sensation is uniform: [selected] is the electrode the person says stands out (0..8), or null.
     */
    data class WholeArrayCheck(
        /** Whether the check's SET_GRAINS command was queued for the board since the levels last changed. */
        val sent: Boolean,
        val selected: Int? = null,
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
 * then the whole-array check with 39 grains on all nine electrodes, adjusted electrode by electrode until the sensation is
 * uniform (003_8ca1dc8f53472543.txt:152). The 2.7 mA cap is enforced three times over:
 * the state machine never raises past step 200, [AmplitudeSteps.requireStep] refuses anything else, and
 * [FirmwareGrainParams] and [FirmwareStimulus] check every step before a command exists. Each electrode's 200 ms
 * stimulus ([giveStimulus]) and the check go to the board through [link], and a NACK (with the firmware's reason) or a
 * missing ack replaces the message with a one-line error.
 *
 * The finished steps go to [store] (the calibration file the compliance study reads); [exportTo] writes the stored
 * calibration to a file the researcher picked and [importFrom] reads one (from `hapticon board calibrate --save` or
 * another phone), refusing a bad file with one line that names the member at fault and keeping what was stored.
 * File work runs on [io], never on the main thread. Not thread-safe: call from the main thread.
 */
class ElectrotactileCalibrationViewModel(
    private val link: StimulatorLink,
    private val store: ElectrodeLevelsStore? = null,
    private val io: CoroutineDispatcher = Dispatchers.IO,
) : ViewModel() {
    private var calibration = ElectrotactileCalibration()

    /** Bumped after every change to [calibration] (it is mutable, so the flow needs a new value). */
    private val progress = MutableStateFlow(Progress(0, sent = false, message = null, problem = false))

    private val stored = MutableStateFlow<StoredCalibration?>(null)

    /**
     * The calibration the compliance study uses (the last finished or imported one), or null when there is none: read
     * from [store] off the main thread. Apart from [uiState] because it does not follow the calibration's steps: an
     * import replaces it in the middle of a calibration, and a new calibration leaves it until it is finished.
     */
    val storedCalibration: StateFlow<StoredCalibration?> = stored

    /** What the screen shows. */
    val uiState: StateFlow<ElectrotactileUiState> = combine(progress, link.ready) { p, ready -> snapshot(p, ready) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, snapshot(progress.value, ready = false))

    init {
        store?.let { store -> viewModelScope.launch { stored.value = withContext(io) { store.stored() } } }
    }

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

    /** Whole-array check: [electrode] (0..8) is the one the person says stands out; [weaker] and [stronger] move it. */
    fun selectElectrode(electrode: Int) {
        if (!calibration.isCheckingWholeArray || electrode !in 0 until ElectrotactileCalibration.ELECTRODES) return
        progress.update { it.copy(selected = electrode) }
    }

    /** Whole-array check: the selected electrode one step weaker (it stood out as stronger). */
    fun weaker() = adjustSelected { calibration.weaker(it) }

    /** Whole-array check: the selected electrode one step stronger (it was felt less), never past 2.7 mA. */
    fun stronger() = adjustSelected { calibration.stronger(it) }

    private fun adjustSelected(adjust: (Int) -> Unit) {
        val electrode = progress.value.selected ?: return
        if (!calibration.isCheckingWholeArray) return
        adjust(electrode)
        // The board's check is stale: send it again with the new level, keeping the electrode selected.
        progress.update { Progress(it.revision + 1, sent = false, message = null, problem = false, selected = electrode) }
        sendWholeArrayCheck()
    }

    /** The whole-array check felt right: calibration is done. */
    fun wholeArrayOk() {
        if (!calibration.isCheckingWholeArray) return
        change {
            calibration.wholeArrayOk()
            null
        }
        save(calibration.result().steps)
    }

    /** Stores [steps] off the main thread; says so when done, or why it failed. */
    private fun save(steps: List<Int>) = fileWork(
        work = { store -> store.save(steps) },
        report = { saved, error ->
            if (saved != null) "Saved: the compliance study stimulates at these levels" else "Not saved: ${oneLine(error)}"
        },
    )

    /**
     * Writes the stored calibration, as a `hapticon.electrotactile-calibration` file, to the stream [open] gives
     * (the file the researcher picked; null when it could not be opened).
     */
    fun exportTo(open: () -> OutputStream?) = fileWork(
        work = { store ->
            store.stored()?.also { kept ->
                val out = open() ?: throw IOException("the file could not be opened")
                out.use { it.write(CalibrationFile.encode(kept).toByteArray(Charsets.UTF_8)) }
            } ?: throw NothingToExport()
        },
        report = { exported, error ->
            when {
                exported != null -> "Exported ${ElectrodeLevelsStore.describe(exported)}"
                error is NothingToExport -> "Nothing to export: finish a calibration or import one first"
                else -> "Not exported: ${oneLine(error)}"
            }
        },
    )

    /**
     * Reads a calibration file from the stream [open] gives (null when it could not be opened) and, when it is valid,
     * stores it for the compliance study; a bad file is refused with one line naming the member at fault, and the
     * stored calibration stays as it was.
     */
    fun importFrom(open: () -> InputStream?) = fileWork(
        work = { store ->
            val input = open() ?: throw IOException("the file could not be opened")
            // One byte past the limit is enough to refuse a file that is too large without reading it all.
            store.import(input.use { it.readNBytes(CalibrationFile.MAX_BYTES + 1) })
        },
        report = { imported, error ->
            if (imported != null) "Imported ${ElectrodeLevelsStore.describe(imported)}: the compliance study now stimulates at these levels" else "Not imported: ${oneLine(error)}"
        },
    )

    /**
     * The one way this screen touches files: [work] on [store] off the main thread, then its outcome as the message
     * ([report] gets the calibration, or null and the error; an error is shown as a problem). The calibration [work]
     * returns is what the store holds now (saved, imported, or the one exported), so it becomes [storedCalibration].
     */
    private fun fileWork(
        work: (ElectrodeLevelsStore) -> StoredCalibration,
        report: (StoredCalibration?, Throwable?) -> String,
    ) {
        val store = store ?: return progress.update { it.copy(message = NO_STORE, problem = true) }
        viewModelScope.launch {
            val outcome = withContext(io) { runCatching { work(store) } }
            outcome.onSuccess { stored.value = it }
            val message = report(outcome.getOrNull(), outcome.exceptionOrNull())
            progress.update { it.copy(message = message, problem = outcome.isFailure) }
        }
    }

    /** There is no stored calibration to export. */
    private class NothingToExport : Exception()

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
        progress.update { Progress(it.revision + 1, sent = false, message = message, problem = false, selected = it.selected) }
    }

    private fun snapshot(p: Progress, ready: Boolean): ElectrotactileUiState {
        val steps = calibration.steps()
        val electrode = calibration.currentElectrode
        return when {
            electrode != null -> {
                val step = steps[electrode]
                ElectrotactileUiState.Electrode(electrode, step, AmplitudeSteps.milliampsOf(step), step == AmplitudeSteps.STEPS, steps, ready, p.message, p.problem)
            }
            calibration.isCheckingWholeArray -> ElectrotactileUiState.WholeArrayCheck(p.sent, p.selected, steps, ready, p.message, p.problem)
            else -> {
                val result = calibration.result()
                val limit = if (result.steps.all { it == 0 }) null else result.userLimit().maxMilliamps
                ElectrotactileUiState.Done(limit, steps, ready, p.message, p.problem)
            }
        }
    }

    private data class Progress(val revision: Int, val sent: Boolean, val message: String?, val problem: Boolean, val selected: Int? = null)

    companion object {
        /** Shown when the view model was made without a store (a preview or a test). */
        const val NO_STORE: String = "No calibration store on this screen"

        // A file's problem on one line (a CalibrationFileException's message is one already, naming the member at fault).
        private fun oneLine(error: Throwable?): String =
            (error?.message ?: error?.javaClass?.simpleName ?: "unknown error").lineSequence().first()
    }
}
