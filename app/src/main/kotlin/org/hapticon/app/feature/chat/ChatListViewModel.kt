package org.hapticon.app.feature.chat

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.sync.BrokerProbe
import org.hapticon.messaging.Topics
import org.hapticon.messaging.BrokerAddress

/** The conversation list, or the first-launch screen while there is no account. */
sealed interface ChatListUiState {
    data object Loading : ChatListUiState

    /** First launch: [brokerUrl] is what an opened invite filled in (empty otherwise). */
    data class NeedsAccount(val brokerUrl: String) : ChatListUiState

    /** First launch, right after the account was saved: "Stay reachable" and autoplay are offered once ([ReachableOfferScreen]). */
    data class OfferReachable(val user: String) : ChatListUiState

    data class Success(
        val user: String,
        val conversations: List<ConversationSummary>,
        val archived: Set<String> = emptySet(),
        /**
         * What the chat list says about reaching this user with the app closed ([reachableNote]); null when
         * nothing needs saying (Stay reachable on and Android lets it run).
         */
        val reachableNote: ReachableNote? = null,
        /** Whether messages can move now; the list says so in a line under its top bar when they cannot. */
        val connection: ChatConnection = ChatConnection.Online,
    ) : ChatListUiState
}

/** Why "New chat" did not open a conversation, in one line for the dialog. */
sealed interface NewChatProblem {
    val message: String

    /** Not a possible user name. */
    data class InvalidName(override val message: String) : NewChatProblem

    /** The broker's directory is loaded and [peer] is not in it: a typo, or someone who has not set up the app yet. */
    data class NeverConnected(val peer: String) : NewChatProblem {
        override val message: String
            get() = "No one called $peer has connected to this broker yet. Check the spelling, or show them your invite code."
    }
}

class ChatListViewModel(
    private val repository: ChatRepository,
    private val settings: ChatSettingsRepository,
    private val probe: BrokerProbe,
    /**
     * Whether Android exempts this app from battery optimisation (PowerManager.isIgnoringBatteryOptimizations),
     * asked again on every resume ([refreshBatteryExemption]): the user can change it in Android's settings.
     */
    private val batteryExempt: () -> Boolean = { true },
    /** Whether messages can move now ([ChatConnection.flow]). */
    connection: Flow<ChatConnection> = flowOf(ChatConnection.Online),
    /** The users who ever connected to the broker, null until known ([org.hapticon.app.sync.ChatSync.knownUsers]). */
    private val knownUsers: StateFlow<Set<String>?> = MutableStateFlow(null),
) : ViewModel() {
    private val exempt = MutableStateFlow(batteryExempt())

    val uiState: StateFlow<ChatListUiState> = combine(settings.preferences, repository.conversations(), exempt, connection) { prefs, conversations, exempt, line ->
        val user = prefs.userName
        when {
            user == null -> ChatListUiState.NeedsAccount(prefs.brokerUrl)
            prefs.reachableOfferPending -> ChatListUiState.OfferReachable(user)
            else -> ChatListUiState.Success(user, conversations, prefs.archived, reachableNote(prefs.stayReachable, exempt), line)
        }
    }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), ChatListUiState.Loading)

    /** Asks Android again whether the app is exempt from battery optimisation (the screen came back). */
    fun refreshBatteryExemption() {
        exempt.value = batteryExempt()
    }

    /**
     * The first-launch offer's answer: "Stay reachable" (with restarts: a participant who said yes expects it
     * after a reboot too) and autoplay as chosen; the offer is not shown again. Both stay in Settings.
     */
    fun answerReachableOffer(stayReachable: Boolean, autoPlay: Boolean) = settings.update {
        it.copy(stayReachable = stayReachable, reachableAfterBoot = stayReachable, autoPlay = autoPlay, reachableOfferPending = false)
    }

    /** The first-launch form's progress: null idle, else testing or the last failure. */
    val accountCheck = MutableStateFlow<AccountCheck>(AccountCheck.Idle)

    /**
     * Tests the broker with [userName] and saves both only when it answered (first launch). A bad name
     * or address is reported at once, without a network call.
     */
    fun saveAccount(userName: String, brokerUrl: String, password: String = "") {
        val name = userName.trim()
        if (!Topics.isValidUserName(name)) {
            accountCheck.value = AccountCheck.Failed("User name: use 1 to 32 letters, digits, '.', '_' or '-'")
            return
        }
        val address = try {
            BrokerAddress.parse(brokerUrl)
        } catch (e: IllegalArgumentException) {
            accountCheck.value = AccountCheck.Failed("Broker address: ${e.message}")
            return
        }
        accountCheck.value = AccountCheck.Testing(address.toString())
        viewModelScope.launch {
            val secret = password.takeIf { it.isNotEmpty() }
            val problem = probe(name, address, secret)
            if (problem != null) {
                accountCheck.value = AccountCheck.Failed(problem)
            } else {
                // In the same main-thread turn as the probe's own save: the list never shows between form and offer.
                settings.update { it.copy(userName = name, brokerUrl = address.toString(), brokerPassword = secret, reachableOfferPending = true) }
                accountCheck.value = AccountCheck.Saved
            }
        }
    }

    /** The chat list's note asked for "Stay reachable": on, with restarts, as the first-launch offer sets it. */
    fun turnOnStayReachable() = settings.update { it.copy(stayReachable = true, reachableAfterBoot = true) }

    /**
     * Starts a conversation with [peer] and calls [onStarted]; returns why not instead when the name is not valid, or
     * when the broker's directory says [peer] never connected and the user did not ask to start [evenIfUnknown]. While
     * the directory is not known (offline, still connecting) the conversation starts: its screen says so once known.
     */
    fun startConversation(peer: String, evenIfUnknown: Boolean = false, onStarted: (String) -> Unit): NewChatProblem? {
        val name = peer.trim()
        if (!Topics.isValidUserName(name)) return NewChatProblem.InvalidName("Use 1 to 32 letters, digits, '.', '_' or '-'")
        val known = knownUsers.value
        if (!evenIfUnknown && known != null && name !in known) return NewChatProblem.NeverConnected(name)
        viewModelScope.launch {
            repository.startConversation(name)
            onStarted(name)
        }
        return null
    }

    fun archive(peer: String) = settings.update { it.copy(archived = it.archived + peer) }

    fun unarchive(peer: String) = settings.update { it.copy(archived = it.archived - peer) }

    /**
     * Deletes [peer]'s conversation. Called as the chat list is left (a pending undo expires), possibly
     * while this ViewModel is being cleared: ATOMIC start and NonCancellable let the deletion run even in
     * a cancelled scope, so a chat the user saw deleted never comes back.
     */
    fun delete(peer: String) {
        viewModelScope.launch(start = kotlinx.coroutines.CoroutineStart.ATOMIC) {
            kotlinx.coroutines.withContext(kotlinx.coroutines.NonCancellable) { repository.deleteConversation(peer) }
        }
        settings.update { it.copy(archived = it.archived - peer) }
    }
}

/** The first-launch connection test. */
sealed interface AccountCheck {
    data object Idle : AccountCheck
    data class Testing(val broker: String) : AccountCheck
    data class Failed(val reason: String) : AccountCheck

    /** The account was just saved; the offer of "Stay reachable" follows. */
    data object Saved : AccountCheck
}
