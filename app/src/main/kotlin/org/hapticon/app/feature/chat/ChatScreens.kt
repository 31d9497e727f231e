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
import androidx.compose.runtime.rememberCoroutineScope
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
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
import org.hapticon.app.feature.iconeditor.IconEditorRoute
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.app.sync.ReachableService
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.Topics
import org.hapticon.messaging.BrokerAddress

/** The screens of the Chats destination. */
private enum class ChatScreen { LIST, CONVERSATION, SETTINGS, INVITE, EDITOR }

/**
 * The Chats destination: first launch, the conversation list, a conversation, settings, the invite and
 * the icon editor. State-based like the app frame (a handful of screens need no back stack); system
 * back returns to the list. An invite link opened from outside ([ChatComponent.pendingInvite]) is
 * applied here and its outcome shown in one line.
 */
@Composable
fun ChatsRoute(component: ChatComponent, onOpenStudy: () -> Unit = {}) {
    var screen by rememberSaveable { mutableStateOf(ChatScreen.LIST) }
    var peer by rememberSaveable { mutableStateOf<String?>(null) }
    var inviteMessage by rememberSaveable { mutableStateOf<String?>(null) }
    val pendingInvite by component.pendingInvite.collectAsStateWithLifecycle()
    LaunchedEffect(pendingInvite) {
        val text = pendingInvite ?: return@LaunchedEffect
        component.pendingInvite.value = null
        inviteMessage = when (val outcome = applyInvite(text, component.repository, component.settings)) {
            is InviteOutcome.Rejected -> "Invite not used: ${outcome.reason}"
            is InviteOutcome.Added -> outcome.note ?: buildString {
                append(outcome.peer?.let { "$it added to your chats" } ?: "Invite opened")
                if (outcome.brokerFilled) append("; broker filled in")
            }
        }
        screen = ChatScreen.LIST
    }
    val pendingConversation by component.pendingConversation.collectAsStateWithLifecycle()
    LaunchedEffect(pendingConversation) {
        val open = pendingConversation ?: return@LaunchedEffect
        component.pendingConversation.value = null
        if (Topics.isValidUserName(open)) {
            peer = open
            screen = ChatScreen.CONVERSATION
        }
    }
    inviteMessage?.let { message ->
        AlertDialog(
            onDismissRequest = { inviteMessage = null },
            confirmButton = { TextButton(onClick = { inviteMessage = null }) { Text("OK") } },
            title = { Text("Invite") },
            text = { Text(message) },
        )
    }
    val back = { screen = ChatScreen.LIST }
    when (screen) {
        ChatScreen.EDITOR -> {
            BackHandler { screen = ChatScreen.CONVERSATION }
            IconEditorRoute(component.icons, component.player, onDone = { screen = ChatScreen.CONVERSATION })
        }
        ChatScreen.CONVERSATION -> {
            val current = peer
            if (current == null) {
                screen = ChatScreen.LIST
            } else {
                BackHandler(onBack = back)
                ConversationRoute(component, current, onBack = back, onEditIcon = { screen = ChatScreen.EDITOR })
            }
        }
        ChatScreen.SETTINGS -> {
            BackHandler(onBack = back)
            SettingsRoute(component, onBack = back, onOpenStudy = onOpenStudy)
        }
        ChatScreen.INVITE -> {
            BackHandler(onBack = back)
            InviteRoute(component, onBack = back)
        }
        ChatScreen.LIST -> ChatListRoute(
            component,
            onOpen = { peer = it; screen = ChatScreen.CONVERSATION },
            onSettings = { screen = ChatScreen.SETTINGS },
            onInvite = { screen = ChatScreen.INVITE },
        )
    }
}

@Composable
fun ChatListRoute(component: ChatComponent, onOpen: (String) -> Unit, onSettings: () -> Unit, onInvite: () -> Unit) {
    val viewModel: ChatListViewModel = viewModel(
        factory = viewModelFactory { initializer { ChatListViewModel(component.repository, component.settings, component.probe) } },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    val check by viewModel.accountCheck.collectAsStateWithLifecycle()
    // Android 13+: notifications are asked for when they are first needed, right after the account is saved.
    // Refused, messages still arrive and show in the list; Settings says so and links to Android's page.
    val notificationPermission = rememberLauncherForActivityResult(ActivityResultContracts.RequestPermission()) { }
    val context = LocalContext.current
    LaunchedEffect(check) {
        if (check != AccountCheck.Saved) return@LaunchedEffect
        viewModel.accountCheck.value = AccountCheck.Idle
        if (Build.VERSION.SDK_INT >= 33 &&
            ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) != PackageManager.PERMISSION_GRANTED
        ) notificationPermission.launch(Manifest.permission.POST_NOTIFICATIONS)
    }
    when (val state = uiState) {
        ChatListUiState.Loading -> ChatLoading()
        is ChatListUiState.NeedsAccount -> FirstLaunchScreen(state.brokerUrl, check, viewModel::saveAccount)
        is ChatListUiState.Success -> ChatListScreen(
            state,
            ChatListActions(
                onOpen = onOpen,
                onNewChat = { viewModel.startConversation(it, onOpen) },
                onArchive = viewModel::archive,
                onUnarchive = viewModel::unarchive,
                onDelete = viewModel::delete,
                onSettings = onSettings,
                onInvite = onInvite,
            ),
        )
    }
}

@Composable
fun ConversationRoute(component: ChatComponent, peer: String, onBack: () -> Unit, onEditIcon: () -> Unit) {
    val viewModel: ConversationViewModel = viewModel(
        key = "conversation-$peer",
        factory = viewModelFactory {
            initializer {
                ConversationViewModel(
                    peer, { component.settings.preferences.value.userName }, component.repository, component.icons,
                    component.player, component.sync.peerCapabilities, component.sync::wake, component.sync::felt,
                    component.patterns?.patterns()?.map { stored -> stored.map { it.pattern } } ?: flowOf(emptyList()),
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
            onBack = onBack, onSend = { viewModel.send(it) }, onSelectIcon = viewModel::selectIcon,
            onSelectSticker = viewModel::selectSticker, onFeel = viewModel::feel, onPreview = viewModel::play,
            onRetry = viewModel::retry, onEditIcon = onEditIcon,
            onSelectPattern = viewModel::selectPattern, onPreviewPattern = viewModel::play,
        ),
        enterSends = prefs.enterSends,
    )
}

@Composable
private fun SettingsRoute(component: ChatComponent, onBack: () -> Unit, onOpenStudy: () -> Unit) {
    val context = LocalContext.current
    val viewModel: SettingsViewModel = viewModel(
        factory = viewModelFactory {
            initializer {
                SettingsViewModel(
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
            }
        },
    )
    val state by viewModel.uiState.collectAsStateWithLifecycle()
    // Asked again on every return to the screen: the user may have changed it in Android's settings.
    androidx.lifecycle.compose.LifecycleResumeEffect(Unit) {
        viewModel.refreshNotifications()
        onPauseOrDispose { }
    }
    val setReachable = { on: Boolean ->
        viewModel.setStayReachable(on)
        if (on) ReachableService.start(context) else ReachableService.stop(context)
    }
    // Android 13+: the ongoing and message notifications need the permission; it is asked when the user
    // turns "Stay reachable" on. Refused, the service still keeps the connection (Android lets a
    // foreground service run without it), and the settings say that nothing will be announced.
    val permission = rememberLauncherForActivityResult(ActivityResultContracts.RequestPermission()) { granted ->
        setReachable(true)
        viewModel.permissionAnswered(granted)
    }
    val export = rememberLauncherForActivityResult(ActivityResultContracts.CreateDocument("application/json")) { uri ->
        if (uri == null) return@rememberLauncherForActivityResult
        viewModel.export(uri.lastPathSegment.orEmpty()) { checkNotNull(context.contentResolver.openOutputStream(uri)) { "cannot write $uri" } }
    }
    // The same system file picker as the Icons import (OpenDocument, read through PatternFileAccess).
    val scope = androidx.compose.runtime.rememberCoroutineScope()
    val certificatePicker = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        if (uri == null) return@rememberLauncherForActivityResult
        scope.launch {
            try {
                val (bytes, name) = kotlinx.coroutines.withContext(kotlinx.coroutines.Dispatchers.IO) {
                    org.hapticon.app.feature.icons.PatternFileAccess.read(
                        context, uri, org.hapticon.messaging.mqtt.ClientCertificate.MAX_PKCS12_BYTES, "a client certificate (.p12)",
                    )
                }
                viewModel.certificatePicked(bytes, name)
            } catch (e: java.io.IOException) {
                viewModel.certificateUnreadable(e.message ?: "the file could not be read")
            }
        }
    }
    SettingsScreen(
        state,
        SettingsActions(
            onBack = onBack,
            update = viewModel::update,
            onBroker = viewModel::setBroker,
            onPassword = viewModel::setPassword,
            onUserName = viewModel::setUserName,
            onStayReachable = { on ->
                val needsPermission = on && Build.VERSION.SDK_INT >= 33 &&
                    ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) != PackageManager.PERMISSION_GRANTED
                if (needsPermission) permission.launch(Manifest.permission.POST_NOTIFICATIONS) else setReachable(on)
            },
            onAllowNotifications = {
                val page = Intent(android.provider.Settings.ACTION_APP_NOTIFICATION_SETTINGS)
                    .putExtra(android.provider.Settings.EXTRA_APP_PACKAGE, context.packageName)
                runCatching { context.startActivity(page) }.onFailure { viewModel.notify("Open Android's settings, Apps, Hapticon, Notifications.") }
            },
            onExport = { export.launch("hapticon-chats.json") },
            onOpenStudy = onOpenStudy,
            onTrustKey = viewModel::trust,
            // PKCS#12 files come as application/x-pkcs12 from some providers and octet-stream from others.
            onImportCertificate = { certificatePicker.launch(arrayOf("application/x-pkcs12", "application/octet-stream", "*/*")) },
            onCertificatePassword = { viewModel.unlockCertificate(it) },
            onCancelCertificate = viewModel::cancelCertificateImport,
            onRemoveCertificate = viewModel::removeCertificate,
        ),
        version = runCatching { context.packageManager.getPackageInfo(context.packageName, 0).versionName }.getOrNull() ?: "",
    )
}

@Composable
private fun InviteRoute(component: ChatComponent, onBack: () -> Unit) {
    val context = LocalContext.current
    val prefs by component.settings.preferences.collectAsStateWithLifecycle()
    val link = remember(prefs.userName, prefs.brokerUrl) {
        val broker = runCatching { BrokerAddress.parse(prefs.brokerUrl) }.getOrNull()
        broker?.let { InviteLink(prefs.userName, it) }
    }
    InviteScreen(link, onBack) { text ->
        val send = Intent(Intent.ACTION_SEND).setType("text/plain").putExtra(Intent.EXTRA_TEXT, text)
        context.startActivity(Intent.createChooser(send, "Share invite").addFlags(Intent.FLAG_ACTIVITY_NEW_TASK))
    }
}
