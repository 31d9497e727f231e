package org.hapticon.app.feature.chat

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.conflate
import kotlinx.coroutines.flow.distinctUntilChanged
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.flowOn
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.onStart
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.IconRepository
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.PeerPitch
import org.hapticon.app.playback.Playback
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.messageUsage
import org.hapticon.app.playback.playMessageOffMain
import org.hapticon.app.playback.playOffMain
import org.hapticon.app.sync.BrokerProbe
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.InvalidMessageException
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.Topics

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

/**
 * What opening an invite link did: the contact added and the broker filled in, or the one-line reason
 * nothing changed. A link never replaces a broker already in use: switching brokers would cut the user
 * off from everyone on the old one, so that stays a deliberate change in Settings.
 */
sealed interface InviteOutcome {
    data class Added(val peer: String?, val brokerFilled: Boolean, val note: String?) : InviteOutcome
    data class Rejected(val reason: String) : InviteOutcome
}

/** Applies an opened invite link: validates it fully before changing anything. */
suspend fun applyInvite(text: String, repository: ChatRepository, settings: ChatSettingsRepository): InviteOutcome {
    val link = InviteLink.parse(text).getOrElse { return InviteOutcome.Rejected(it.message ?: "Not a Hapticon invite") }
    val prefs = settings.preferences.value
    if (link.user != null && link.user == prefs.userName) return InviteOutcome.Rejected("This is your own invite")
    val current = prefs.brokerUrl.takeIf { it.isNotEmpty() }?.let { runCatching { BrokerAddress.parse(it) }.getOrNull() }
    val fill = current == null
    if (fill) settings.update { it.copy(brokerUrl = link.broker.toString()) }
    link.user?.let { repository.startConversation(it) }
    val note = if (!fill && current != link.broker) "${link.user ?: "The invite"} uses ${link.broker}; you stay on $current (change it in Settings)" else null
    return InviteOutcome.Added(link.user, fill, note)
}

/**
 * What the peer's phone makes of the chosen icon or pattern ("how will this feel there"); [fidelityPercent] is
 * null for a pattern, where nothing plays, and while the chosen icon's figure is still being computed off the
 * main thread (`ConversationViewModel`). [alternative] is
 * set when the peer's capabilities leave two renderers possible (a pattern on an audio-coupled API 36 phone:
 * envelope if its vibrator offers envelope effects, else amplitude steps), shown as "X or Y".
 */
data class PeerFeel(
    val renderer: RendererKind,
    val fidelityPercent: Int?,
    val alternative: RendererKind? = null,
    /** The pitch the peer's phone will play, one line ([org.hapticon.app.playback.PeerPitch]); null when it plays none. */
    val pitch: String? = null,
    /**
     * The control points the peer's envelope effect will get, resampled within the limits it publishes (or the guaranteed
     * ones, said so), one line ([PeerPitch.describeEnvelope]); null when it plays no envelope effect.
     */
    val envelope: String? = null,
) {
    companion object {
        /**
         * How [caps]'s phone plays [icon]: its renderer, that renderer's fidelity and the pitch it will give the note.
         * The fidelity renders the icon, so the composer passes the figure it computed off the main thread (null until then).
         */
        fun ofIcon(
            caps: Capabilities,
            icon: HapticIcon,
            fidelityPercent: Int? = RendererChoice.fidelityPercent(caps.renderer, icon),
        ): PeerFeel {
            val pattern = icon.toPattern()
            val audioCoupled = caps.renderer == RendererKind.AUDIO_COUPLED
            // Planned once for both lines (it resamples the envelope); audio carries the icon whole and needs no plan.
            val plan = if (audioCoupled) null else PeerPitch.planOf(caps, pattern)
            return PeerFeel(
                caps.renderer, fidelityPercent,
                pitch = PeerPitch.describe(caps, pattern, audioCoupled = audioCoupled, icon = true, knownPlan = plan),
                // The peer's envelope renderer resamples the icon's pattern as it does a pattern; audio carries it whole.
                envelope = plan?.let { PeerPitch.describeEnvelope(caps, pattern, icon = true, knownPlan = it) },
            )
        }

        /**
         * How [caps]'s phone plays a pattern, following [org.hapticon.app.playback.PatternPlan.of]: audio-coupled where
         * the peer plays icons so (builds that publish `envelopeEffects`); an envelope effect needs API 36; otherwise
         * amplitude steps, or on/off without amplitude control. An older audio-coupled API 36 peer does not say
         * whether its vibrator has envelope effects, so it is "envelope or amplitude waveform".
         */
        fun ofPattern(caps: Capabilities, pattern: HapticPattern? = null): PeerFeel {
            val steps = if (caps.amplitudeControl) RendererKind.AMPLITUDE_WAVEFORM else RendererKind.ON_OFF
            // Planned once for every line below (planning resamples the envelope).
            val plan = pattern?.let { PeerPitch.planOf(caps, it) }
            val pitch = pattern?.let { PeerPitch.describe(caps, it, knownPlan = plan) }
            val envelope = pattern?.let { PeerPitch.describeEnvelope(caps, it, knownPlan = plan) }
            // A peer that publishes envelopeEffects (this build) is planned exactly: an envelope phone plays a pattern
            // its envelope cannot follow (a sharp pulse, or beyond its limits) as steps, and the line must say so.
            if (plan != null && caps.envelopeEffects != null && caps.renderer != RendererKind.AUDIO_COUPLED) {
                return PeerFeel(plan.renderer, null, pitch = pitch, envelope = envelope)
            }
            return when (caps.renderer) {
                RendererKind.AUDIO_COUPLED -> when {
                    // Builds that publish envelopeEffects play patterns as audio too; older ones plan them without audio,
                    // and do not say whether their vibrator has envelope effects.
                    caps.envelopeEffects != null -> PeerFeel(RendererKind.AUDIO_COUPLED, null, pitch = pitch)
                    (caps.apiLevel ?: 0) >= 36 -> PeerFeel(RendererKind.ENVELOPE, null, steps, pitch = pitch)
                    else -> PeerFeel(steps, null, pitch = pitch)
                }
                RendererKind.AMPLITUDE_WAVEFORM -> PeerFeel(steps, null, pitch = pitch)
                // Envelope, on/off, no actuator, the CLI's audio and unknown stay what the peer said.
                else -> PeerFeel(caps.renderer, null, pitch = pitch, envelope = envelope)
            }
        }
    }
}

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

/** The settings screen's values, read from the chat settings. */
data class SettingsUiState(
    val preferences: ChatPreferences,
    val renderers: List<RendererKind>,
    val connection: String,
    /** False when Android will not show this app's notifications (permission refused, or turned off). */
    val notificationsAllowed: Boolean = true,
    /** End-to-end warnings (a peer's changed key, forged payloads), newest last ([org.hapticon.app.sync.ChatSync.securityWarnings]). */
    val securityWarnings: List<String> = emptyList(),
    /** Peers whose changed key waits for the user's trust. */
    val changedKeys: Set<String> = emptySet(),
    /** The outcome of the last action that takes a moment (broker test, export, permission), one line. */
    val notice: String? = null,
    /** The client certificate for mutual TLS, if one is stored. */
    val clientCertificate: org.hapticon.app.data.ClientCertificateStatus = org.hapticon.app.data.ClientCertificateStatus.None,
    /** A picked certificate file waiting for its password, null when none is. */
    val certificateImport: CertificateImport? = null,
)

/** A picked client certificate file ([fileName]) waiting for its password; [error] says why the last one did not open it. */
data class CertificateImport(val fileName: String, val error: String? = null)
