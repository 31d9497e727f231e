package org.hapticon.app.feature.chat

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.AdaptiveRenderer
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.RendererChoice
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.InvalidMessageException
import org.hapticon.messaging.Topics

/** The conversation list, or the first-run account screen while there is no user name. */
sealed interface ChatListUiState {
    data object Loading : ChatListUiState
    data class NeedsAccount(val brokerUrl: String) : ChatListUiState
    data class Success(val user: String, val conversations: List<ConversationSummary>, val preferences: ChatPreferences) : ChatListUiState
}

class ChatListViewModel(
    private val repository: ChatRepository,
    private val settings: ChatSettingsRepository,
) : ViewModel() {
    val uiState: StateFlow<ChatListUiState> = combine(settings.preferences, repository.conversations()) { prefs, conversations ->
        val user = prefs.userName
        if (user == null) ChatListUiState.NeedsAccount(prefs.brokerUrl) else ChatListUiState.Success(user, conversations, prefs)
    }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), ChatListUiState.Loading)

    /** Saves the account (a blank [password] means none); returns why not when the user name or URL is not valid. */
    fun saveAccount(userName: String, brokerUrl: String, password: String): String? {
        val name = userName.trim()
        if (!Topics.isValidUserName(name)) return "Use 1 to 32 letters, digits, '.', '_' or '-'"
        val url = brokerUrl.trim()
        if (runCatching { org.hapticon.messaging.mqtt.BrokerAddress.parse(url) }.isFailure) return "Not a broker URL (e.g. tcp://10.0.2.2:1883)"
        settings.update { it.copy(userName = name, brokerUrl = url, brokerPassword = password.takeIf { p -> p.isNotEmpty() }) }
        return null
    }

    /** Starts a conversation; returns why not when [peer] is not a valid user name. */
    fun startConversation(peer: String, onStarted: (String) -> Unit): String? {
        val name = peer.trim()
        if (!Topics.isValidUserName(name)) return "Not a valid user name"
        viewModelScope.launch {
            repository.startConversation(name)
            onStarted(name)
        }
        return null
    }

    fun setAutoPlay(enabled: Boolean) = settings.update { it.copy(autoPlay = enabled) }

    fun setRendererOverride(renderer: AdaptiveRenderer?) = settings.update { it.copy(rendererOverride = renderer?.name) }
}

/** What the peer's phone makes of the chosen icon ("how will this feel there"). */
data class PeerFeel(val renderer: AdaptiveRenderer, val fidelityPercent: Int?)

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
    ) : ConversationUiState
}

class ConversationViewModel(
    private val peer: String,
    private val user: () -> String?,
    private val repository: ChatRepository,
    icons: IconRepository,
    private val player: HapticPlayer,
    peerCapabilities: StateFlow<Map<String, Capabilities>>,
    /** Wakes the outbox sender after a message was stored. */
    private val onSent: () -> Unit,
) : ViewModel() {
    private data class Draft(val icon: HapticIcon? = null, val sticker: Sticker? = null, val error: String? = null)

    private val draft = MutableStateFlow(Draft())

    val uiState: StateFlow<ConversationUiState> = combine(
        repository.messages(peer), icons.icons(), draft, peerCapabilities,
    ) { messages, iconList, draft, capabilities ->
        val feel = capabilities[peer]?.let { caps ->
            val renderer = RendererChoice.fromWire(caps.renderer)
            PeerFeel(renderer, draft.icon?.let { RendererChoice.fidelityPercent(renderer, it) })
        }
        ConversationUiState.Success(peer, messages, iconList, draft.icon, draft.sticker, feel, draft.error)
    }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), ConversationUiState.Loading)

    fun selectIcon(icon: HapticIcon?) {
        draft.value = draft.value.copy(icon = icon, error = null)
    }

    fun selectSticker(sticker: Sticker?) {
        draft.value = draft.value.copy(sticker = sticker, error = null)
    }

    /** Feels [icon]: a press by the user, so not rate-limited. */
    fun play(icon: HapticIcon) {
        player.play(icon)
    }

    /** Stores the message with the selected sticker and icon (into the outbox), then clears the selection. */
    fun send(text: String, onStored: () -> Unit = {}) {
        val sender = user() ?: return
        val current = draft.value
        viewModelScope.launch {
            try {
                repository.send(sender, peer, text, current.sticker?.wireName, current.icon)
                draft.value = Draft()
                onSent()
                onStored()
            } catch (e: InvalidMessageException) {
                draft.value = current.copy(error = e.message)
            }
        }
    }
}
