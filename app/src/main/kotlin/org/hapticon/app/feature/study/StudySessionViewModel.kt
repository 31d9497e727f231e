package org.hapticon.app.feature.study

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import kotlinx.coroutines.sync.Mutex
import kotlinx.coroutines.sync.withLock
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.playOffMain
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.app.playback.Playback
import org.hapticon.app.study.MaskingNoisePlayer
import org.hapticon.app.study.SessionRecord
import org.hapticon.app.study.StudyRepository
import org.hapticon.study.LikertScale
import org.hapticon.study.StudyPlan
import org.hapticon.study.StudySession
import org.hapticon.study.StudyStep
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.StudyEvent

/**
 * A participant's session walk. Where the participant is comes only from the event log ([StudySession.nextStep]),
 * so a new ViewModel on the same database (after a crash or kill) resumes at the exact next step. Every event is
 * appended through the study module's hash chain ([EventLog]) and stored before the screen moves on; a mutex keeps
 * appends in order. The masking noise plays while a task's trials (or the screen of all its icons) are on screen.
 *
 * Actions return their [Job] so that callers (tests) can wait for the write.
 */
class StudySessionViewModel(
    private val sessionId: Long,
    private val repository: StudyRepository,
    private val player: HapticPlayer,
    private val noise: MaskingNoisePlayer,
    private val clock: () -> Long = System::currentTimeMillis,
) : ViewModel() {
    private val mutex = Mutex()

    /**
     * Where the walk stands: the events logged so far and the screen's own choices (the value picked, whether the
     * icon plays). Written only under [mutex], after the event is stored; the participant's screen is derived from it.
     */
    private val walk = MutableStateFlow<Walk>(Walk.Loading)

    /** What the participant sees: the step the log says comes next, with the progress and the screen's choices. */
    val uiState: StateFlow<SessionUiState> = walk.map(::uiStateOf).stateIn(viewModelScope, SharingStarted.Eagerly, SessionUiState.Loading)

    private lateinit var record: SessionRecord
    private lateinit var log: EventLog
    private lateinit var session: StudySession
    private var selection: Int? = null
    private var playing = false
    private var paused = false
    private var noiseOn = false

    /** Completes once the log is loaded and the current step is on screen (and logged). */
    val loaded: Job = viewModelScope.launch {
        mutex.withLock {
            val found = repository.session(sessionId) ?: return@withLock fail("session $sessionId does not exist")
            val entries = repository.entries(sessionId)
            try {
                log = EventLog.resume(found.participant, entries)
                session = StudySession(StudyPlan.ofSession(found.protocol, log.events))
            } catch (e: IllegalArgumentException) {
                return@withLock fail("this session cannot continue: ${e.message}")
            }
            record = found
            enter()
        }
    }

    /** Leaves the current task intro: logs TaskStarted and shows the first trial. */
    fun startTask(): Job = leave { step -> (step as? StudyStep.TaskIntro)?.let { StudyEvent.TaskStarted(it.task.id) } }

    /**
     * Plays the trial's icon: logs IconPressed, PlaybackStarted when the actuator starts, and PlaybackFinished when it
     * is done (after the playback's duration). The returned job completes after PlaybackFinished; the screen stays
     * usable meanwhile.
     */
    fun pressIcon(): Job = pressStimulus(null)

    /**
     * Plays icon [stimulusId] of the screen showing all of a task's icons together ([StudyStep.Explore]), logging as
     * [pressIcon] does; any icon, in any order, as often as the participant likes.
     */
    fun pressIcon(stimulusId: String): Job = pressStimulus(stimulusId)

    private fun pressStimulus(stimulusId: String?): Job = viewModelScope.launch {
        var finish: Triple<String, String, Long>? = null
        act { step ->
            val (taskId, stimulus) = when (step) {
                is StudyStep.Trial -> step.task.id to step.stimulus
                is StudyStep.Explore -> step.task.id to (step.stimuli.firstOrNull { it.id == stimulusId } ?: return@act)
                else -> return@act
            }
            append(StudyEvent.IconPressed(taskId, stimulus.id))
            // The protocol's envelope model: a paper-model protocol plays the paper's trapezoids, the default what the study's participants felt.
            // The participant's press in the open app: a touch. One Android ignores (Battery Saver) is not logged as started.
            val playback = player.playOffMain(stimulus.icon, record.protocol.envelopeModel, VibrationUsage.TOUCH)
            if (playback is Playback.Playing) {
                append(StudyEvent.PlaybackStarted(taskId, stimulus.id))
                playing = true
                finish = Triple(taskId, stimulus.id, playback.durationMillis)
            }
            publish()
        }.join()
        val (taskId, id, duration) = finish ?: return@launch
        delay(duration)
        mutex.withLock {
            append(StudyEvent.PlaybackFinished(taskId, id))
            playing = false
            publish()
        }
    }

    /** Leaves the screen of all the task's icons: logs ExplorationEnded and shows the task's first question. */
    fun finishExploring(): Job = leave { step -> (step as? StudyStep.Explore)?.let { StudyEvent.ExplorationEnded(it.task.id) } }

    /** Selects [value] on the scale; nothing is logged until [next]. */
    fun select(value: Int): Job = act { step ->
        if (step is StudyStep.Trial && record.protocol.scale.accepts(value)) {
            selection = value
            publish()
        }
    }

    /** Logs the selected answer and moves to the next trial or the task end. Ignored until the icon was pressed and a value selected. */
    fun next(): Job = act { step ->
        val value = selection
        if (step is StudyStep.Trial && value != null && pressed(log.events, step)) {
            append(StudyEvent.Answer(step.task.id, step.stimulus.id, value))
            selection = null
            enter()
        }
    }

    /** Leaves the task end: logs TaskEnded and shows the next task's intro, or the end of the session. */
    fun finishTask(): Job = leave { step -> (step as? StudyStep.TaskEnd)?.let { StudyEvent.TaskEnded(it.task.id) } }

    /** The app went to the background: the noise stops. */
    fun pause(): Job = act {
        paused = true
        stopNoise()
    }

    /** The app is back: the noise resumes if a task is under way. */
    fun resume(): Job = act { step ->
        paused = false
        if (step is StudyStep.Trial || step is StudyStep.Explore) startNoise()
    }

    override fun onCleared() {
        noise.stop()
        player.stop()
    }

    // Logs the event that completes the current step, when [eventFor] has one for it, and shows the next step.
    private fun leave(eventFor: (StudyStep) -> StudyEvent?): Job = act { step ->
        eventFor(step)?.let {
            append(it)
            enter()
        }
    }

    private fun act(block: suspend (StudyStep) -> Unit): Job = viewModelScope.launch {
        loaded.join()
        mutex.withLock {
            if (walk.value is Walk.Going) block(session.nextStep(log.events))
        }
    }

    // Logs what showing the current step implies, starts or stops the noise, and publishes the step.
    private suspend fun enter() {
        when (val step = session.nextStep(log.events)) {
            is StudyStep.Trial -> {
                // Logged on every showing, also after a restart: response times count from the last one.
                append(StudyEvent.StimulusShown(step.task.id, step.stimulus.id))
                if (!paused) startNoise()
            }
            is StudyStep.Explore -> if (!paused) startNoise()
            is StudyStep.TaskIntro, is StudyStep.TaskEnd -> stopNoise()
            StudyStep.Done -> {
                stopNoise()
                if (log.events.none { it == StudyEvent.SessionEnded }) append(StudyEvent.SessionEnded)
            }
        }
        publish()
    }

    // Started once per task, not per trial: restarting the loop at every trial would be audible.
    private fun startNoise() {
        if (!noiseOn && record.masking.isOn) {
            noise.start(record.masking)
            noiseOn = true
        }
    }

    private fun stopNoise() {
        if (noiseOn) noise.stop()
        noiseOn = false
    }

    private suspend fun append(event: StudyEvent) {
        val entry = log.append(event, clock())
        repository.append(sessionId, entry)
    }

    private fun pressedIn(events: List<StudyEvent>, taskId: String): Set<String> =
        events.mapNotNullTo(HashSet()) { (it as? StudyEvent.IconPressed)?.takeIf { e -> e.taskId == taskId }?.stimulusId }

    private fun pressed(events: List<StudyEvent>, step: StudyStep.Trial): Boolean = events.any {
        it is StudyEvent.IconPressed && it.taskId == step.task.id && it.stimulusId == step.stimulus.id
    }

    // Publishes the walk as it stands (the log hands out a fresh list of its events each time).
    private fun publish() {
        walk.value = Walk.Going(log.events, selection, playing)
    }

    private fun uiStateOf(walk: Walk): SessionUiState = when (walk) {
        Walk.Loading -> SessionUiState.Loading
        is Walk.Failed -> SessionUiState.Failed(walk.message)
        is Walk.Going -> {
            val step = session.nextStep(walk.events)
            SessionUiState.Active(
                participant = record.participant,
                step = step,
                scale = record.protocol.scale,
                answered = session.answeredTrials(walk.events),
                trials = session.plan.trials.size,
                selected = walk.selection,
                iconPressed = step is StudyStep.Trial && pressed(walk.events, step),
                pressedStimuli = if (step is StudyStep.Explore) pressedIn(walk.events, step.task.id) else emptySet(),
                playing = walk.playing,
            )
        }
    }

    private fun fail(message: String) {
        stopNoise()
        walk.value = Walk.Failed(message)
    }

    /** The walk's sources: nothing read yet, a log that cannot go on, or the events logged and the screen's choices. */
    private sealed interface Walk {
        data object Loading : Walk

        data class Failed(val message: String) : Walk

        data class Going(val events: List<StudyEvent>, val selection: Int?, val playing: Boolean) : Walk
    }
}

/** What the participant's screen shows. */
sealed interface SessionUiState {
    data object Loading : SessionUiState

    /** The session cannot go on (its log is broken or missing); the researcher has to step in. */
    data class Failed(val message: String) : SessionUiState

    /** The session at [step]: [answered] of [trials] rated so far. */
    data class Active(
        val participant: String,
        val step: StudyStep,
        val scale: LikertScale,
        val answered: Int,
        val trials: Int,
        /** The value picked on the scale but not yet confirmed with Next. */
        val selected: Int?,
        /** Whether the participant has felt this trial's icon at least once. */
        val iconPressed: Boolean,
        /** Whether the icon is playing now. */
        val playing: Boolean,
        /** On the screen of all a task's icons ([StudyStep.Explore]): the stimuli pressed so far. */
        val pressedStimuli: Set<String> = emptySet(),
    ) : SessionUiState {
        /** Next is enabled once the icon was pressed and a value chosen. */
        val canContinue: Boolean get() = step is StudyStep.Trial && iconPressed && selected != null
    }
}
