package org.hapticon.app.feature.gesture

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.gesture.SocialTouchModelStore
import org.hapticon.app.gesture.readLimited
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.social.MessageFiles
import org.hapticon.gesture.social.ContactFrame
import org.hapticon.gesture.social.LogitBoost
import org.hapticon.gesture.social.SocialTouchFeatures
import org.hapticon.gesture.social.SocialTouchModel
import org.hapticon.messaging.InvalidMessageException
import java.io.InputStream

/** One classified touch message: [label] with [probability], from [touches] touches over [seconds], read from [source]. */
data class SocialTouchResult(val label: String, val probability: Double, val touches: Int, val seconds: Double, val source: String)

/** What the social-touch tab shows. */
sealed interface SocialTouchUiState {
    /** Reading the stored model. */
    data object Loading : SocialTouchUiState

    /** The model read (or none), the pad, the classified messages and what teaching collected. */
    data class Ready(
        /** The stored model's classes, empty without a model. */
        val modelLabels: List<String> = emptyList(),
        /** Whether a finger is on the pad. */
        val touching: Boolean = false,
        /** Touches so far in the message being collected. */
        val touches: Int = 0,
        /** Teaching: finished messages become examples of [teachLabel] instead of being classified. */
        val teaching: Boolean = false,
        val teachLabel: String = "",
        /** Examples collected per class, in the order the classes were first taught. */
        val examples: Map<String, Int> = emptyMap(),
        val training: Boolean = false,
        /** Newest first. */
        val results: List<SocialTouchResult> = emptyList(),
        val peers: List<String> = emptyList(),
        val peer: String? = null,
        val sendEnabled: Boolean = false,
        val message: String? = null,
    ) : SocialTouchUiState {
        /** The latest classified message. */
        val latest: SocialTouchResult? get() = results.firstOrNull()
    }
}

/**
 * Social-touch recognition (the EIT-skin paper: the 13 [SocialTouchFeatures] of a touch message, LogitBoost over
 * decision stumps) on the phone: the touch pad's contact frames are cut into messages ([SocialTouchMessages]) and
 * each is classified with the stored model, or, while teaching, kept as an example of a class to train a model
 * here ([LogitBoost.train] with WEKA's defaults, [LogitBoost.WEKA_DEFAULTS]). A message file ([MessageFiles]: a
 * `ContactCsv` pointer stream, or a skin's or pressure grid's `SkinCsv` recording) is classified as one message. With
 * sending on, a message whose class names a preset icon (stroke, hit, knock, hug) is sent to the chosen conversation
 * as that icon.
 * [clockSeconds] is the pad's time base (the events' uptime); [work] runs training and file reading.
 */
class SocialTouchViewModel(
    private val store: SocialTouchModelStore,
    private val repository: ChatRepository?,
    private val user: () -> String?,
    private val onSent: () -> Unit,
    private val clockSeconds: () -> Double,
    private val gapSeconds: Double = SocialTouchMessages.DEFAULT_GAP_SECONDS,
    private val work: CoroutineDispatcher = Dispatchers.Default,
) : ViewModel() {
    private val messages = SocialTouchMessages(gapSeconds)
    private val examples = ArrayList<Pair<String, DoubleArray>>()
    private val local = MutableStateFlow(SocialTouchUiState.Ready())
    private val model = MutableStateFlow<SocialTouchModel?>(null)
    private val loaded = MutableStateFlow(false)
    private var quietCheck: Job? = null

    private val peers: Flow<List<String>> = repository?.conversations()?.map { list -> list.map { it.peer } } ?: flowOf(emptyList())

    /** What the screen shows. */
    val uiState: StateFlow<SocialTouchUiState> = combine(local, model, peers, loaded) { state, m, names, isLoaded ->
        if (!isLoaded) {
            SocialTouchUiState.Loading
        } else {
            state.copy(modelLabels = m?.labels.orEmpty(), peers = names, peer = state.peer?.takeIf { it in names } ?: names.firstOrNull())
        }
    }.stateIn(viewModelScope, SharingStarted.Eagerly, SocialTouchUiState.Loading)

    init {
        viewModelScope.launch {
            val stored = withContext(work) { store.model.also { it.value } }
            stored.collect {
                model.value = it
                loaded.value = true
            }
        }
    }

    /** One frame from the pad (main thread). A lifted finger starts the wait for the message's end. */
    fun contact(frame: ContactFrame) {
        messages.offer(frame)
        local.update { it.copy(touching = messages.inContact, touches = messages.touchesSoFar) }
        quietCheck?.cancel()
        if (!messages.inContact && messages.touchesSoFar > 0) {
            quietCheck = viewModelScope.launch {
                delay((gapSeconds * 1000).toLong())
                messages.endIfQuiet(clockSeconds())?.let { onMessage(it, "touch pad") }
            }
        }
    }

    private fun onMessage(message: TouchMessage, source: String) {
        local.update { it.copy(touching = false, touches = 0) }
        val state = local.value
        if (state.teaching) {
            val label = state.teachLabel.trim()
            if (label.isEmpty()) return fail("Name the class you are teaching first")
            examples += label to message.features
            local.update { it.copy(examples = it.examples + (label to (it.examples[label] ?: 0) + 1), message = null) }
            return
        }
        val current = model.value ?: return fail("Teach or import a social-touch model first")
        val (label, probability) = current.classify(message.features)
        val result = SocialTouchResult(label, probability, message.touches, message.seconds, source)
        local.update { it.copy(results = listOf(result) + it.results.take(MAX_SHOWN - 1), message = null) }
        send(result)
    }

    private fun send(result: SocialTouchResult) {
        val state = uiState.value as? SocialTouchUiState.Ready ?: return
        val peer = state.peer
        val chats = repository
        if (!state.sendEnabled || peer == null || chats == null) return
        val icon = iconFor(result.label) ?: return fail("\"${result.label}\" names no preset icon, so it was not sent")
        val sender = user() ?: return fail("Set up your chat account first")
        viewModelScope.launch {
            try {
                chats.send(sender, peer, result.label, icon = icon)
                onSent()
                local.update { it.copy(message = "Sent ${icon.name} (${result.label}) to $peer") }
            } catch (e: InvalidMessageException) {
                fail(e.message ?: "The message was not valid")
            }
        }
    }

    /** Classifies a message file ([MessageFiles]) as one message; a bad file says why and changes nothing. */
    fun classifyFile(open: () -> InputStream, source: String) {
        viewModelScope.launch {
            val outcome = withContext(work) {
                runCatching {
                    // The whole file is one message, as the paper's trials were: no cutting at pauses.
                    val file = MessageFiles.read(open().use { readLimited(it, MAX_FILE_BYTES, source) }.toString(Charsets.UTF_8), source)
                    if (file.touches == 0) throw IllegalArgumentException("$source has no contact")
                    TouchMessage(file.features, file.touches, file.seconds)
                }
            }
            outcome.fold({ onMessage(it, source) }, { e -> fail(e.message ?: "Could not read $source") })
        }
    }

    /** Imports a model file made by `hapticon train --classifier logitboost`; a bad file keeps the stored model and says why. */
    fun importModel(open: () -> InputStream, source: String) {
        viewModelScope.launch {
            val outcome = withContext(work) {
                runCatching { store.import(open().use { readLimited(it, MAX_FILE_BYTES, source) }.toString(Charsets.UTF_8)) }
            }
            outcome.fold(
                { local.update { it.copy(message = "Imported $source") } },
                { e -> fail("$source: ${e.message ?: e.javaClass.simpleName}") },
            )
        }
    }

    /** Teaching on: finished messages become examples of the class named by [setTeachLabel]. */
    fun setTeaching(teaching: Boolean) {
        local.update { it.copy(teaching = teaching, message = null) }
    }

    /** Names the class the next taught messages are examples of. */
    fun setTeachLabel(label: String) {
        local.update { it.copy(teachLabel = label) }
    }

    /** Trains a model on the taught examples (at least two classes) off the main thread and stores it. */
    fun train() {
        val taken = examples.toList()
        val labels = taken.map { it.first }.distinct()
        if (labels.size < 2) return fail("Teach at least two classes first")
        local.update { it.copy(training = true, message = null) }
        viewModelScope.launch {
            val outcome = withContext(work) {
                runCatching {
                    val boost = LogitBoost.train(taken.map { it.second }, IntArray(taken.size) { labels.indexOf(taken[it].first) }, labels.size)
                    SocialTouchModel(labels, boost).also(store::save)
                }
            }
            local.update {
                it.copy(
                    training = false,
                    teaching = outcome.isFailure && it.teaching,
                    message = outcome.fold({ m -> "Trained on ${taken.size} messages of ${m.labels.size} classes" }, { e -> e.message }),
                )
            }
        }
    }

    /** Forgets the taught examples. */
    fun clearExamples() {
        examples.clear()
        local.update { it.copy(examples = emptyMap(), message = null) }
    }

    /** Chooses the conversation recognised messages go to. */
    fun selectPeer(peer: String) {
        local.update { it.copy(peer = peer) }
    }

    /** Turns sending recognised messages on or off. */
    fun setSendEnabled(enabled: Boolean) {
        local.update { it.copy(sendEnabled = enabled) }
    }

    /** Hides the message. */
    fun dismissMessage() {
        local.update { it.copy(message = null) }
    }

    private fun fail(message: String) {
        local.update { it.copy(message = message) }
    }

    companion object {
        /** Classified messages listed. */
        const val MAX_SHOWN: Int = 20

        /** Largest model or contact file read: 16 MiB. */
        const val MAX_FILE_BYTES: Int = 16 shl 20

        /** The preset icon a class names, as a whole word ("hug", "gentle-stroke"), or null. */
        fun iconFor(label: String): HapticIcon? =
            label.lowercase().split('-', '_', ' ').firstNotNullOfOrNull { HapticIcon.preset(it) }
    }
}
