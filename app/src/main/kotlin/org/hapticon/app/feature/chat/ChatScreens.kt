package org.hapticon.app.feature.chat

import androidx.compose.runtime.remember
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.ui.text.input.KeyboardType
import androidx.compose.ui.text.input.PasswordVisualTransformation
import androidx.activity.compose.BackHandler
import androidx.compose.foundation.Image
import androidx.compose.foundation.clickable
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.Spacer
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.layout.width
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.LazyRow
import androidx.compose.foundation.lazy.items
import androidx.compose.material3.AssistChip
import androidx.compose.material3.Button
import androidx.compose.material3.Card
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.FilterChip
import androidx.compose.material3.HorizontalDivider
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.DisposableEffect
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.res.painterResource
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.unit.dp
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.feature.iconeditor.IconEditorRoute
import org.hapticon.app.playback.AdaptiveRenderer
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.app.ui.SwitchRow
import org.hapticon.core.HapticIcon

/**
 * The Chats destination: the first-run account screen, the conversation list, a conversation and the
 * icon editor. State-based like the app frame (a handful of screens need no back stack); system back
 * returns to the list.
 */
@Composable
fun ChatsRoute(component: ChatComponent) {
    var peer by rememberSaveable { mutableStateOf<String?>(null) }
    var editing by rememberSaveable { mutableStateOf(false) }
    when {
        editing -> {
            BackHandler { editing = false }
            IconEditorRoute(component.icons, component.player, onDone = { editing = false })
        }
        peer != null -> {
            val current = peer!!
            BackHandler { peer = null }
            ConversationRoute(component, current, onBack = { peer = null }, onEditIcon = { editing = true })
        }
        else -> ChatListRoute(component, onOpen = { peer = it })
    }
}

@Composable
fun ChatListRoute(component: ChatComponent, onOpen: (String) -> Unit) {
    val viewModel: ChatListViewModel = viewModel(
        factory = viewModelFactory { initializer { ChatListViewModel(component.repository, component.settings) } },
    )
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    ChatListScreen(
        uiState = uiState,
        availableRenderers = org.hapticon.app.playback.RendererChoice.possible(component.device, null),
        onSaveAccount = viewModel::saveAccount,
        onNewConversation = { viewModel.startConversation(it, onOpen) },
        onOpen = onOpen,
        onAutoPlay = viewModel::setAutoPlay,
        onRendererOverride = viewModel::setRendererOverride,
    )
}

/** The account screen until a user name is set, then the conversations and the chat settings. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun ChatListScreen(
    uiState: ChatListUiState,
    availableRenderers: List<AdaptiveRenderer>,
    onSaveAccount: (userName: String, brokerUrl: String, password: String) -> String?,
    onNewConversation: (String) -> String?,
    onOpen: (String) -> Unit,
    onAutoPlay: (Boolean) -> Unit,
    onRendererOverride: (AdaptiveRenderer?) -> Unit,
) {
    Scaffold(topBar = { TopAppBar(title = { Text("Chats") }) }) { padding ->
        Box(Modifier.fillMaxSize().padding(padding)) {
            when (uiState) {
                ChatListUiState.Loading -> CircularProgressIndicator(Modifier.align(Alignment.Center))
                is ChatListUiState.NeedsAccount -> AccountForm(uiState.brokerUrl, onSaveAccount)
                is ChatListUiState.Success -> LazyColumn(Modifier.fillMaxSize().padding(horizontal = 16.dp)) {
                    item { Text("Signed in as ${uiState.user}", style = MaterialTheme.typography.bodyMedium) }
                    item { NewConversation(onNewConversation) }
                    if (uiState.conversations.isEmpty()) item { Text("No conversations yet", Modifier.padding(vertical = 16.dp)) }
                    items(uiState.conversations, key = { it.peer }) { ConversationRow(it, onOpen) }
                    item {
                        HorizontalDivider(Modifier.padding(vertical = 8.dp))
                        SwitchRow("Play icons when messages arrive", uiState.preferences.autoPlay, onAutoPlay)
                        val selected = availableRenderers.firstOrNull { it.name == uiState.preferences.rendererOverride }
                        DropdownField(
                            label = "Renderer",
                            options = listOf<AdaptiveRenderer?>(null) + availableRenderers,
                            selected = selected,
                            optionLabel = { it?.label ?: "Automatic (best for this phone)" },
                            onSelect = onRendererOverride,
                        )
                    }
                }
            }
        }
    }
}

@Composable
private fun AccountForm(defaultBroker: String, onSave: (String, String, String) -> String?) {
    var name by rememberSaveable { mutableStateOf("") }
    var broker by rememberSaveable { mutableStateOf(defaultBroker) }
    // Not rememberSaveable: a password does not belong in the saved instance state.
    var password by remember { mutableStateOf("") }
    var error by rememberSaveable { mutableStateOf<String?>(null) }
    Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(12.dp)) {
        Text("Welcome to Hapticon", style = MaterialTheme.typography.headlineSmall)
        OutlinedTextField(name, { name = it }, label = { Text("User name") }, singleLine = true, modifier = Modifier.fillMaxWidth())
        OutlinedTextField(broker, { broker = it }, label = { Text("Broker URL") }, singleLine = true, modifier = Modifier.fillMaxWidth())
        OutlinedTextField(
            password, { password = it }, label = { Text("Broker password") }, singleLine = true,
            visualTransformation = PasswordVisualTransformation(),
            keyboardOptions = KeyboardOptions(keyboardType = KeyboardType.Password), modifier = Modifier.fillMaxWidth(),
        )
        error?.let { Text(it, color = MaterialTheme.colorScheme.error) }
        Button(onClick = { error = onSave(name, broker, password) }) { Text("Start chatting") }
    }
}

@Composable
private fun NewConversation(onStart: (String) -> String?) {
    var peer by rememberSaveable { mutableStateOf("") }
    var error by rememberSaveable { mutableStateOf<String?>(null) }
    Row(verticalAlignment = Alignment.CenterVertically) {
        OutlinedTextField(
            peer, { peer = it }, label = { Text("Peer's user name") }, singleLine = true,
            isError = error != null, supportingText = error?.let { { Text(it) } }, modifier = Modifier.weight(1f),
        )
        TextButton(onClick = { error = onStart(peer); if (error == null) peer = "" }) { Text("New conversation") }
    }
}

@Composable
private fun ConversationRow(summary: ConversationSummary, onOpen: (String) -> Unit) {
    Column(
        Modifier.fillMaxWidth().clickable(onClickLabel = "Open conversation with ${summary.peer}") { onOpen(summary.peer) }
            .padding(vertical = 12.dp),
    ) {
        Text(summary.peer + if (summary.unread > 0) "  (${summary.unread} new)" else "", style = MaterialTheme.typography.titleMedium)
        summary.lastText?.takeIf { it.isNotEmpty() }?.let { Text(it, maxLines = 1, style = MaterialTheme.typography.bodySmall) }
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
                    component.player, component.sync.peerCapabilities, component.sync::wake,
                )
            }
        },
    )
    // Read receipts go out while the conversation is on screen.
    DisposableEffect(peer) {
        component.sync.openConversation(peer)
        onDispose { component.sync.closeConversation(peer) }
    }
    val uiState by viewModel.uiState.collectAsStateWithLifecycle()
    ConversationScreen(
        uiState, onBack = onBack, onSend = { viewModel.send(it) }, onSelectIcon = viewModel::selectIcon,
        onSelectSticker = viewModel::selectSticker, onPlay = viewModel::play, onEditIcon = onEditIcon,
    )
}

/** A conversation: messages oldest first, then the composer with sticker and icon pickers. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun ConversationScreen(
    uiState: ConversationUiState,
    onBack: () -> Unit,
    onSend: (String) -> Unit,
    onSelectIcon: (HapticIcon?) -> Unit,
    onSelectSticker: (Sticker?) -> Unit,
    onPlay: (HapticIcon) -> Unit,
    onEditIcon: () -> Unit,
) {
    val title = (uiState as? ConversationUiState.Success)?.peer ?: ""
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text(title) },
                navigationIcon = { IconButton(onClick = onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back to chats") } },
            )
        },
    ) { padding ->
        when (uiState) {
            ConversationUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) { CircularProgressIndicator() }
            is ConversationUiState.Success -> Column(Modifier.fillMaxSize().padding(padding)) {
                LazyColumn(Modifier.weight(1f).fillMaxWidth().padding(horizontal = 12.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
                    items(uiState.messages, key = { it.id }) { MessageBubble(it, onPlay) }
                }
                Composer(uiState, onSend, onSelectIcon, onSelectSticker, onPlay, onEditIcon)
            }
        }
    }
}

@Composable
private fun MessageBubble(message: StoredMessage, onPlay: (HapticIcon) -> Unit) {
    Row(Modifier.fillMaxWidth(), horizontalArrangement = if (message.outgoing) Arrangement.End else Arrangement.Start) {
        Card(Modifier.padding(2.dp)) {
            Column(Modifier.padding(10.dp)) {
                Sticker.of(message.sticker)?.let {
                    Image(painterResource(it.drawable), contentDescription = "Sticker: ${it.label}", modifier = Modifier.size(72.dp))
                } ?: message.sticker?.let { Text("[$it]") }
                if (message.text.isNotEmpty()) Text(message.text)
                message.icon?.let { icon ->
                    AssistChip(
                        onClick = { onPlay(icon) },
                        label = { Text("Feel ${icon.name}") },
                        modifier = Modifier.semantics { contentDescription = "Play haptic icon ${icon.name}" },
                    )
                }
                if (message.outgoing) {
                    val state = stateLabel(message.state)
                    Text(
                        state, style = MaterialTheme.typography.labelSmall,
                        color = if (message.state == MessageState.FAILED) MaterialTheme.colorScheme.error else MaterialTheme.colorScheme.onSurfaceVariant,
                        modifier = Modifier.semantics { contentDescription = "Message state: $state" },
                    )
                }
            }
        }
    }
}

/** The visible label of an own message's state. */
fun stateLabel(state: MessageState): String = when (state) {
    MessageState.SENDING -> "Sending…"
    MessageState.SENT -> "Sent"
    MessageState.DELIVERED -> "Delivered"
    MessageState.READ -> "Read"
    MessageState.FAILED -> "Failed, retrying"
    MessageState.RECEIVED -> "Received"
}

@Composable
private fun Composer(
    uiState: ConversationUiState.Success,
    onSend: (String) -> Unit,
    onSelectIcon: (HapticIcon?) -> Unit,
    onSelectSticker: (Sticker?) -> Unit,
    onPlay: (HapticIcon) -> Unit,
    onEditIcon: () -> Unit,
) {
    var text by rememberSaveable { mutableStateOf("") }
    Column(Modifier.fillMaxWidth().padding(8.dp)) {
        Text("Sticker", style = MaterialTheme.typography.labelMedium)
        LazyRow(horizontalArrangement = Arrangement.spacedBy(6.dp)) {
            items(Sticker.entries) { sticker ->
                val selected = uiState.selectedSticker == sticker
                Image(
                    painterResource(sticker.drawable),
                    contentDescription = "Sticker ${sticker.label}",
                    modifier = Modifier.size(44.dp)
                        .semantics { stateDescription = if (selected) "selected" else "not selected" }
                        .clickable { onSelectSticker(if (selected) null else sticker) },
                )
            }
        }
        Text("Haptic icon (press to feel, again to choose)", style = MaterialTheme.typography.labelMedium)
        LazyRow(horizontalArrangement = Arrangement.spacedBy(6.dp), verticalAlignment = Alignment.CenterVertically) {
            items(uiState.icons, key = { it.name }) { icon ->
                val selected = uiState.selectedIcon == icon
                FilterChip(
                    selected = selected,
                    onClick = {
                        onPlay(icon)
                        onSelectIcon(if (selected) null else icon)
                    },
                    label = { Text(icon.name) },
                    leadingIcon = { EnvelopeThumbnail(icon, Modifier.width(40.dp).height(20.dp)) },
                    modifier = Modifier.semantics { contentDescription = "Icon ${icon.name}" },
                )
            }
            item { TextButton(onClick = onEditIcon) { Text("New icon…") } }
        }
        uiState.selectedIcon?.let { icon ->
            val feel = uiState.peerFeel
            Text(
                if (feel == null) "How ${icon.name} will feel there: unknown until ${uiState.peer} connects"
                else "How ${icon.name} will feel there: ${feel.renderer.label}" + (feel.fidelityPercent?.let { ", $it% fidelity" } ?: ""),
                style = MaterialTheme.typography.bodySmall,
            )
        }
        uiState.error?.let { Text(it, color = MaterialTheme.colorScheme.error) }
        Row(verticalAlignment = Alignment.CenterVertically) {
            OutlinedTextField(text, { text = it }, label = { Text("Message") }, modifier = Modifier.weight(1f))
            Spacer(Modifier.width(8.dp))
            Button(onClick = { onSend(text); text = "" }) { Text("Send") }
        }
    }
}
