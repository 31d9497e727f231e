package org.hapticon.app.feature.chat

import org.hapticon.app.ui.Sticker
import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.conflate
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.flowOn
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.onStart
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.playMessageOffMain
import org.hapticon.app.playback.playOffMain
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.messageUsage
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.app.playback.RendererChoice
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.InvalidMessageException
import org.hapticon.core.render.RendererKind

sealed interface ConversationUiState {
    data object Loading : ConversationUiState
    data class Success(
        val peer: String,
        val messages: List<StoredMessage>,
        val icons: List<HapticIcon>,
        val selectedIcon: HapticIcon?,
        val selectedSticker: Sticker?,
        /** Null until the peer's capabilities are known. */
        val peerFeel: PeerFeel?,
        val error: String?,
        /** The user's imported patterns, offered after the icons; a message carries an icon or a pattern. */
        val patterns: List<HapticPattern> = emptyList(),
        val selectedPattern: HapticPattern? = null,
        /** Whether messages can move now; the screen says so in a line under its top bar when they cannot. */
        val connection: ChatConnection = ChatConnection.Online,
        /** True once the broker's directory is loaded and [peer] is not in it: they never connected to this broker. */
        val peerNeverConnected: Boolean = false,
    ) : ConversationUiState
}

class ConversationViewModel(
    private val peer: String,
    private val user: () -> String?,
    private val repository: ChatRepository,
    icons: IconRepository,
    private val player: HapticPlayer,
    peerCapabilities: StateFlow<Map<String, Capabilities>>,
    /** Wakes the outbox sender after a message was stored or a retry asked for. */
    private val onSent: () -> Unit,
    /** Tells the sync that Android played a received message's icon at the user's press (the felt receipt). */
    private val onFelt: (peer: String, messageId: String) -> Unit = { _, _ -> },
    /** The user's patterns ([org.hapticon.app.data.RoomPatternRepository]); none where the app has no pattern store. */
    patterns: Flow<List<HapticPattern>> = flowOf(emptyList()),
    /** Whether messages can move now ([ChatConnection.flow]). */
    connection: Flow<ChatConnection> = flowOf(ChatConnection.Online),
    /** The users who ever connected to the broker, null until known ([org.hapticon.app.sync.ChatSync.knownUsers]). */
    knownUsers: Flow<Set<String>?> = flowOf(null),
) : ViewModel() {
    /** The message being composed: at most one of [icon] and [pattern], as [org.hapticon.messaging.ChatMessage] requires. */
    private data class Draft(
        val icon: HapticIcon? = null,
        val pattern: HapticPattern? = null,
        val sticker: Sticker? = null,
        val error: String? = null,
    )

    private val draft = MutableStateFlow(Draft())

    /** Which figure a computed fidelity belongs to: the peer's renderer and the chosen icon. */
    private data class FigureKey(val renderer: RendererKind, val icon: HapticIcon)

    /**
     * The chosen icon's fidelity on the peer's renderer ("how it will feel there"). Computing it renders the icon
     * (its whole PCM signal for an audio-coupled peer), so it runs in the player's render context, as playback does
     * ([playOffMain]), never on the main thread; a choice made while a figure is computed replaces the pending one.
     */
    private val figure: Flow<Pair<FigureKey, Int?>?> = combine(draft, peerCapabilities) { draft, capabilities ->
        val renderer = capabilities[peer]?.renderer
        val icon = draft.icon
        if (renderer == null || icon == null || draft.pattern != null) null else FigureKey(renderer, icon)
    }.distinctUntilChanged()
        .conflate()
        .map { key -> key?.let { it to RendererChoice.fidelityPercent(it.renderer, it.icon) } }
        .flowOn(player.renderContext)
        .onStart { emit(null) }

    /** The draft with what the peer will feel of it; the figure only once computed for this very choice. */
    private val composer: Flow<Pair<Draft, PeerFeel?>> = combine(draft, peerCapabilities, figure) { draft, capabilities, figure ->
        val feel = capabilities[peer]?.let { caps ->
            when {
                draft.pattern != null -> PeerFeel.ofPattern(caps, draft.pattern)
                draft.icon != null -> {
                    val percent = figure?.takeIf { it.first == FigureKey(caps.renderer, draft.icon) }?.second
                    PeerFeel.ofIcon(caps, draft.icon, percent)
                }
                else -> PeerFeel(caps.renderer, null)
            }
        }
        draft to feel
    }

    private val reach: Flow<Pair<ChatConnection, Boolean>> =
        combine(connection, knownUsers) { line, known -> line to (known != null && peer !in known) }

    val uiState: StateFlow<ConversationUiState> = combine(
        repository.messages(peer), icons.icons(), patterns, composer, reach,
    ) { messages, iconList, patternList, (draft, feel), (line, neverConnected) ->
        ConversationUiState.Success(
            peer, messages, iconList, draft.icon, draft.sticker, feel, draft.error, patternList, draft.pattern, line, neverConnected,
        )
    }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), ConversationUiState.Loading)

    /** Chooses [icon] (null: none); it replaces a chosen pattern, as a message carries one or the other. */
    fun selectIcon(icon: HapticIcon?) {
        val current = draft.value
        draft.value = current.copy(icon = icon, pattern = if (icon != null) null else current.pattern, error = null)
    }

    /** Chooses [pattern] (null: none); it replaces a chosen icon. */
    fun selectPattern(pattern: HapticPattern?) {
        val current = draft.value
        draft.value = current.copy(pattern = pattern, icon = if (pattern != null) null else current.icon, error = null)
    }

    fun selectSticker(sticker: Sticker?) {
        draft.value = draft.value.copy(sticker = sticker, error = null)
    }

    /** Feels [icon] on this phone (a long press in the composer): a press by the user (a touch), so not rate-limited. */
    fun play(icon: HapticIcon) {
        viewModelScope.launch { player.playOffMain(icon, VibrationUsage.TOUCH) }
    }

    /** Feels [pattern] on this phone (a long press in the composer), planned for this phone as a received one is. */
    fun play(pattern: HapticPattern) {
        viewModelScope.launch { player.playOffMain(pattern, VibrationUsage.TOUCH) }
    }

    /**
     * Feels a message's icon or pattern. A received one plays as what it is, the peer's communication
     * ([messageUsage]); its sender learns it was felt only once Android played it ([Playback.Playing]).
     */
    fun feel(message: StoredMessage) {
        if (message.icon == null && message.pattern == null) return
        viewModelScope.launch {
            val playback = player.playMessageOffMain(message.icon, message.pattern, messageUsage(message.outgoing))
            if (!message.outgoing && playback is Playback.Playing) onFelt(peer, message.id)
        }
    }

    /** Sends a failed or waiting own message now: the same row and id, shown as sending again until the broker has it. */
    fun retry(message: StoredMessage) {
        if (!message.outgoing) return
        viewModelScope.launch {
            repository.retryNow(message.id)
            onSent()
        }
    }

    /**
     * Stores the message with the selected sticker and icon or pattern (into the outbox), then clears the selection and
     * calls [onStored]. A message that cannot be stored keeps the draft and says why in [ConversationUiState.Success.error];
     * [onStored] is not called, so the composer keeps the text.
     */
    fun send(text: String, onStored: () -> Unit = {}) {
        val sender = user() ?: run {
            draft.value = draft.value.copy(error = "Set up your account first: Chats, then Settings")
            return
        }
        val current = draft.value
        viewModelScope.launch {
            try {
                repository.send(sender, peer, text, current.sticker?.wireName, current.icon, current.pattern)
                draft.value = Draft()
                onSent()
                onStored()
            } catch (e: InvalidMessageException) {
                draft.value = current.copy(error = e.message)
            }
        }
    }
}
