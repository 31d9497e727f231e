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
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.app.gesture.RecordingImport
import org.hapticon.app.gesture.SavedRecording
import org.hapticon.app.gesture.SourceRecorder
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.playOffMain
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.gesture.Recording
import org.hapticon.gesture.extraction.FitOptions
import org.hapticon.gesture.extraction.IconFit
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.LevelReference
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.sensor.live.PlotSource

/** What the recorder shows: the source, the live or recorded take, the trim, the fitted icon and the saved recordings. */
sealed interface RecorderUiState {
    /** Reading the saved recordings. */
    data object Loading : RecorderUiState

    /** The recorder, its saved recordings read. */
    data class Ready(
        val sourceKind: GestureSourceKind = GestureSourceKind.TOUCH,
        /** False when this phone lacks the chosen source. */
        val sourceAvailable: Boolean = true,
        val recording: Boolean = false,
        /** Seconds recorded so far (live) or the recorded take's length. */
        val seconds: Double = 0.0,
        val maxSeconds: Double = RecorderViewModel.MAX_SECONDS,
        /** Channel names of the live source or of [take]. */
        val channels: List<String> = emptyList(),
        /** Changes when the live plot has new samples. */
        val plotRevision: Long = 0,
        /** The recorded (or imported, or opened) take being trimmed; null before one exists. */
        val take: Recording? = null,
        /** The trim, frames `[trimFrom, trimTo)` of [take]. */
        val trimFrom: Int = 0,
        val trimTo: Int = 0,
        /** The channel the icon is fitted to. */
        val fitChannel: String? = null,
        val fitting: Boolean = false,
        val fit: IconFit? = null,
        val iconName: String = "my gesture",
        /** The name of the icon last saved, to confirm it. */
        val savedIcon: String? = null,
        val savedRecordings: List<SavedRecording> = emptyList(),
        /** A problem or a confirmation for the user. */
        val message: String? = null,
        /** The saved recordings fitted together by [RecorderViewModel.fitSavedStrongest], levels against the strongest; null before. */
        val batch: List<BatchIcon>? = null,
        val batchFitting: Boolean = false,
    ) : RecorderUiState {
        /** The trimmed take, or null while there is none. */
        val trimmed: Recording? get() = take?.slice(trimFrom, trimTo)
    }
}

/** One saved recording ([recordingName]) of a batch fit and the icon fitted to it. */
data class BatchIcon(val recordingName: String, val fit: IconFit)

/**
 * The gesture recorder: records from the chosen [GestureSourceKind] with a live plot (at most
 * [MAX_SECONDS]), trims, fits an icon with the gesture module's [IconFitter] on [work] (off the main
 * thread), plays it, saves it as a custom icon through [icons] (so it appears in the picker and the Icons
 * tab), and saves, lists, opens and deletes recordings.
 */
class RecorderViewModel(
    private val gestures: GestureComponent,
    private val icons: RoomIconRepository?,
    private val player: HapticPlayer,
    private val work: CoroutineDispatcher = Dispatchers.Default,
) : ViewModel() {
    private val recorder = SourceRecorder(MAX_SECONDS)
    private val state = MutableStateFlow(RecorderUiState.Ready())
    private val loaded = MutableStateFlow(false)
    private var ticker: Job? = null

    /** What the screen shows. */
    val uiState: StateFlow<RecorderUiState> = combine(state, loaded) { ready, isLoaded -> if (isLoaded) ready else RecorderUiState.Loading }
        .stateIn(viewModelScope, SharingStarted.Eagerly, RecorderUiState.Loading)

    /** The live plot's samples. */
    val plot: PlotSource get() = recorder.history

    init {
        selectSource(GestureSourceKind.TOUCH)
        refreshRecordings()
    }

    /** Chooses the source to record from (not while recording). */
    fun selectSource(kind: GestureSourceKind) {
        if (recorder.recording) return
        val source = gestures.source(kind)
        state.update { it.copy(sourceKind = kind, sourceAvailable = source != null, message = if (source == null) "This phone has no ${kind.label.lowercase()}" else null) }
    }

    /** Starts recording from the chosen source with a live plot; stops by itself at [MAX_SECONDS]. */
    fun startRecording() {
        val source = gestures.source(state.value.sourceKind) ?: return
        try {
            recorder.start(source)
        } catch (e: IllegalStateException) {
            state.update { it.copy(message = e.message) }
            return
        }
        state.update {
            it.copy(recording = true, seconds = 0.0, channels = source.channels.map { c -> c.name }, take = null, fit = null, savedIcon = null, message = null)
        }
        ticker = viewModelScope.launch {
            while (isActive) {
                delay(PLOT_REFRESH_MILLIS)
                state.update { it.copy(seconds = recorder.seconds, plotRevision = it.plotRevision + 1) }
                if (recorder.full) {
                    stopRecording()
                    state.update { it.copy(message = "Stopped at the ${MAX_SECONDS.toInt()} s limit") }
                }
            }
        }
    }

    /** Stops recording and shows the take for trimming. */
    fun stopRecording() {
        if (!recorder.recording) return
        ticker?.cancel()
        ticker = null
        val take = recorder.stop()
        if (take == null) {
            state.update { it.copy(recording = false, message = "Nothing was recorded") }
        } else {
            showTake(take)
        }
    }

    private fun showTake(take: Recording, message: String? = null) {
        state.update {
            it.copy(
                recording = false, take = take, seconds = take.durationSeconds, channels = take.channels.map { c -> c.name },
                trimFrom = 0, trimTo = take.frameCount, fitChannel = take.channels.first().name, fit = null, savedIcon = null, message = message,
            )
        }
    }

    /** Keeps frames `[from, to)`; clamped to the take and to at least two frames. */
    fun setTrim(from: Int, to: Int) {
        val take = state.value.take ?: return
        val end = to.coerceIn(2, take.frameCount)
        val start = from.coerceIn(0, end - 2)
        state.update { it.copy(trimFrom = start, trimTo = end, fit = null) }
    }

    /** Chooses the channel the icon is fitted to. */
    fun selectFitChannel(name: String) {
        state.update { it.copy(fitChannel = name, fit = null) }
    }

    /** Sets the name the icon is played and saved under. */
    fun setIconName(name: String) {
        state.update { it.copy(iconName = name, savedIcon = null) }
    }

    /** Fits an icon to the trimmed take's chosen channel, off the main thread. */
    fun makeIcon() {
        val current = state.value
        val trimmed = current.trimmed ?: return
        val name = current.iconName.trim().ifEmpty { "gesture" }
        state.update { it.copy(fitting = true, fit = null, message = null) }
        viewModelScope.launch {
            // Level against the channel's full scale when its source states one, so a light gesture stays light;
            // otherwise against the gesture's own peak. The report names the reference either way.
            val fullScale = trimmed.channel(current.fitChannel ?: trimmed.channels.first().name)?.fullScale
            val reference = if (fullScale != null) LevelReference.FullScale else LevelReference.GesturePeak
            val result = withContext(work) { runCatching { IconFitter.fit(trimmed, current.fitChannel, FitOptions(levelReference = reference, name = name)) } }
            state.update {
                // IconFitter reports a bad input as IllegalArgumentException (NoGestureException included), with a message.
                it.copy(fitting = false, fit = result.getOrNull(), message = result.exceptionOrNull()?.let { e -> e.message ?: e.javaClass.simpleName })
            }
        }
    }

    /** The fitted icon under the chosen name, or null (and a message) when there is none or the name is not valid. */
    private fun namedIcon(): HapticIcon? {
        val current = state.value
        val fitted = current.fit?.icon ?: return null
        return try {
            fitted.copy(name = current.iconName.trim())
        } catch (e: IconValidationException) {
            state.update { it.copy(message = "Name: ${e.message}") }
            null
        }
    }

    /** Plays the fitted icon. */
    fun play() {
        namedIcon()?.let { viewModelScope.launch { player.playOffMain(it, VibrationUsage.TOUCH) } }
    }

    /** Saves the fitted icon as a custom icon (replacing one of the same name). */
    fun saveIcon() {
        val icon = namedIcon() ?: return
        val repository = icons ?: run {
            state.update { it.copy(message = "Icons cannot be saved in this build") }
            return
        }
        viewModelScope.launch {
            repository.save(icon)
            state.update { it.copy(savedIcon = icon.name, message = "Saved \"${icon.name}\" to your icons") }
        }
    }

    /** Saves the trimmed take as [name] with an optional gesture [label]. */
    fun saveRecording(name: String, label: GestureLabel?) {
        val trimmed = state.value.trimmed ?: return
        viewModelScope.launch {
            val result = withContext(work) { runCatching { gestures.recordings.save(name, label, trimmed) } }
            state.update { it.copy(message = result.fold({ saved -> "Saved recording ${saved.id}" }, { e -> e.message })) }
            refreshRecordings()
        }
    }

    /** Opens saved recording [id] for trimming. */
    fun openRecording(id: String) {
        viewModelScope.launch {
            withContext(work) { runCatching { gestures.recordings.load(id) } }
                .onSuccess { showTake(it) }
                .onFailure { e -> state.update { it.copy(message = e.message) } }
        }
    }

    /** Deletes saved recording [id]. */
    fun deleteRecording(id: String) {
        viewModelScope.launch {
            withContext(work) { gestures.recordings.delete(id) }
            refreshRecordings()
        }
    }

    /**
     * Fits every saved recording in [ids] (default: all) as one batch, as `hapticon fit --reference strongest` does
     * for a directory: each gesture's envelope peak is measured, and the strongest of the batch is the reference
     * every level is relative to ([IconFitter.fitBatch]), so a gesture half as strong as the strongest fits about
     * half its level. Each icon is named after its recording. The chosen fit channel is used where every recording
     * has it, else each recording's first channel.
     */
    fun fitSavedStrongest(ids: List<String> = state.value.savedRecordings.map { it.id }) {
        val saved = state.value.savedRecordings.filter { it.id in ids }
        if (saved.isEmpty()) {
            state.update { it.copy(message = "No saved recordings to fit") }
            return
        }
        val channel = state.value.fitChannel
        state.update { it.copy(batchFitting = true, batch = null, message = null) }
        viewModelScope.launch {
            val result = withContext(work) {
                runCatching {
                    val recordings = saved.map { gestures.recordings.load(it.id) }
                    val common = channel?.takeIf { c -> recordings.all { it.channel(c) != null } }
                    IconFitter.fitBatch(recordings, common).mapIndexed { i, fit -> BatchIcon(saved[i].name, fit.named(saved[i].name)) }
                }
            }
            state.update {
                it.copy(batchFitting = false, batch = result.getOrNull(), message = result.exceptionOrNull()?.let { e -> e.message ?: e.javaClass.simpleName })
            }
        }
    }

    /** Saves every icon of the last batch fit as a custom icon (replacing ones of the same names). */
    fun saveBatchIcons() {
        val batch = state.value.batch ?: return
        val repository = icons ?: run {
            state.update { it.copy(message = "Icons cannot be saved in this build") }
            return
        }
        viewModelScope.launch {
            for (item in batch) repository.save(item.fit.icon)
            state.update { it.copy(message = "Saved ${batch.size} icons to your icons") }
        }
    }

    /** This fit with its icon renamed to [name] when that is a valid icon name, else unchanged. */
    private fun IconFit.named(name: String): IconFit =
        try {
            IconFit(icon.copy(name = name.trim()), report)
        } catch (e: IconValidationException) {
            this
        }

    /** Reads a picked WAV or CSV file (named [source] in errors) as the take to trim. */
    fun importFile(open: () -> InputStream, source: String) {
        viewModelScope.launch {
            withContext(work) { runCatching { open().use { RecordingImport.read(it, source) } } }
                .onSuccess { showTake(it, "Imported $source") }
                .onFailure { e -> state.update { it.copy(message = e.message ?: "Could not read $source") } }
        }
    }

    /** Hides the message. */
    fun dismissMessage() {
        state.update { it.copy(message = null) }
    }

    private fun refreshRecordings() {
        viewModelScope.launch {
            val list = withContext(work) { gestures.recordings.list() }
            state.update { it.copy(savedRecordings = list) }
            loaded.value = true
        }
    }

    override fun onCleared() {
        recorder.stop()
    }

    companion object {
        /** The longest recording: a minute of touch at 200 Hz is 12 000 frames per channel. */
        const val MAX_SECONDS: Double = 60.0

        /** How often the live plot and the length redraw. */
        const val PLOT_REFRESH_MILLIS: Long = 100
    }
}
