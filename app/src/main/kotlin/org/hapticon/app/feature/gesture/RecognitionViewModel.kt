package org.hapticon.app.feature.gesture

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.gesture.GestureSink
import org.hapticon.app.gesture.GestureSource
import org.hapticon.app.gesture.GestureSourceKind
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.recognition.Gesture
import org.hapticon.gesture.recognition.GestureEvent
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.recognition.LiveRecognizer
import org.hapticon.messaging.InvalidMessageException
import kotlin.math.abs

/** One recognised gesture that was sent: to [peer], the preset [icon], at [atSeconds] into the run. */
data class SentGesture(val label: GestureLabel, val icon: String, val peer: String, val atSeconds: Double)

/** Live recognition: the model, the source, the latest decision and what was sent to whom. */
sealed interface RecognitionUiState {
    /** Reading the stored model. */
    data object Loading : RecognitionUiState

    /** Recognition, the stored model read. */
    data class Ready(
        val model: GestureModel? = null,
        val sourceKind: GestureSourceKind = GestureSourceKind.SENSOR_BOARD,
        val running: Boolean = false,
        /** The latest decision (every hop) and its vote share. */
        val decision: GestureLabel? = null,
        val probability: Double = 0.0,
        /** The latest stable gesture event. */
        val lastEvent: GestureLabel? = null,
        /** Conversations to send to. */
        val peers: List<String> = emptyList(),
        val peer: String? = null,
        val sendEnabled: Boolean = false,
        /** Newest first. */
        val sent: List<SentGesture> = emptyList(),
        val message: String? = null,
    ) : RecognitionUiState
}

/**
 * Runs a [LiveRecognizer] on the chosen source's thread and, with "send" on, sends each recognised
 * gesture to the chosen conversation as its preset icon ([presetFor]) through [repository] (then
 * [onSent] wakes the sync), at most one per [minSendIntervalSeconds] of stream time — the recogniser's
 * frame clock, so the limit holds whatever the UI thread does. [user] is the account name.
 */
class RecognitionViewModel(
    private val gestures: GestureComponent,
    private val repository: ChatRepository?,
    private val user: () -> String?,
    private val onSent: () -> Unit,
    private val minSendIntervalSeconds: Double = MIN_SEND_INTERVAL_SECONDS,
    private val work: CoroutineDispatcher = Dispatchers.Default,
) : ViewModel() {
    private val state = MutableStateFlow(RecognitionUiState.Ready())
    private val loaded = MutableStateFlow(false)
    private var source: GestureSource? = null

    // Written on the source's thread only.
    private var lastSentFrame = Long.MIN_VALUE

    /** What the screen shows. */
    val uiState: StateFlow<RecognitionUiState> = combine(state, loaded) { ready, isLoaded -> if (isLoaded) ready else RecognitionUiState.Loading }
        .stateIn(viewModelScope, SharingStarted.Eagerly, RecognitionUiState.Loading)

    init {
        viewModelScope.launch {
            val models = withContext(work) { gestures.models.model.also { it.value } }
            models.collect { model ->
                state.update { it.copy(model = model) }
                loaded.value = true
            }
        }
        repository?.let { chats ->
            viewModelScope.launch {
                chats.conversations().collect { list ->
                    val peers = list.map { it.peer }
                    state.update { it.copy(peers = peers, peer = it.peer?.takeIf { p -> p in peers } ?: peers.firstOrNull()) }
                }
            }
        }
    }

    /** Chooses the source to recognise from (not while running). */
    fun selectSource(kind: GestureSourceKind) {
        if (state.value.running) return
        state.update { it.copy(sourceKind = kind, message = null) }
    }

    /** Chooses the conversation recognised gestures go to. */
    fun selectPeer(peer: String) {
        state.update { it.copy(peer = peer) }
    }

    /** Turns sending recognised gestures on or off. */
    fun setSendEnabled(enabled: Boolean) {
        state.update { it.copy(sendEnabled = enabled) }
    }

    /** Starts recognising from the chosen source with the stored model; says why not when the two do not match. */
    fun start() {
        if (state.value.running) return
        val model = state.value.model ?: return fail("Teach or import a model first")
        val chosen = gestures.source(state.value.sourceKind) ?: return fail("This phone has no ${state.value.sourceKind.label.lowercase()}")
        val names = chosen.channels.map { it.name }
        // The model reads its channels by name, in its own order; a source may offer more.
        val columns = model.channels.map { names.indexOf(it) }
        if (columns.any { it < 0 }) return fail("The model needs channels ${model.channels.joinToString()}; ${chosen.label} gives ${names.joinToString().ifEmpty { "none" }}")
        if (abs(chosen.sampleRate - model.sampleRate) > model.sampleRate * 1e-3) {
            return fail("The model was trained at ${model.sampleRate} Hz; ${chosen.label} runs at ${chosen.sampleRate} Hz")
        }
        val recognizer = LiveRecognizer(model)
        val frame = DoubleArray(columns.size)
        var decisions = 0L
        lastSentFrame = Long.MIN_VALUE
        val sink = GestureSink { values ->
            for (i in columns.indices) frame[i] = values[columns[i]]
            val event = recognizer.push(frame)
            if (recognizer.decisionCount != decisions) {
                decisions = recognizer.decisionCount
                state.update { it.copy(decision = recognizer.lastDecision, probability = recognizer.lastProbability) }
            }
            if (event != null) onEvent(event, model.sampleRate)
        }
        try {
            chosen.start(sink)
        } catch (e: IllegalStateException) {
            return fail(e.message ?: "${chosen.label} could not start")
        }
        source = chosen
        state.update { it.copy(running = true, decision = null, probability = 0.0, lastEvent = null, message = null) }
    }

    /** Stops the source; the last decision stays shown. */
    fun stop() {
        source?.stop()
        source = null
        state.update { it.copy(running = false) }
    }

    /** On the source's thread: shows the event and sends it when sending is on and the rate limit allows. */
    private fun onEvent(event: GestureEvent, sampleRate: Double) {
        val current = state.value
        state.update { it.copy(lastEvent = event.label) }
        val gesture = event.label.gesture ?: return
        val peer = current.peer
        val chats = repository
        if (!current.sendEnabled || peer == null || chats == null) return
        val minFrames = (minSendIntervalSeconds * sampleRate).toLong()
        if (lastSentFrame != Long.MIN_VALUE && event.decisionFrame - lastSentFrame < minFrames) return
        val sender = user() ?: return fail("Set up your chat account first")
        lastSentFrame = event.decisionFrame
        val icon = presetFor(gesture)
        val sent = SentGesture(event.label, icon.name, peer, event.decisionFrame / sampleRate)
        viewModelScope.launch {
            try {
                chats.send(sender, peer, event.label.id.replace('-', ' '), icon = icon)
                onSent()
                state.update { it.copy(sent = listOf(sent) + it.sent.take(MAX_SHOWN - 1)) }
            } catch (e: InvalidMessageException) {
                fail(e.message ?: "The message was not valid")
            }
        }
    }

    private fun fail(message: String) {
        state.update { it.copy(message = message) }
    }

    /** Hides the message. */
    fun dismissMessage() {
        state.update { it.copy(message = null) }
    }

    override fun onCleared() {
        source?.stop()
    }

    companion object {
        /** At most one sent gesture per 2 s: a long squeeze or a fidgety hand must not flood the chat. */
        const val MIN_SEND_INTERVAL_SECONDS: Double = 2.0

        /** Sent gestures listed. */
        const val MAX_SHOWN: Int = 20

        /**
         * The preset icon sent for [gesture]. Intensity picks nothing: gentle and energetic send the same
         * preset (the text says which), because the presets come from the originating study and scaling their
         * level would change what the receiver learned to recognise.
         */
        fun presetFor(gesture: Gesture): HapticIcon = when (gesture) {
            Gesture.STROKE -> HapticIcon.STROKE
            Gesture.HIT -> HapticIcon.HIT
            Gesture.KNOCK -> HapticIcon.KNOCK
            Gesture.HUG -> HapticIcon.HUG
        }
    }
}
