package org.hapticon.app.feature.study

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceProtocol
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.ComplianceTrial
import org.hapticon.study.compliance.MagnitudeEstimate
import org.hapticon.study.compliance.MagnitudeEstimation
import java.io.File
import java.io.FileOutputStream

/** What the compliance study screen shows: the set-up, a trial, or the finished session. */
sealed interface ComplianceUiState {
    /** Whether a framed board is streaming (conditions are rendered by its firmware). */
    val boardReady: Boolean

    /** A refusal or a confirmation. */
    val message: String?

    /** Before the session: who, which participant number (the trial order), how many repetitions, and the calibration. */
    data class Setup(
        val protocol: ComplianceProtocol,
        val participant: String,
        val participantIndex: Int,
        /** The electrotactile calibration's steps, or null before one was finished. */
        val levels: List<Int>?,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState

    /** Trial [ComplianceTrial.index] + 1 of [total]: the condition on the board, waiting for the participant's number. */
    data class Trial(
        val participant: String,
        val trial: ComplianceTrial,
        val total: Int,
        val instructions: String,
        /** Whether this trial's condition reached the board (answers are taken only then). */
        val sent: Boolean,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState

    /** Every trial answered: each condition's normalised geometric mean, and where the answers are. */
    data class Done(
        val participant: String,
        val answers: Int,
        val means: Map<String, Double>,
        val file: String,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState
}

/**
 * Runs Shaping Compliance's study ([ComplianceStudy.PROTOCOL]: 0/9/19/39 grains × five electrode shapes, magnitude
 * estimation) with a participant: when a trial starts its condition goes to the board as SET_GRAINS
 * ([ComplianceCondition.firmwareParams]: its grains over the board's announced force range, its electrode shape, each
 * electrode at the person's calibrated step from [levels]; the reference firmware renders the grains stand-alone while
 * the participant presses), and the participant's number is appended to `<participant>.csv` in [answersDir] (and
 * synced) before the next trial, so an answered trial is never lost. No calibration, no session.
 *
 * Disk work (reading the calibration through [levels], appending and syncing an answer) runs on [io], never on the
 * main thread (debug builds' StrictMode would flag it); the next trial starts only once the answer is synced, and a
 * failed write leaves the trial where it was, saying so, for the answer to be given again. A session keeps the levels
 * read when it started: a calibration finished meanwhile applies to the next session, not half-way through this one.
 */
class ComplianceViewModel(
    private val link: StimulatorLink,
    private val levels: () -> List<Int>?,
    private val answersDir: File,
    private val protocol: ComplianceProtocol = ComplianceStudy.PROTOCOL,
    private val io: CoroutineDispatcher = Dispatchers.IO,
) : ViewModel() {
    private val local = MutableStateFlow<ComplianceUiState>(setup("", 0, null))

    /** The levels the running session stimulates at, read once when it started. */
    private var sessionSteps: List<Int>? = null

    /** True while an answer is being written: a second answer (a double tap) is ignored until it is synced. */
    private var saving = false

    /** What the screen shows, with the board's state kept current. */
    val uiState: StateFlow<ComplianceUiState> = combine(local, link.ready) { state, ready -> withBoard(state, ready) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, local.value)

    private var trials: List<ComplianceTrial> = emptyList()
    private val answered = ArrayList<MagnitudeEstimate>()

    init {
        refreshLevels()
    }

    /** Names the participant (their answers file). */
    fun setParticipant(name: String) = updateSetup { it.copy(participant = name, message = null) }

    /** The participant's number: which shuffled order of the trials they get. */
    fun setParticipantIndex(index: Int) = updateSetup { it.copy(participantIndex = index.coerceAtLeast(0)) }

    /** How many times each condition is felt (1..[ComplianceProtocol.MAX_REPETITIONS]). */
    fun setRepetitions(repetitions: Int) = updateSetup {
        it.copy(protocol = it.protocol.copy(repetitions = repetitions.coerceIn(1, ComplianceProtocol.MAX_REPETITIONS)))
    }

    /** Starts the session: needs a participant name and a finished calibration; sends the first condition. */
    fun start() {
        if (local.value !is ComplianceUiState.Setup) return
        viewModelScope.launch {
            val steps = withContext(io) { levels() }
            // The set-up as it is now (a second tap meanwhile already started the session: nothing to do).
            val setup = local.value as? ComplianceUiState.Setup ?: return@launch
            val name = setup.participant.trim()
            if (!NAME.matches(name)) {
                local.value = setup.copy(levels = steps, message = "Name the participant with letters, digits, - or _")
                return@launch
            }
            if (steps == null) {
                local.value = setup.copy(levels = null, message = "Calibrate the electrodes first: Sensors → Electrotactile array")
                return@launch
            }
            sessionSteps = steps
            trials = setup.protocol.trials(setup.participantIndex)
            answered.clear()
            local.value = ComplianceUiState.Trial(name, trials.first(), trials.size, setup.protocol.instructions, sent = false, boardReady = false, message = null)
            sendCondition(steps)
        }
    }

    /** Sends the current trial's condition to the board (again). */
    fun sendCondition() {
        sendCondition(sessionSteps ?: return)
    }

    private fun sendCondition(steps: List<Int>) {
        val trial = local.value as? ComplianceUiState.Trial ?: return
        // The board's own range (its device info), so a full press fires the condition's grains on any ADC.
        val range = link.forceRange()
            ?: return run { local.value = trial.copy(sent = false, message = if (link.isReady()) StimulatorLink.NO_FORCE_RANGE else NO_BOARD) }
        val sent = link.send(trial.trial.condition.firmwareParams(steps, range, protocol.distribution)) != null
        local.value = trial.copy(sent = sent, message = if (sent) null else NO_BOARD)
    }

    /** The participant's answer for the current trial: a positive number, stored before the next trial starts. */
    fun answer(text: String) {
        val trial = local.value as? ComplianceUiState.Trial ?: return
        if (!trial.sent) return run { local.value = trial.copy(message = "The condition has not reached the board yet") }
        val value = try {
            MagnitudeEstimation.requireEstimate(text.trim().toDoubleOrNull() ?: Double.NaN)
        } catch (e: IllegalArgumentException) {
            return run { local.value = trial.copy(message = "Type a positive number, e.g. 10") }
        }
        if (saving) return
        saving = true
        val file = File(answersDir, "${trial.participant}.csv")
        viewModelScope.launch {
            val written = withContext(io) { runCatching { append(file, trial, value) } }
            saving = false
            written.exceptionOrNull()?.let { e ->
                // Not acknowledged, so nothing is lost: the trial stays and its answer can be given again.
                local.value = trial.copy(message = "Not saved (${e.message ?: e.javaClass.simpleName}): give the answer again")
                return@launch
            }
            answered += MagnitudeEstimate(trial.participant, trial.trial.condition.id, value)
            val next = trials.getOrNull(trial.trial.index + 1)
            if (next == null) {
                local.value = ComplianceUiState.Done(
                    trial.participant, answered.size, MagnitudeEstimation.conditionMeans(answered), file.path, boardReady = false, message = null,
                )
            } else {
                local.value = trial.copy(trial = next, sent = false, message = null)
                sendCondition()
            }
        }
    }

    /** Back to the set-up (the answers given so far stay in the file). */
    fun finish() {
        sessionSteps = null
        local.value = setup("", 0, null)
        refreshLevels()
    }

    private fun setup(participant: String, index: Int, message: String?) =
        ComplianceUiState.Setup(protocol, participant, index, levels = null, boardReady = false, message = message)

    private fun updateSetup(change: (ComplianceUiState.Setup) -> ComplianceUiState.Setup) {
        local.update { state -> if (state is ComplianceUiState.Setup) change(state) else state }
        // Read again on every set-up change, so a calibration finished meanwhile shows up before the session starts.
        refreshLevels()
    }

    /** Reads the stored calibration off the main thread into the set-up. */
    private fun refreshLevels() {
        viewModelScope.launch {
            val read = withContext(io) { levels() }
            local.update { state -> if (state is ComplianceUiState.Setup) state.copy(levels = read) else state }
        }
    }

    private fun append(file: File, trial: ComplianceUiState.Trial, value: Double) {
        file.parentFile?.mkdirs()
        val header = !file.exists()
        FileOutputStream(file, true).use { out ->
            if (header) out.write("$CSV_HEADER\n".toByteArray())
            val t = trial.trial
            out.write("${trial.participant},${t.index},${t.condition.id},${t.condition.grains},${t.condition.mask.name.lowercase()},${t.repetition},$value\n".toByteArray())
            // Synced before the next trial: an acknowledged answer survives a crash or a flat battery.
            out.fd.sync()
        }
    }

    private fun withBoard(state: ComplianceUiState, ready: Boolean): ComplianceUiState = when (state) {
        is ComplianceUiState.Setup -> state.copy(boardReady = ready)
        is ComplianceUiState.Trial -> state.copy(boardReady = ready)
        is ComplianceUiState.Done -> state.copy(boardReady = ready)
    }

    companion object {
        /** The answers file's columns. */
        const val CSV_HEADER: String = "participant,trial,condition,grains,electrodes,repetition,estimate"

        private val NAME = Regex("[A-Za-z0-9_-]{1,40}")

        private const val NO_BOARD = "Connect the board (Framed protocol) to render the condition"
    }
}
