package org.hapticon.app.feature.chat

import androidx.compose.runtime.setValue
import androidx.compose.runtime.getValue
import org.hapticon.app.ui.Sticker
import androidx.compose.foundation.ExperimentalFoundationApi
import androidx.compose.foundation.background
import androidx.compose.foundation.combinedClickable
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.layout.width
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.items
import androidx.compose.material3.AlertDialog
import androidx.compose.material3.Badge
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.DropdownMenu
import androidx.compose.material3.DropdownMenuItem
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.ExtendedFloatingActionButton
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.SnackbarDuration
import androidx.compose.material3.SnackbarHost
import androidx.compose.material3.SnackbarHostState
import androidx.compose.material3.SnackbarResult
import androidx.compose.material3.SwipeToDismissBox
import androidx.compose.material3.SwipeToDismissBoxValue
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.material3.TopAppBar
import androidx.compose.material3.rememberSwipeToDismissBoxState
import androidx.compose.runtime.Composable
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.rememberCoroutineScope
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.CustomAccessibilityAction
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.customActions
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.text.font.FontWeight
import androidx.compose.ui.text.style.TextAlign
import androidx.compose.ui.text.style.TextOverflow
import androidx.compose.ui.unit.dp
import kotlinx.coroutines.launch
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.core.io.IconJson

/** What the chat list can ask for. */
data class ChatListActions(
    val onOpen: (String) -> Unit = {},
    /**
     * Starts a conversation with the name typed, even with one the broker never saw when the second argument is true;
     * returns why not, null when started.
     */
    val onNewChat: (peer: String, evenIfUnknown: Boolean) -> NewChatProblem? = { _, _ -> null },
    val onArchive: (String) -> Unit = {},
    val onUnarchive: (String) -> Unit = {},
    val onDelete: (String) -> Unit = {},
    val onSettings: () -> Unit = {},
    val onInvite: () -> Unit = {},
    /** The button of the note on reaching this user with the app closed ([ReachableNoteRow]). */
    val onReachableNote: (ReachableNote) -> Unit = {},
)

/**
 * The conversations, like Google Messages' list: avatar, name, a one-line preview (with the icon's
 * glyph when the last message carried one), relative time and an unread badge; a "New chat" button;
 * swipe a row away (or long-press it) to archive or delete, with an undo snackbar. Deletion waits for
 * the snackbar: undone, nothing was deleted; leaving the list while it shows deletes at once (the undo
 * went with the snackbar). Archiving takes effect at once and undo brings the chat back. While messages cannot move
 * (offline, broker unreachable) a line under the top bar says so; the list itself comes from Room as always.
 */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun ChatListScreen(
    uiState: ChatListUiState.Success,
    actions: ChatListActions,
    clock: ChatClock = remember { ChatClock() },
    nowMillis: Long = System.currentTimeMillis(),
) {
    val snackbar = remember { SnackbarHostState() }
    val scope = rememberCoroutineScope()
    var hidden by remember { mutableStateOf(setOf<String>()) }
    var showArchived by rememberSaveable { mutableStateOf(false) }
    var newChat by rememberSaveable { mutableStateOf(false) }

    fun archive(peer: String) {
        actions.onArchive(peer)
        scope.launch {
            snackbar.currentSnackbarData?.dismiss()
            if (snackbar.showSnackbar("Chat with $peer archived", "Undo", duration = SnackbarDuration.Short) == SnackbarResult.ActionPerformed) {
                actions.onUnarchive(peer)
            }
        }
    }

    fun delete(peer: String) {
        hidden = hidden + peer
        scope.launch {
            snackbar.currentSnackbarData?.dismiss()
            val result = snackbar.showSnackbar("Chat with $peer deleted", "Undo", duration = SnackbarDuration.Short)
            if (result != SnackbarResult.ActionPerformed) actions.onDelete(peer)
            hidden = hidden - peer
        }
    }

    // Leaving the list (opening a chat, Settings, the app closing) ends the snackbar's coroutine: what is
    // still waiting for its undo is deleted then, as Google Messages does, rather than silently kept.
    val pendingDeletes by androidx.compose.runtime.rememberUpdatedState(hidden)
    val commitDelete by androidx.compose.runtime.rememberUpdatedState(actions.onDelete)
    androidx.compose.runtime.DisposableEffect(Unit) {
        onDispose { pendingDeletes.forEach { commitDelete(it) } }
    }

    val visible = uiState.conversations.filter { it.peer !in hidden && (it.peer in uiState.archived) == showArchived }
    val archivedCount = uiState.conversations.count { it.peer in uiState.archived }
    Scaffold(
        topBar = { ChatListTopBar(showArchived, uiState.connection, onLeaveArchive = { showArchived = false }, actions) },
        floatingActionButton = { if (!showArchived) NewChatButton(onClick = { newChat = true }) },
        snackbarHost = { SnackbarHost(snackbar) },
    ) { padding ->
        Column(Modifier.fillMaxSize().padding(padding)) {
            uiState.reachableNote?.let { ReachableNoteRow(it, actions.onReachableNote) }
            if (visible.isEmpty() && !showArchived) {
                EmptyChats(uiState.user, Modifier.fillMaxWidth().weight(1f), onInvite = actions.onInvite, onNewChat = { newChat = true })
            } else {
                LazyColumn(Modifier.fillMaxWidth().weight(1f), contentPadding = PaddingValues(bottom = 88.dp)) {
                    items(visible, key = { it.peer }) { summary ->
                        ConversationRow(
                            summary, clock.relative(summary.lastAtMillis ?: 0, nowMillis).takeIf { summary.lastAtMillis != null },
                            archived = showArchived, onOpen = actions.onOpen,
                            onArchive = { if (showArchived) actions.onUnarchive(it) else archive(it) }, onDelete = ::delete,
                        )
                    }
                    if (!showArchived && archivedCount > 0) item { ArchivedChatsButton(archivedCount, onClick = { showArchived = true }) }
                }
            }
        }
    }
    if (newChat) {
        NewChatDialog(
            onStart = { peer, evenIfUnknown -> actions.onNewChat(peer, evenIfUnknown).also { if (it == null) newChat = false } },
            onDismiss = { newChat = false },
        )
    }
}

/** "Chats" (or "Archived chats", with the way back), invite and settings, and the connection line under them. */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
private fun ChatListTopBar(showArchived: Boolean, connection: ChatConnection, onLeaveArchive: () -> Unit, actions: ChatListActions) {
    Column {
        TopAppBar(
            title = { Text(if (showArchived) "Archived chats" else "Chats") },
            navigationIcon = {
                if (showArchived) IconButton(onClick = onLeaveArchive) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back to chats") }
            },
            actions = {
                IconButton(onClick = actions.onInvite) { Icon(HapticonIcons.PersonAdd, contentDescription = "Invite someone") }
                IconButton(onClick = actions.onSettings) { Icon(HapticonIcons.Settings, contentDescription = "Settings") }
            },
        )
        connection.line()?.let { ConnectionLine(it) }
    }
}

/** The "New chat" button over the list. */
@Composable
private fun NewChatButton(onClick: () -> Unit) {
    ExtendedFloatingActionButton(
        onClick = onClick,
        icon = { Icon(HapticonIcons.Edit, contentDescription = null) },
        text = { Text("New chat") },
        // Named on the button itself: the label is a child the merged tree does not always carry.
        modifier = Modifier.semantics { contentDescription = "New chat" },
    )
}

/** The way to the archived chats, at the end of the list. */
@Composable
private fun ArchivedChatsButton(count: Int, onClick: () -> Unit) {
    TextButton(onClick = onClick, modifier = Modifier.padding(horizontal = 8.dp)) {
        Icon(HapticonIcons.Archive, contentDescription = null)
        Text("Archived ($count)", Modifier.padding(start = 8.dp))
    }
}

@Composable
private fun EmptyChats(user: String, modifier: Modifier, onInvite: () -> Unit, onNewChat: () -> Unit) {
    Column(
        modifier.padding(32.dp),
        verticalArrangement = Arrangement.spacedBy(12.dp, Alignment.CenterVertically),
        horizontalAlignment = Alignment.CenterHorizontally,
    ) {
        Icon(HapticonIcons.Vibration, contentDescription = null, tint = MaterialTheme.colorScheme.primary, modifier = Modifier.size(56.dp))
        Text("No chats yet", style = MaterialTheme.typography.headlineSmall)
        Text(
            "You are $user. Show your invite code to someone next to you, or start a chat with a user name you know.",
            style = MaterialTheme.typography.bodyLarge, textAlign = TextAlign.Center, color = MaterialTheme.colorScheme.onSurfaceVariant,
        )
        androidx.compose.material3.Button(onClick = onInvite) { Text("Show my invite code") }
        TextButton(onClick = onNewChat) { Text("Start a chat by user name") }
    }
}

@OptIn(ExperimentalMaterial3Api::class, ExperimentalFoundationApi::class)
@Composable
private fun ConversationRow(
    summary: ConversationSummary,
    time: String?,
    archived: Boolean,
    onOpen: (String) -> Unit,
    onArchive: (String) -> Unit,
    onDelete: (String) -> Unit,
) {
    val peer = summary.peer
    var menu by remember { mutableStateOf(false) }
    val dismiss = rememberSwipeToDismissBoxState()
    // Swiping acts once the row is fully away; the row is then gone from the list (archived or hidden).
    androidx.compose.runtime.LaunchedEffect(dismiss.currentValue) {
        when (dismiss.currentValue) {
            SwipeToDismissBoxValue.StartToEnd -> onArchive(peer)
            SwipeToDismissBoxValue.EndToStart -> onDelete(peer)
            SwipeToDismissBoxValue.Settled -> Unit
        }
        if (dismiss.currentValue != SwipeToDismissBoxValue.Settled) dismiss.snapTo(SwipeToDismissBoxValue.Settled)
    }
    val archiveLabel = if (archived) "Unarchive" else "Archive"
    SwipeToDismissBox(
        state = dismiss,
        backgroundContent = { SwipeBackground(toDelete = dismiss.dismissDirection == SwipeToDismissBoxValue.EndToStart) },
    ) {
        Box {
            Row(
                Modifier.fillMaxWidth().background(MaterialTheme.colorScheme.surface)
                    .combinedClickable(
                        onClickLabel = "Open conversation with $peer",
                        onLongClickLabel = "More actions",
                        onLongClick = { menu = true },
                        onClick = { onOpen(peer) },
                    )
                    .semantics {
                        customActions = listOf(
                            CustomAccessibilityAction(archiveLabel) { onArchive(peer); true },
                            CustomAccessibilityAction("Delete") { onDelete(peer); true },
                        )
                    }
                    .padding(horizontal = 16.dp, vertical = 10.dp),
                verticalAlignment = Alignment.CenterVertically,
            ) {
                Avatar(peer)
                NameAndPreview(summary, Modifier.weight(1f).padding(horizontal = 16.dp))
                TimeAndUnread(time, summary.unread)
            }
            RowMenu(
                expanded = menu, archiveLabel, onDismiss = { menu = false },
                onArchive = { menu = false; onArchive(peer) }, onDelete = { menu = false; onDelete(peer) },
            )
        }
    }
}

/** What a swipe uncovers under a row: delete (to the start) or archive (to the end). */
@Composable
private fun SwipeBackground(toDelete: Boolean) {
    Row(
        Modifier.fillMaxSize().background(if (toDelete) MaterialTheme.colorScheme.errorContainer else MaterialTheme.colorScheme.secondaryContainer)
            .padding(horizontal = 24.dp),
        verticalAlignment = Alignment.CenterVertically,
        horizontalArrangement = if (toDelete) Arrangement.End else Arrangement.Start,
    ) {
        Icon(if (toDelete) HapticonIcons.Delete else HapticonIcons.Archive, contentDescription = null)
    }
}

/** The peer's name and the last message's preview, in bold while unread. */
@Composable
private fun NameAndPreview(summary: ConversationSummary, modifier: Modifier) {
    Column(modifier) {
        val unread = summary.unread > 0
        Text(
            summary.peer, style = MaterialTheme.typography.titleMedium,
            fontWeight = if (unread) FontWeight.Bold else FontWeight.Normal, maxLines = 1, overflow = TextOverflow.Ellipsis,
        )
        Text(
            previewOf(summary), style = MaterialTheme.typography.bodyMedium, maxLines = 1, overflow = TextOverflow.Ellipsis,
            color = if (unread) MaterialTheme.colorScheme.onSurface else MaterialTheme.colorScheme.onSurfaceVariant,
            fontWeight = if (unread) FontWeight.SemiBold else FontWeight.Normal,
        )
    }
}

/** The last message's time over the unread badge (or the badge's height kept empty). */
@Composable
private fun TimeAndUnread(time: String?, unread: Int) {
    Column(horizontalAlignment = Alignment.End, verticalArrangement = Arrangement.spacedBy(6.dp)) {
        time?.let { Text(it, style = MaterialTheme.typography.labelMedium, color = MaterialTheme.colorScheme.onSurfaceVariant) }
        if (unread > 0) {
            Badge(containerColor = MaterialTheme.colorScheme.primary, contentColor = MaterialTheme.colorScheme.onPrimary) {
                Text(if (unread > 99) "99+" else unread.toString(), Modifier.semantics {
                    this[androidx.compose.ui.semantics.SemanticsProperties.ContentDescription] = listOf("$unread unread")
                })
            }
        } else {
            Box(Modifier.height(16.dp).width(1.dp))
        }
    }
}

/** A row's long-press menu: archive (or unarchive) and delete. */
@Composable
private fun RowMenu(expanded: Boolean, archiveLabel: String, onDismiss: () -> Unit, onArchive: () -> Unit, onDelete: () -> Unit) {
    DropdownMenu(expanded = expanded, onDismissRequest = onDismiss) {
        DropdownMenuItem(
            text = { Text(archiveLabel) }, leadingIcon = { Icon(HapticonIcons.Archive, contentDescription = null) },
            onClick = onArchive,
        )
        DropdownMenuItem(
            text = { Text("Delete") }, leadingIcon = { Icon(HapticonIcons.Delete, contentDescription = null) },
            onClick = onDelete,
        )
    }
}

/** The glyph that stands for a haptic icon in text (a wavy dash: a vibration drawn in one character). */
const val ICON_GLYPH: String = "〰"

/** The row's preview: "You: " for own messages, the text, and the icon's glyph and name. */
fun previewOf(summary: ConversationSummary): String {
    val iconName = summary.lastIconJson?.let { runCatching { IconJson.decode(it).name }.getOrNull() }
    val body = listOfNotNull(
        iconName?.let { "$ICON_GLYPH $it" },
        summary.lastText?.takeIf { it.isNotEmpty() },
    ).joinToString(" · ").ifEmpty { if (summary.lastAtMillis == null) "No messages yet" else "Sticker" }
    return if (summary.lastOutgoing && summary.lastAtMillis != null) "You: $body" else body
}

/**
 * Asks for the peer's user name. A name the broker never saw is said so under the field, and the button becomes
 * "Start anyway" (they may set up the app later; messages reach them once they connect) until the name changes.
 */
@Composable
private fun NewChatDialog(onStart: (peer: String, evenIfUnknown: Boolean) -> NewChatProblem?, onDismiss: () -> Unit) {
    var peer by rememberSaveable { mutableStateOf("") }
    var error by remember { mutableStateOf<NewChatProblem?>(null) }
    val unknown = error is NewChatProblem.NeverConnected
    AlertDialog(
        onDismissRequest = onDismiss,
        title = { Text("New chat") },
        text = {
            OutlinedTextField(
                peer, { peer = it; error = null }, label = { Text("Their user name") }, singleLine = true,
                modifier = Modifier.semantics { contentDescription = "Their user name" },
                isError = error != null, supportingText = { Text(error?.message ?: "As they chose it on their phone, e.g. bob") },
            )
        },
        confirmButton = { TextButton(onClick = { error = onStart(peer, unknown) }) { Text(if (unknown) "Start anyway" else "Start chat") } },
        dismissButton = { TextButton(onClick = onDismiss) { Text("Cancel") } },
    )
}

/** The spinner while the chat list loads. */
@Composable
internal fun ChatLoading(modifier: Modifier = Modifier) {
    Box(modifier.fillMaxSize(), contentAlignment = Alignment.Center) { CircularProgressIndicator() }
}
