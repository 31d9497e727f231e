package org.hapticon.app.feature.chat

import android.Manifest
import android.content.Intent
import android.content.pm.PackageManager
import android.os.Build
import androidx.activity.compose.BackHandler
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.material3.AlertDialog
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.LaunchedEffect
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.rememberUpdatedState
import androidx.compose.runtime.rememberCoroutineScope
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.runtime.Stable
import androidx.compose.runtime.saveable.Saver
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import androidx.compose.ui.platform.LocalContext
import androidx.core.content.ContextCompat
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.launch
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.withContext
import org.hapticon.app.data.ChatExport
import org.hapticon.app.data.PatternFileAccess
import org.hapticon.messaging.mqtt.ClientCertificate
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.sync.KeepAlive
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.app.sync.ReachableService
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.Topics
import org.hapticon.messaging.BrokerAddress

/** The screens of the Chats destination. */
enum class ChatScreen { LIST, CONVERSATION, SETTINGS, INVITE, EDITOR }

/**
 * Which screen the Chats destination shows, held by the app frame: it shows its tab bar only over the chat list
 * (and first launch), as Signal does; a conversation and the screens opened from the list take the whole height.
 */
@Stable
class ChatsNavigation(initial: ChatScreen = ChatScreen.LIST) {
    /** The screen shown. */
    var screen: ChatScreen by mutableStateOf(initial)

    /** True on the chat list, the one Chats screen under the app's tab bar. */
    val atTopLevel: Boolean get() = screen == ChatScreen.LIST

    companion object {
        /** Keeps the screen across configuration changes and process death, by name. */
        val Saver: Saver<ChatsNavigation, String> = Saver({ it.screen.name }, { ChatsNavigation(ChatScreen.valueOf(it)) })
    }
}

/** A [ChatsNavigation] that survives configuration changes and process death. */
@Composable
fun rememberChatsNavigation(): ChatsNavigation = rememberSaveable(saver = ChatsNavigation.Saver) { ChatsNavigation() }

/**
 * The Chats destination: first launch, the conversation list, a conversation, settings, the invite and
 * the icon editor. State-based like the app frame (a handful of screens need no back stack); system
 * back returns to the list. An invite link opened from outside ([ChatComponent.pendingInvite]) is
 * applied here and its outcome shown in one line. The icon editor is a feature of its own: the app's navigation
 * hands it in as [iconEditor].
 */
@Composable
fun ChatsRoute(
    component: ChatComponent,
    iconEditor: @Composable (onDone: () -> Unit) -> Unit,
    onOpenStudy: () -> Unit = {},
    navigation: ChatsNavigation = rememberChatsNavigation(),
) {
    var screen by navigation::screen
    var peer by rememberSaveable { mutableStateOf<String?>(null) }
    var inviteMessage by rememberSaveable { mutableStateOf<String?>(null) }
    Consume(component.pendingInvite) { text ->
        inviteMessage = applyInvite(text, component.repository, component.settings).message
        screen = ChatScreen.LIST
    }
    Consume(component.pendingConversation) { open ->
        if (Topics.isValidUserName(open)) {
            peer = open
            screen = ChatScreen.CONVERSATION
        }
    }
    // Shared text: straight into the picked conversation's composer, or held for the chat the user opens next.
    var sharedDraft by rememberSaveable { mutableStateOf<String?>(null) }
    var choosingForShare by rememberSaveable { mutableStateOf(false) }
    Consume(component.pendingShare) { share ->
        sharedDraft = share.text
        val to = share.peer
        if (to != null && Topics.isValidUserName(to)) {
            peer = to
            screen = ChatScreen.CONVERSATION
        } else {
            screen = ChatScreen.LIST
            choosingForShare = true
        }
    }
    if (choosingForShare) {
        NoticeDialog("Share", "Open a chat: the shared text will be in its message field, ready to send.") { choosingForShare = false }
    }
    inviteMessage?.let { message -> NoticeDialog("Invite", message) { inviteMessage = null } }
    // A scanned invite goes the way of an opened link: checked, applied, its outcome said in the dialog.
    val scanInvite = rememberInviteScanner(onScanned = { component.pendingInvite.value = it }, onFailed = { inviteMessage = it })
    val back = { screen = ChatScreen.LIST }
    when (screen) {
        ChatScreen.EDITOR -> {
            BackHandler { screen = ChatScreen.CONVERSATION }
            iconEditor { screen = ChatScreen.CONVERSATION }
        }
        ChatScreen.CONVERSATION -> {
            val current = peer
            if (current == null) {
                screen = ChatScreen.LIST
            } else {
                BackHandler(onBack = back)
                ConversationRoute(
                    component, current, onBack = back, onEditIcon = { screen = ChatScreen.EDITOR },
                    sharedText = sharedDraft, onSharedTextUsed = { sharedDraft = null },
                )
            }
        }
        ChatScreen.SETTINGS -> {
            BackHandler(onBack = back)
            SettingsRoute(component, onBack = back, onOpenStudy = onOpenStudy)
        }
        ChatScreen.INVITE -> {
            BackHandler(onBack = back)
            InviteRoute(component, onBack = back, onScan = scanInvite)
        }
        ChatScreen.LIST -> ChatListRoute(
            component,
            onOpen = { peer = it; screen = ChatScreen.CONVERSATION },
            onSettings = { screen = ChatScreen.SETTINGS },
            onInvite = { screen = ChatScreen.INVITE },
            onScanInvite = scanInvite,
        )
    }
}

@Composable
fun ChatListRoute(
    component: ChatComponent,
    onOpen: (String) -> Unit,
    onSettings: () -> Unit,
    onInvite: () -> Unit,
    onScanInvite: () -> Unit = {},
) {
    val context = LocalContext.current
    val viewModel: ChatListViewModel = viewModel(
        factory = viewModelFactory {
            initializer {
                val app = context.applicationContext
                ChatListViewModel(
                    component.repository, component.settings, component.probe, batteryExempt = { KeepAlive.isBatteryExempt(app) },
                    connection = connectionOf(component), knownUsers = component.sync.knownUsers,
                )
            }
        },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val check by viewModel.accountCheck.collectAsStateWithLifecycle()
    LaunchedEffect(check) {
        if (check == AccountCheck.Saved) viewModel.accountCheck.value = AccountCheck.Idle
    }
    // Android's answers (notifications, the battery exemption) come back as the app's state: asked again on return.
    val requests = rememberReachableRequests(onAnswered = viewModel::refreshBatteryExemption)
    androidx.lifecycle.compose.LifecycleResumeEffect(Unit) {
        viewModel.refreshBatteryExemption()
        onPauseOrDispose { }
    }
    when (val state = uiState) {
        ChatListUiState.Loading -> ChatLoading()
        is ChatListUiState.NeedsAccount -> FirstLaunchScreen(state.brokerUrl, check, onScanInvite, viewModel::saveAccount)
        // Notifications are asked for here, whatever the answer: from now on messages can arrive.
        is ChatListUiState.OfferReachable -> ReachableOfferScreen(state.user) { stayReachable, autoPlay ->
            viewModel.answerReachableOffer(stayReachable, autoPlay)
            requests.afterChoice(stayReachable)
        }
        is ChatListUiState.Success -> ChatListScreen(
            state,
            ChatListActions(
                onOpen = onOpen,
                onNewChat = { peer, evenIfUnknown -> viewModel.startConversation(peer, evenIfUnknown, onOpen) },
                onArchive = viewModel::archive,
                onUnarchive = viewModel::unarchive,
                onDelete = viewModel::delete,
                onSettings = onSettings,
                onInvite = onInvite,
                onReachableNote = { note ->
                    when (note) {
                        ReachableNote.OFF -> {
                            viewModel.turnOnStayReachable()
                            requests.afterChoice(true)
                        }
                        ReachableNote.BATTERY_OPTIMISED -> requests.askBatteryExemption()
                    }
                },
            ),
        )
    }
}

@Composable
fun ConversationRoute(
    component: ChatComponent,
    peer: String,
    onBack: () -> Unit,
    onEditIcon: () -> Unit,
    sharedText: String? = null,
    onSharedTextUsed: () -> Unit = {},
) {
    val viewModel: ConversationViewModel = viewModel(
        key = "conversation-$peer",
        factory = viewModelFactory {
            initializer {
                ConversationViewModel(
                    peer, { component.settings.preferences.value.userName }, component.repository, component.icons,
                    component.player, component.sync.peerCapabilities, component.sync::wake, component.sync::felt,
                    component.patterns?.patterns()?.map { stored -> stored.map { it.pattern } } ?: flowOf(emptyList()),
                    connectionOf(component), component.sync.knownUsers,
                )
            }
        },
    )
    // On screen means RESUMED: the app left with the chat open (another app, the screen off) pauses it, so later
    // messages are neither marked read nor kept from notifying. The notification goes away; Android learns which
    // conversation is shown (its LocusId, the same as its shortcut's and notification's).
    val activity = androidx.activity.compose.LocalActivity.current
    androidx.lifecycle.compose.LifecycleResumeEffect(peer) {
        component.sync.openConversation(peer)
        component.notifier?.clear(peer)
        if (android.os.Build.VERSION.SDK_INT >= 29) activity?.setLocusContext(android.content.LocusId(MessageNotifier.shortcutId(peer)), null)
        onPauseOrDispose {
            component.sync.closeConversation(peer)
            if (android.os.Build.VERSION.SDK_INT >= 29) activity?.setLocusContext(null, null)
        }
    }
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val prefs by component.settings.preferences.collectAsStateWithLifecycle()
    ConversationScreen(
        uiState,
        ConversationActions(
            onBack = onBack, onSend = viewModel::send, onSelectIcon = viewModel::selectIcon,
            onSelectSticker = viewModel::selectSticker, onFeel = viewModel::feel, onPreview = viewModel::play,
            onRetry = viewModel::retry, onEditIcon = onEditIcon,
            onSelectPattern = viewModel::selectPattern, onPreviewPattern = viewModel::play,
        ),
        enterSends = prefs.enterSends,
        sharedText = sharedText,
        onSharedTextUsed = onSharedTextUsed,
    )
}

/** Hands each value put in [pending] (from outside the app: a link, a notification, a share) to [handle] once. */
@Composable
private fun <T : Any> Consume(pending: MutableStateFlow<T?>, handle: suspend (T) -> Unit) {
    val value by pending.collectAsStateWithLifecycle()
    val current by rememberUpdatedState(handle)
    LaunchedEffect(value) {
        val arrived = value ?: return@LaunchedEffect
        pending.value = null
        current(arrived)
    }
}

/** A dialog that tells the user one thing, closed with OK. */
@Composable
private fun NoticeDialog(title: String, text: String, onDismiss: () -> Unit) {
    AlertDialog(
        onDismissRequest = onDismiss,
        confirmButton = { TextButton(onClick = onDismiss) { Text("OK") } },
        title = { Text(title) },
        text = { Text(text) },
    )
}

/** Whether [component]'s messages can move now, for the line under the chat screens' top bars. */
private fun connectionOf(component: ChatComponent): Flow<ChatConnection> =
    ChatConnection.flow(component.sync.connection, component.online, component.settings.preferences.map { it.brokerUrl })

@Composable
private fun SettingsRoute(component: ChatComponent, onBack: () -> Unit, onOpenStudy: () -> Unit) {
    val context = LocalContext.current
    val viewModel: SettingsViewModel = viewModel(factory = viewModelFactory { initializer { settingsViewModel(component) } })
    val state by viewModel.uiState.collectAsStateWithLifecycle()
    // Asked again on every return to the screen: the user may have changed it in Android's settings.
    androidx.lifecycle.compose.LifecycleResumeEffect(Unit) {
        viewModel.refreshNotifications()
        onPauseOrDispose { }
    }
    // Android 13+: the ongoing and message notifications need the permission; it is asked when the user
    // turns "Stay reachable" on, then the battery exemption, as on first launch. Refused, the service still keeps
    // the connection (Android lets a foreground service run without it), and the settings say that nothing will
    // be announced.
    val requests = rememberReachableRequests(onAnswered = {
        viewModel.permissionAnswered(
            Build.VERSION.SDK_INT < 33 ||
                ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) == PackageManager.PERMISSION_GRANTED,
        )
    })
    val export = rememberLauncherForActivityResult(ActivityResultContracts.CreateDocument("application/json")) { uri ->
        if (uri == null) return@rememberLauncherForActivityResult
        viewModel.export(uri.lastPathSegment.orEmpty()) { checkNotNull(context.contentResolver.openOutputStream(uri)) { "cannot write $uri" } }
    }
    val pickCertificate = rememberCertificatePicker(viewModel)
    SettingsScreen(
        state,
        SettingsActions(
            onBack = onBack,
            update = viewModel::update,
            onBroker = viewModel::setBroker,
            onPassword = viewModel::setPassword,
            onUserName = viewModel::setUserName,
            onStayReachable = { on ->
                viewModel.setStayReachable(on)
                if (on) requests.afterChoice(true) else ReachableService.stop(context)
            },
            onAllowNotifications = {
                val page = Intent(android.provider.Settings.ACTION_APP_NOTIFICATION_SETTINGS)
                    .putExtra(android.provider.Settings.EXTRA_APP_PACKAGE, context.packageName)
                runCatching { context.startActivity(page) }.onFailure { viewModel.notify("Open Android's settings, Apps, Hapticon, Notifications.") }
            },
            onExport = { export.launch("hapticon-chats.json") },
            onOpenStudy = onOpenStudy,
            onTrustKey = viewModel::trust,
            onImportCertificate = pickCertificate,
            onCertificatePassword = { viewModel.unlockCertificate(it) },
            onCancelCertificate = viewModel::cancelCertificateImport,
            onRemoveCertificate = viewModel::removeCertificate,
        ),
        version = runCatching { context.packageManager.getPackageInfo(context.packageName, 0).versionName }.getOrNull() ?: "",
    )
}

/** The settings' ViewModel over [component]'s settings, sync, certificates and messages. */
private fun settingsViewModel(component: ChatComponent): SettingsViewModel = SettingsViewModel(
    component.settings, component.sync.connection, component.sync.securityWarnings, component.sync.changedKeys,
    renderers = { RendererChoice.possible(component.device, null) },
    canNotify = { component.notifier?.canNotify() },
    probe = component.probe,
    trustKey = component.trustKey,
    exportJson = { ChatExport.toJson(component.repository.allMessages()) },
    republishCapabilities = component.sync::republishCapabilities,
    certificates = component.certificates,
    onCertificateChanged = component.sync::restartSession,
)

/**
 * Opens the system file picker for a client certificate and hands what it reads to [viewModel]: the same picker as
 * the Icons import (OpenDocument, read through PatternFileAccess). PKCS#12 files come as application/x-pkcs12 from
 * some providers and octet-stream from others.
 */
@Composable
private fun rememberCertificatePicker(viewModel: SettingsViewModel): () -> Unit {
    val context = LocalContext.current
    val scope = rememberCoroutineScope()
    val picker = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        if (uri == null) return@rememberLauncherForActivityResult
        scope.launch {
            try {
                val (bytes, name) = withContext(Dispatchers.IO) {
                    PatternFileAccess.read(context, uri, ClientCertificate.MAX_PKCS12_BYTES, "a client certificate (.p12)")
                }
                viewModel.certificatePicked(bytes, name)
            } catch (e: java.io.IOException) {
                viewModel.certificateUnreadable(e.message ?: "the file could not be read")
            }
        }
    }
    return { picker.launch(arrayOf("application/x-pkcs12", "application/octet-stream", "*/*")) }
}

@Composable
private fun InviteRoute(component: ChatComponent, onBack: () -> Unit, onScan: () -> Unit) {
    val context = LocalContext.current
    val prefs by component.settings.preferences.collectAsStateWithLifecycle()
    val link = remember(prefs.userName, prefs.brokerUrl) {
        val broker = runCatching { BrokerAddress.parse(prefs.brokerUrl) }.getOrNull()
        broker?.let { InviteLink(prefs.userName, it) }
    }
    InviteScreen(link, onBack, onShare = { text ->
        val send = Intent(Intent.ACTION_SEND).setType("text/plain").putExtra(Intent.EXTRA_TEXT, text)
        context.startActivity(Intent.createChooser(send, "Share invite").addFlags(Intent.FLAG_ACTIVITY_NEW_TASK))
    }, onScan = onScan)
}
