package org.hapticon.app.feature.gesture

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import java.io.InputStream
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.isActive
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.GestureSpans
import org.hapticon.app.gesture.SourceRecorder
import org.hapticon.app.gesture.readLimited
import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.recognition.LabelledWindows
import org.hapticon.gesture.recognition.PersonalTrainer
import org.hapticon.sensor.live.PlotSource

/** How a personal model trained: window accuracy on its own examples and on the held-out last take of each label. */
data class TrainingResult(
    val trainingAccuracy: Double,
    /** Null when there was a single take per label, so nothing to hold out. */
    val validationAccuracy: Double?,
    val windows: Int,
    val labels: List<GestureLabel>,
    /** Wall time of training the stored model, in ms. */
    val trainingMillis: Long,
)

/** The teach flow: which labels, how many takes, the examples so far, the take being recorded and the training outcome. */
sealed interface TeachUiState {
    /** Reading the stored model. */
    data object Loading : TeachUiState

    /** The teach flow, the stored model read. */
    data class Ready(
        val sourceKind: GestureSourceKind = GestureSourceKind.SENSOR_BOARD,
        /** The labels taught, [GestureLabel.NONE] always among them, in [GestureLabel.ALL] order. */
        val labels: List<GestureLabel> = TeachViewModel.DEFAULT_LABELS,
        val takesPerLabel: Int = TeachViewModel.DEFAULT_TAKES,
        /** Takes recorded per label. */
        val recorded: Map<GestureLabel, Int> = emptyMap(),
        val recording: Boolean = false,
        val seconds: Double = 0.0,
        val plotRevision: Long = 0,
        val channels: List<String> = emptyList(),
        val training: Boolean = false,
        val result: TrainingResult? = null,
        /** The stored model, for the summary line. */
        val model: GestureModel? = null,
        val message: String? = null,
    ) : TeachUiState {
        /** The next label to record a take of, or null when every label has its takes. */
        val next: GestureLabel? get() = labels.firstOrNull { (recorded[it] ?: 0) < takesPerLabel }

        /** Takes recorded over takes wanted. */
        val progress: Pair<Int, Int> get() = labels.sumOf { minOf(recorded[it] ?: 0, takesPerLabel) } to labels.size * takesPerLabel
    }
}

/**
 * Teaches a personal recognition model: records [TeachUiState.Ready.takesPerLabel] takes of each chosen label on
 * the chosen source (each take "rest, do it once, rest", at most [MAX_TAKE_SECONDS]; the gesture's span is
 * found by [GestureSpans]), trains with [PersonalTrainer] on [work] and stores the model through the
 * component's model store. Also imports a model made with `hapticon train`.
 */
class TeachViewModel(
    private val gestures: GestureComponent,
    private val trainer: PersonalTrainer = PersonalTrainer(),
    private val work: CoroutineDispatcher = Dispatchers.Default,
    private val nanoTime: () -> Long = System::nanoTime,
) : ViewModel() {
    private val recorder = SourceRecorder(MAX_TAKE_SECONDS)
    private val examples = ArrayList<Pair<GestureLabel, Recording>>()
    private val state = MutableStateFlow(TeachUiState.Ready())
    private val loaded = MutableStateFlow(false)
    private var ticker: Job? = null

    /** What the screen shows. */
    val uiState: StateFlow<TeachUiState> = combine(state, loaded) { ready, isLoaded -> if (isLoaded) ready else TeachUiState.Loading }
        .stateIn(viewModelScope, SharingStarted.Eagerly, TeachUiState.Loading)

    /** The live plot of the take being recorded. */
    val plot: PlotSource get() = recorder.history

    init {
        viewModelScope.launch {
            val stored = withContext(work) { gestures.models.model.value }
            state.update { it.copy(model = stored) }
            loaded.value = true
        }
    }

    /** Chooses the source the takes are recorded from; forgets takes from another source. */
    fun selectSource(kind: GestureSourceKind) {
        if (recorder.recording) return
        // Examples from another source have other channels: they cannot be trained together.
        examples.clear()
        state.update { it.copy(sourceKind = kind, recorded = emptyMap(), result = null, message = null) }
    }

    /** Adds or removes [label] from the taught labels ([GestureLabel.NONE] stays: the model must know rest). */
    fun toggleLabel(label: GestureLabel) {
        if (label.isNone || recorder.recording) return
        state.update {
            val labels = if (label in it.labels) it.labels - label else it.labels + label
            it.copy(labels = labels.sortedBy { l -> l.index })
        }
    }

    /** Sets how many takes each gesture gets (1 to [MAX_TAKES]). */
    fun setTakesPerLabel(takes: Int) {
        state.update { it.copy(takesPerLabel = takes.coerceIn(1, MAX_TAKES)) }
    }

    /** Starts recording a take of the next label. */
    fun startTake() {
        if (state.value.next == null) return
        val source = gestures.source(state.value.sourceKind) ?: run {
            state.update { it.copy(message = "This phone has no ${it.sourceKind.label.lowercase()}") }
            return
        }
        try {
            recorder.start(source)
        } catch (e: IllegalStateException) {
            state.update { it.copy(message = e.message) }
            return
        }
        state.update { it.copy(recording = true, seconds = 0.0, channels = source.channels.map { c -> c.name }, message = null) }
        ticker = viewModelScope.launch {
            while (isActive) {
                delay(RecorderViewModel.PLOT_REFRESH_MILLIS)
                state.update { it.copy(seconds = recorder.seconds, plotRevision = it.plotRevision + 1) }
                if (recorder.full) stopTake()
            }
        }
    }

    /** Stops the take and keeps it as an example of the label it was for. */
    fun stopTake() {
        if (!recorder.recording) return
        ticker?.cancel()
        ticker = null
        val take = recorder.stop()
        val label = state.value.next
        if (take != null && label != null) addExample(label, take) else state.update { it.copy(recording = false, message = "Nothing was recorded") }
    }

    /** Adds [take] as an example of [label] (the recorded takes go through here; tests call it directly). */
    fun addExample(label: GestureLabel, take: Recording) {
        val first = examples.firstOrNull()?.second
        if (first != null && first.channels.map { it.name } != take.channels.map { it.name }) {
            state.update { it.copy(recording = false, message = "This take has other channels than the first; start again on one source") }
            return
        }
        examples += label to take
        state.update { it.copy(recording = false, recorded = it.recorded + (label to (it.recorded[label] ?: 0) + 1), result = null) }
    }

    /** Forgets every example. */
    fun clearExamples() {
        examples.clear()
        state.update { it.copy(recorded = emptyMap(), result = null, message = null) }
    }

    /**
     * Trains off the main thread: first without the last take of each label to measure validation accuracy
     * on it, then on every take for the model that is stored.
     */
    fun train() {
        val taken = examples.toList()
        if (taken.isEmpty()) return
        state.update { it.copy(training = true, message = null) }
        viewModelScope.launch {
            val outcome = withContext(work) { runCatching { trainAndStore(taken) } }
            state.update {
                it.copy(training = false, result = outcome.getOrNull()?.first, model = outcome.getOrNull()?.second ?: it.model, message = outcome.exceptionOrNull()?.message)
            }
        }
    }

    private fun trainAndStore(taken: List<Pair<GestureLabel, Recording>>): Pair<TrainingResult, GestureModel> {
        val labelled = taken.map { (label, take) -> GestureSpans.label(take, label) }
        val lastOfLabel = taken.indices.groupBy { taken[it].first }.values.map { it.last() }.toSet()
        val validation: Double? = if (taken.groupBy { it.first }.values.all { it.size >= 2 }) {
            val held = labelled.filterIndexed { i, _ -> i in lastOfLabel }
            val kept = labelled.filterIndexed { i, _ -> i !in lastOfLabel }
            val model = trainer.train(kept)
            GestureSpans.accuracy(model, LabelledWindows.of(held, trainer.window))
        } else {
            null
        }
        val started = nanoTime()
        val model = trainer.train(labelled)
        val millis = (nanoTime() - started) / 1_000_000
        val windows = LabelledWindows.of(labelled, trainer.window)
        gestures.models.save(model)
        return TrainingResult(GestureSpans.accuracy(model, windows), validation, windows.size, model.labels, millis) to model
    }

    /** Imports a model file made by `hapticon train`; a bad file leaves the stored model and shows why. */
    fun importModel(open: () -> InputStream, source: String) {
        viewModelScope.launch {
            val outcome = withContext(work) {
                runCatching { gestures.models.import(open().use { readLimited(it, GestureModel.MAX_MODEL_CHARS, source) }.toString(Charsets.UTF_8)) }
            }
            state.update {
                outcome.fold(
                    { model -> it.copy(model = model, result = null, message = "Imported $source") },
                    { e -> it.copy(message = "$source: ${e.message ?: e.javaClass.simpleName}") },
                )
            }
        }
    }

    /** Hides the message. */
    fun dismissMessage() {
        state.update { it.copy(message = null) }
    }

    override fun onCleared() {
        recorder.stop()
    }

    companion object {
        /** Longest take. */
        const val MAX_TAKE_SECONDS: Double = 10.0

        /** Takes per label by default: enough for 0.98 accuracy on the synthetic people (docs/gesture-recognition.md). */
        const val DEFAULT_TAKES: Int = 5

        /** Most takes per gesture offered. */
        const val MAX_TAKES: Int = 20

        /** Rest and a gentle hug: "squeeze to send a hug". */
        val DEFAULT_LABELS: List<GestureLabel> = listOf(GestureLabel.NONE, GestureLabel.parse("hug-gentle"))
    }
}

