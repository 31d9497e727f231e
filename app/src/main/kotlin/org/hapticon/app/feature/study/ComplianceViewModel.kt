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
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.study.compliance.ComplianceAnswersCsv
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceProtocol
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.ComplianceTask
import org.hapticon.study.compliance.ComplianceTrial
import org.hapticon.study.compliance.DrawingPoint
import org.hapticon.study.compliance.MagnitudeEstimate
import org.hapticon.study.compliance.MagnitudeEstimation
import java.io.File
import java.io.FileOutputStream
import java.time.Instant
import java.util.Locale

/** What the compliance study screen shows: the set-up, a calibration (with a break), a trial, or the finished session. */
sealed interface ComplianceUiState {
    /** Whether a framed board is streaming (conditions are rendered by its firmware). */
    val boardReady: Boolean

    /** A refusal or a confirmation. */
    val message: String?

    /** Before the session: which protocol, who, which participant number (the trial order), and the stored calibration. */
    data class Setup(
        val protocols: List<ComplianceProtocol>,
        val protocol: ComplianceProtocol,
        val participant: String,
        val participantIndex: Int,
        /** The stored electrotactile calibration, or null when there is none. */
        val calibration: StoredCalibration?,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState

    /**
     * Before [next]: calibrate the electrodes again (Shaping Compliance recalibrates before each repetition,
     * 003_8ca1dc8f53472543.txt:152), after a break when [isBreak]. [fresh] says whether the stored [calibration] was
     * made since this step began, which the session needs before it goes on.
     */
    data class Calibrate(
        val participant: String,
        val protocol: ComplianceProtocol,
        val next: ComplianceTrial,
        val isBreak: Boolean,
        val calibration: StoredCalibration?,
        val fresh: Boolean,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState

    /** Trial [ComplianceTrial.index] + 1 of [total]: the condition on the board, waiting for the participant's answer. */
    data class Trial(
        val participant: String,
        val protocol: ComplianceProtocol,
        val trial: ComplianceTrial,
        val total: Int,
        /** Whether this trial's condition reached the board (answers are taken only then). */
        val sent: Boolean,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState

    /** Every trial answered: where the answers are, a summary, and the export once made. */
    data class Done(
        val participant: String,
        val protocol: ComplianceProtocol,
        val answers: Int,
        val file: File,
        /** Task 1: each condition's median standardized score (condition id to median); empty for Task 2. */
        val medians: Map<String, Double>,
        /** Why [medians] could not be computed, or null. */
        val summaryProblem: String?,
        /** The copy of the answers file to share, once exported. */
        val exported: File?,
        override val boardReady: Boolean,
        override val message: String?,
    ) : ComplianceUiState
}

/**
 * Runs Shaping Compliance's study with a participant ([ComplianceStudy]: Task 1 as published by default, Task 2's
 * drawings, or our extended variant). When a trial starts its condition goes to the board as SET_GRAINS
 * ([ComplianceCondition.firmwareParams]: its grains over the board's announced force range, its electrode shape, each
 * electrode at the person's calibrated step); the reference firmware renders the grains stand-alone while the
 * participant presses. Before every trial the protocol marks [ComplianceTrial.calibrateBefore] (the first, and in Task 1
 * the first of each repetition, after a break) the session waits for a calibration made since then: the researcher runs
 * it ([calibration] is the stored one, read through the same store the calibration screen saves to) and goes on.
 *
 * Each answer (a signed rating, or Task 2's yes/no and drawing) is appended to `<participant>-<protocol>.csv` in
 * [answersDir] ([ComplianceAnswersCsv]) and synced before the next trial, so an answered trial is never lost; disk work
 * runs on [io], never on the main thread, a second tap while an answer is saved is ignored, and a failed write leaves the
 * trial where it was, saying so. [exportAnswers] copies the file to [exportsDir] for sharing.
 */
class ComplianceViewModel(
    private val link: StimulatorLink,
    private val calibration: () -> StoredCalibration?,
    private val answersDir: File,
    private val exportsDir: File = answersDir,
    private val io: CoroutineDispatcher = Dispatchers.IO,
    private val clock: () -> Instant = Instant::now,
) : ViewModel() {
    private val local = MutableStateFlow<ComplianceUiState>(setup(ComplianceStudy.PROTOCOL, "", 0, null))

    /** The levels the current block stimulates at: those of the calibration made before it. */
    private var sessionSteps: List<Int>? = null

    /** When the current calibration step began: a calibration must be at least this recent to go on. */
    private var calibrateSince: Instant = Instant.EPOCH

    /** True while an answer is being written: a second answer (a double tap) is ignored until it is synced. */
    private var saving = false

    /** What the screen shows, with the board's state kept current. */
    val uiState: StateFlow<ComplianceUiState> = combine(local, link.ready) { state, ready -> withBoard(state, ready) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, local.value)

    private var trials: List<ComplianceTrial> = emptyList()
    private val ratings = ArrayList<MagnitudeEstimate>()
    private var answered = 0

    init {
        refreshCalibration()
    }

    /** Picks the protocol (by [ComplianceProtocol.id]) of the next session. */
    fun selectProtocol(id: String) = updateSetup { state -> state.copy(protocol = state.protocols.firstOrNull { it.id == id } ?: state.protocol, message = null) }

    /** Names the participant (their answers file). */
    fun setParticipant(name: String) = updateSetup { it.copy(participant = name, message = null) }

    /** The participant's number: which counterbalanced order of the trials they get. */
    fun setParticipantIndex(index: Int) = updateSetup { it.copy(participantIndex = index.coerceAtLeast(0)) }

    /** Starts the session: needs a participant name; the first step is the calibration. */
    fun start() {
        val setup = local.value as? ComplianceUiState.Setup ?: return
        val name = setup.participant.trim()
        if (!NAME.matches(name)) {
            local.value = setup.copy(message = "Name the participant with letters, digits, - or _")
            return
        }
        trials = setup.protocol.trials(setup.participantIndex)
        ratings.clear()
        answered = 0
        sessionSteps = null
        enter(name, setup.protocol, trials.first())
    }

    /** Reads the stored calibration again (after the calibration screen closes), off the main thread. */
    fun refreshCalibration() {
        viewModelScope.launch {
            val read = withContext(io) { calibration() }
            local.update { state ->
                when (state) {
                    is ComplianceUiState.Setup -> state.copy(calibration = read)
                    is ComplianceUiState.Calibrate -> state.copy(calibration = read, fresh = isFresh(read))
                    else -> state
                }
            }
        }
    }

    /** After a fresh calibration: on to the trial it was made for, at its levels. */
    fun continueAfterCalibration() {
        val state = local.value as? ComplianceUiState.Calibrate ?: return
        viewModelScope.launch {
            val read = withContext(io) { calibration() }
            val current = local.value as? ComplianceUiState.Calibrate ?: return@launch
            if (read == null || !isFresh(read)) {
                local.value = current.copy(calibration = read, fresh = false, message = "Calibrate the electrodes first: the study recalibrates before this repetition")
                return@launch
            }
            sessionSteps = read.result.steps
            local.value = ComplianceUiState.Trial(state.participant, state.protocol, state.next, trials.size, sent = false, boardReady = false, message = null)
            sendCondition()
        }
    }

    /** Sends the current trial's condition to the board (again). */
    fun sendCondition() {
        val trial = local.value as? ComplianceUiState.Trial ?: return
        val steps = sessionSteps ?: return
        // The board's own range (its device info), so a full press fires the condition's grains on any ADC.
        val range = link.forceRange()
            ?: return run { local.value = trial.copy(sent = false, message = if (link.isReady()) StimulatorLink.NO_FORCE_RANGE else NO_BOARD) }
        val sent = link.send(trial.trial.condition.firmwareParams(steps, range, trial.protocol.distribution)) != null
        local.value = trial.copy(sent = sent, message = if (sent) null else NO_BOARD)
    }

    /** Task 1's answer for the current trial: a signed number, stored before the next trial starts. */
    fun answer(text: String) {
        val trial = sentTrial(ComplianceTask.MAGNITUDE) ?: return
        val value = MagnitudeEstimation.parse(text)
            ?: return run { local.value = trial.copy(message = "Type a number: positive if more compliant than the desk, negative if less, 0 if the same") }
        save(trial, ComplianceAnswersCsv.ratingRow(trial.protocol, trial.participant, trial.trial, value)) {
            ratings += MagnitudeEstimate(trial.participant, trial.trial.repetition, trial.trial.condition, value)
        }
    }

    /**
     * Task 2's answer for the current trial: whether it felt [moreCompliant] than the desk and the [contours] drawn
     * (each at least 3 points; at least one when more compliant).
     */
    fun answerDrawing(moreCompliant: Boolean?, contours: List<List<DrawingPoint>>) {
        val trial = sentTrial(ComplianceTask.DRAWING) ?: return
        if (moreCompliant == null) return run { local.value = trial.copy(message = "First answer: did it feel more compliant than the desk?") }
        val outlines = contours.filter { it.size >= 3 }
        if (moreCompliant && outlines.isEmpty()) return run { local.value = trial.copy(message = "Draw the outline of the area where you felt compliance") }
        save(trial, ComplianceAnswersCsv.drawingRow(trial.protocol, trial.participant, trial.trial, moreCompliant, outlines)) {}
    }

    /** Copies the answers file to the exports folder, for sharing. */
    fun exportAnswers() {
        val done = local.value as? ComplianceUiState.Done ?: return
        viewModelScope.launch {
            val copied = withContext(io) {
                runCatching {
                    if (!exportsDir.isDirectory && !exportsDir.mkdirs()) throw java.io.IOException("cannot create $exportsDir")
                    File(exportsDir, done.file.name).also { done.file.copyTo(it, overwrite = true) }
                }
            }
            local.update { state ->
                if (state !is ComplianceUiState.Done) return@update state
                copied.fold(
                    onSuccess = { state.copy(exported = it, message = null) },
                    onFailure = { state.copy(message = "Not exported (${it.message ?: it.javaClass.simpleName})") },
                )
            }
        }
    }

    /** Back to the set-up (the answers given so far stay in the file). */
    fun finish() {
        val protocol = when (val state = local.value) {
            is ComplianceUiState.Setup -> state.protocol
            is ComplianceUiState.Calibrate -> state.protocol
            is ComplianceUiState.Trial -> state.protocol
            is ComplianceUiState.Done -> state.protocol
        }
        sessionSteps = null
        local.value = setup(protocol, "", 0, null)
        refreshCalibration()
    }

    private fun sentTrial(task: ComplianceTask): ComplianceUiState.Trial? {
        val trial = local.value as? ComplianceUiState.Trial ?: return null
        if (trial.protocol.task != task) return null
        if (!trial.sent) {
            local.value = trial.copy(message = "The condition has not reached the board yet")
            return null
        }
        return trial
    }

    /** Appends [row] off the main thread; once synced, [kept] records it and the next trial (or calibration) follows. */
    private fun save(trial: ComplianceUiState.Trial, row: String, kept: () -> Unit) {
        if (saving) return
        saving = true
        val file = answersFile(trial.participant, trial.protocol)
        viewModelScope.launch {
            val written = withContext(io) { runCatching { append(file, row) } }
            saving = false
            written.exceptionOrNull()?.let { e ->
                // Not acknowledged, so nothing is lost: the trial stays and its answer can be given again.
                local.value = trial.copy(message = "Not saved (${e.message ?: e.javaClass.simpleName}): give the answer again")
                return@launch
            }
            kept()
            answered++
            val next = trials.getOrNull(trial.trial.index + 1)
            if (next == null) {
                local.value = done(trial, file)
            } else {
                enter(trial.participant, trial.protocol, next)
            }
        }
    }

    /** The next trial, or the calibration (and break) before it. */
    private fun enter(participant: String, protocol: ComplianceProtocol, next: ComplianceTrial) {
        if (next.calibrateBefore) {
            calibrateSince = clock()
            local.value = ComplianceUiState.Calibrate(participant, protocol, next, next.breakBefore, calibration = null, fresh = false, boardReady = false, message = null)
            refreshCalibration()
        } else {
            local.value = ComplianceUiState.Trial(participant, protocol, next, trials.size, sent = false, boardReady = false, message = null)
            sendCondition()
        }
    }

    private fun done(trial: ComplianceUiState.Trial, file: File): ComplianceUiState.Done {
        val (medians, problem) = if (trial.protocol.task == ComplianceTask.MAGNITUDE) {
            try {
                MagnitudeEstimation.standardize(ratings).groupBy { it.condition.id }
                    .mapValues { (_, scores) -> org.hapticon.study.analysis.Descriptives.of(scores.map { it.value }).median } to null
            } catch (e: IllegalArgumentException) {
                emptyMap<String, Double>() to e.message
            }
        } else {
            emptyMap<String, Double>() to null
        }
        return ComplianceUiState.Done(trial.participant, trial.protocol, answered, file, medians, problem, exported = null, boardReady = false, message = null)
    }

    private fun isFresh(read: StoredCalibration?): Boolean = read != null && !read.calibratedAt.isBefore(calibrateSince)

    private fun answersFile(participant: String, protocol: ComplianceProtocol) = File(answersDir, "$participant-${protocol.id}.csv")

    private fun setup(protocol: ComplianceProtocol, participant: String, index: Int, message: String?) =
        ComplianceUiState.Setup(ComplianceStudy.ALL, protocol, participant, index, calibration = null, boardReady = false, message = message)

    private fun updateSetup(change: (ComplianceUiState.Setup) -> ComplianceUiState.Setup) {
        local.update { state -> if (state is ComplianceUiState.Setup) change(state) else state }
    }

    private fun append(file: File, row: String) {
        file.parentFile?.mkdirs()
        val header = !file.exists()
        FileOutputStream(file, true).use { out ->
            if (header) out.write("${ComplianceAnswersCsv.HEADER}\n".toByteArray())
            out.write("$row\n".toByteArray())
            // Synced before the next trial: an acknowledged answer survives a crash or a flat battery.
            out.fd.sync()
        }
    }

    private fun withBoard(state: ComplianceUiState, ready: Boolean): ComplianceUiState = when (state) {
        is ComplianceUiState.Setup -> state.copy(boardReady = ready)
        is ComplianceUiState.Calibrate -> state.copy(boardReady = ready)
        is ComplianceUiState.Trial -> state.copy(boardReady = ready)
        is ComplianceUiState.Done -> state.copy(boardReady = ready)
    }

    companion object {
        private val NAME = Regex("[A-Za-z0-9_-]{1,40}")

        private const val NO_BOARD = "Connect the board (Framed protocol) to render the condition"

        /** A condition's name for the researcher: "39 grains, small square". */
        fun describe(condition: ComplianceCondition): String =
            "${condition.grains} grains, ${ComplianceCondition.shapeName(condition.mask).replace('-', ' ')}"

        /** A median as shown: two decimals. */
        fun format(value: Double): String = String.format(Locale.ROOT, "%.2f", value)
    }
}
