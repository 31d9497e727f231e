package org.hapticon.app.feature.chat

import org.hapticon.app.ui.Sticker
import androidx.compose.foundation.ExperimentalFoundationApi
import androidx.compose.foundation.Image
import androidx.compose.foundation.background
import androidx.compose.foundation.border
import androidx.compose.foundation.clickable
import androidx.compose.foundation.combinedClickable
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.PaddingValues
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.heightIn
import androidx.compose.foundation.layout.ExperimentalLayoutApi
import androidx.compose.foundation.layout.WindowInsets
import androidx.compose.foundation.layout.imePadding
import androidx.compose.foundation.layout.isImeVisible
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.layout.widthIn
import androidx.compose.foundation.layout.width
import androidx.compose.foundation.lazy.LazyColumn
import androidx.compose.foundation.lazy.LazyListState
import androidx.compose.foundation.lazy.LazyRow
import androidx.compose.foundation.lazy.items
import androidx.compose.foundation.lazy.rememberLazyListState
import androidx.compose.foundation.shape.CircleShape
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.material3.AssistChip
import androidx.compose.material3.AssistChipDefaults
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.ExtendedFloatingActionButton
import androidx.compose.material3.FilledIconButton
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Surface
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.LaunchedEffect
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableIntStateOf
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.runtime.snapshotFlow
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.draw.clip
import androidx.compose.ui.draw.drawWithContent
import androidx.compose.ui.geometry.Offset
import androidx.compose.ui.geometry.Size
import androidx.compose.ui.graphics.BlendMode
import androidx.compose.ui.graphics.Brush
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.graphics.CompositingStrategy
import androidx.compose.ui.graphics.graphicsLayer
import androidx.compose.ui.res.painterResource
import androidx.compose.ui.semantics.CustomAccessibilityAction
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.customActions
import androidx.compose.ui.semantics.hideFromAccessibility
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.onClick
import androidx.compose.ui.semantics.clearAndSetSemantics
import androidx.compose.ui.semantics.collapse
import androidx.compose.ui.semantics.expand
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.semantics.stateDescription
import androidx.compose.ui.platform.testTag
import androidx.compose.foundation.text.KeyboardActions
import androidx.compose.foundation.text.KeyboardOptions
import androidx.compose.ui.input.key.Key
import androidx.compose.ui.input.key.KeyEventType
import androidx.compose.ui.input.key.isShiftPressed
import androidx.compose.ui.input.key.key
import androidx.compose.ui.input.key.onPreviewKeyEvent
import androidx.compose.ui.input.key.type
import androidx.compose.ui.text.input.ImeAction
import androidx.compose.ui.text.input.KeyboardCapitalization
import androidx.compose.ui.text.style.TextOverflow
import androidx.compose.ui.unit.dp
import kotlinx.coroutines.launch
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.playback.label
import org.hapticon.app.ui.EnvelopeThumbnail
import org.hapticon.app.ui.PatternThumbnail
import org.hapticon.app.ui.keepUnitsWithNumbers
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern

/** What the conversation screen can ask for; the route wires each to the view model. */
data class ConversationActions(
    val onBack: () -> Unit = {},
    /**
     * Send the text with the chosen icon or pattern; the composer empties its field only when [onSend]'s second
     * argument is called (the message is stored), so a send that fails keeps what was typed.
     */
    val onSend: (text: String, onStored: () -> Unit) -> Unit = { _, onStored -> onStored() },
    val onSelectIcon: (HapticIcon?) -> Unit = {},
    val onSelectSticker: (Sticker?) -> Unit = {},
    /** Feel a message's icon (a received one also sends a felt receipt). */
    val onFeel: (StoredMessage) -> Unit = {},
    /** Preview an icon from the composer on this phone (a long press). */
    val onPreview: (HapticIcon) -> Unit = {},
    val onRetry: (StoredMessage) -> Unit = {},
    val onEditIcon: () -> Unit = {},
    /** Choose (or, with null, drop) one of the user's patterns for the next message. */
    val onSelectPattern: (HapticPattern?) -> Unit = {},
    /** Preview a pattern from the composer on this phone (a long press). */
    val onPreviewPattern: (HapticPattern) -> Unit = {},
)

/**
 * A conversation, laid out like Google Messages and Signal: own messages on the right in the primary
 * container colour, received ones on the left; the time (and for own messages the state) under each
 * bubble; a separator before each day. The list is anchored at the bottom: it opens at the latest
 * message and follows new ones unless the user scrolled up, when a "new messages" button jumps back.
 * The composer sits below the list in the same column with [imePadding], so neither it nor the keyboard
 * ever covers the last bubble.
 *
 * For TalkBack each message is one stop that says who wrote it, its words, its icon, the time and (own messages)
 * its state; double-tap feels the icon or, for a message not sent, sends it again. A message arriving while the
 * conversation is open is announced politely ([ArrivalAnnouncer]). A line under the top bar says when messages
 * cannot move now ([ConversationUiState.Success.connection]) or when the peer has never connected to the broker.
 */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun ConversationScreen(
    uiState: ConversationUiState,
    actions: ConversationActions,
    clock: ChatClock = remember { ChatClock() },
    nowMillis: Long = System.currentTimeMillis(),
    /** The keyboard's Enter sends (the user's "Enter key sends" setting); otherwise it starts a new line. */
    enterSends: Boolean = false,
    /** Text shared from another app: it goes into the message field once, then [onSharedTextUsed]. */
    sharedText: String? = null,
    onSharedTextUsed: () -> Unit = {},
) {
    val title = (uiState as? ConversationUiState.Success)?.peer ?: ""
    Scaffold(
        topBar = {
            TopAppBar(
                title = {
                    Row(verticalAlignment = Alignment.CenterVertically) {
                        if (title.isNotEmpty()) Avatar(title, Modifier.size(36.dp))
                        Text(title, Modifier.padding(start = 12.dp))
                    }
                },
                navigationIcon = { IconButton(onClick = actions.onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back to chats") } },
            )
        },
    ) { padding ->
        when (uiState) {
            ConversationUiState.Loading -> Box(Modifier.fillMaxSize().padding(padding), Alignment.Center) { CircularProgressIndicator() }
            is ConversationUiState.Success -> Column(Modifier.fillMaxSize().padding(padding).imePadding()) {
                // Nothing moving at all matters more than whether this peer ever connected.
                val connectionLine = uiState.connection.line()
                when {
                    connectionLine != null -> ConnectionLine(connectionLine)
                    uiState.peerNeverConnected -> ConnectionLine(neverConnectedLine(uiState.peer), HapticonIcons.Info)
                }
                ArrivalAnnouncer(uiState.messages, clock)
                MessageList(uiState, actions, clock, nowMillis, Modifier.weight(1f).fillMaxWidth())
                Composer(uiState, actions, enterSends, sharedText, onSharedTextUsed)
            }
        }
    }
}

@Composable
private fun MessageList(
    uiState: ConversationUiState.Success,
    actions: ConversationActions,
    clock: ChatClock,
    nowMillis: Long,
    modifier: Modifier,
) {
    val items = remember(uiState.messages, nowMillis / 60_000) { conversationItems(uiState.messages, clock, nowMillis) }
    // Reversed: index 0 is the newest message at the bottom, so the list opens there.
    val listState = rememberLazyListState()
    var following by remember { mutableStateOf(true) }
    var unseen by remember { mutableIntStateOf(0) }
    val scope = androidx.compose.runtime.rememberCoroutineScope()
    // Only the user's own scrolling decides whether to follow: an insertion must not change it.
    LaunchedEffect(listState) {
        snapshotFlow { listState.isScrollInProgress }.collect { scrolling ->
            if (!scrolling) {
                following = listState.firstVisibleItemIndex == 0
                if (following) unseen = 0
            }
        }
    }
    val newest = uiState.messages.lastOrNull()
    LaunchedEffect(newest?.id) {
        if (newest == null) return@LaunchedEffect
        if (following || newest.outgoing) {
            listState.scrollToItem(0)
            following = true
            unseen = 0
        } else {
            unseen++
        }
    }
    Box(modifier) {
        LazyColumn(
            state = listState,
            reverseLayout = true,
            modifier = Modifier.fillMaxSize().testTag(MESSAGE_LIST_TAG),
            contentPadding = PaddingValues(horizontal = 12.dp, vertical = 8.dp),
            // Bottom: a short conversation sits on the composer, as in Messages (spacedBy alone would align it to the top).
            verticalArrangement = Arrangement.spacedBy(6.dp, Alignment.Bottom),
        ) {
            items(items, key = { it.key }) { item ->
                when (item) {
                    is ConversationItem.DaySeparator -> DaySeparator(item.label)
                    is ConversationItem.Bubble -> MessageBubble(item.message, item.time, actions)
                }
            }
        }
        if (!following) {
            ExtendedFloatingActionButton(
                onClick = {
                    scope.launch {
                        listState.animateScrollToItem(0)
                        following = true
                        unseen = 0
                    }
                },
                icon = { Icon(HapticonIcons.ArrowDownward, contentDescription = null) },
                text = { Text(if (unseen > 0) "$unseen new message${if (unseen == 1) "" else "s"}" else "Latest") },
                modifier = Modifier.align(Alignment.BottomCenter).padding(bottom = 12.dp)
                    .semantics { contentDescription = if (unseen > 0) "$unseen new messages, jump to the latest" else "Jump to the latest message" },
            )
        }
    }
}

/** The composer's icon row's test tag; its patterns are keyed `pattern:NAME`. */
const val COMPOSER_ICONS_TAG: String = "composer-icons"

/** The message list's test tag. */
const val MESSAGE_LIST_TAG: String = "messages"

@Composable
private fun DaySeparator(label: String) {
    Box(Modifier.fillMaxWidth().padding(vertical = 6.dp), contentAlignment = Alignment.Center) {
        Surface(shape = CircleShape, color = MaterialTheme.colorScheme.surfaceContainerHigh) {
            Text(
                label, style = MaterialTheme.typography.labelMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
                modifier = Modifier.padding(horizontal = 12.dp, vertical = 4.dp),
            )
        }
    }
}

/** Hides a drawn part of a bubble from accessibility services: the bubble says it whole ([spokenBubble]). */
private val HiddenFromTalkBack: Modifier = Modifier.semantics { hideFromAccessibility() }

/**
 * One message: the bubble, and under it the time and, for an own message, its state. To TalkBack the whole is one
 * stop ([spokenBubble]) with at most two actions: a tap feels the icon or pattern or, for a message not sent, sends
 * it again (then "Feel …" is a custom action). Its drawn parts are hidden from accessibility services, so nothing is
 * said twice, but they stay in the semantics tree for the contrast and touch-target checks.
 *
 * For a finger the same actions are where they are drawn: the bubble and its "Feel …" chip feel, and a message not
 * sent is resent by a tap on the bubble or on the red "Not sent, tap to retry" line, itself a 48 dp target.
 */
@Composable
private fun MessageBubble(message: StoredMessage, time: String, actions: ConversationActions) {
    val own = message.outgoing
    val colors = MaterialTheme.colorScheme
    val container = if (own) colors.primaryContainer else colors.surfaceContainerHighest
    val content = if (own) colors.onPrimaryContainer else colors.onSurface
    // The corner nearest the sender's side is tighter, as in Messages.
    val shape = if (own) RoundedCornerShape(20.dp, 20.dp, 4.dp, 20.dp) else RoundedCornerShape(20.dp, 20.dp, 20.dp, 4.dp)
    val failed = own && message.state == MessageState.FAILED
    val feelLabel = feelLabelOf(message)
    val feel = { actions.onFeel(message) }
    val retry = { actions.onRetry(message) }
    val tap: (() -> Unit)? = when {
        failed -> retry
        feelLabel != null -> feel
        else -> null
    }
    Box(Modifier.fillMaxWidth(), contentAlignment = if (own) Alignment.CenterEnd else Alignment.CenterStart) {
        Column(
            Modifier.widthIn(min = 48.dp).semantics(mergeDescendants = true) {
                contentDescription = spokenBubble(message, time)
                if (tap != null) onClick(label = if (failed) "Retry sending" else feelLabel) { tap(); true }
                if (failed && feelLabel != null) customActions = listOf(CustomAccessibilityAction(feelLabel) { feel(); true })
            },
            horizontalAlignment = if (own) Alignment.End else Alignment.Start,
        ) {
            Surface(
                shape = shape, color = container, contentColor = content,
                modifier = Modifier.widthIn(max = 300.dp)
                    .then(if (tap != null) Modifier.clickable(onClick = tap).then(HiddenFromTalkBack) else Modifier),
            ) {
                Column(Modifier.padding(horizontal = 14.dp, vertical = 10.dp)) {
                    Sticker.of(message.sticker)?.let {
                        Image(painterResource(it.drawable), contentDescription = "Sticker: ${it.label}", modifier = HiddenFromTalkBack.size(72.dp))
                    } ?: message.sticker?.let { Text("[$it]", HiddenFromTalkBack) }
                    if (message.text.isNotEmpty()) Text(message.text, HiddenFromTalkBack, style = MaterialTheme.typography.bodyLarge)
                    message.icon?.let { icon ->
                        FeelChip("Feel ${icon.name}", onClick = feel, labelColor = content) {
                            EnvelopeThumbnail(icon, Modifier.clearAndSetSemantics {}.width(32.dp).height(16.dp))
                        }
                    }
                    message.pattern?.let { pattern ->
                        FeelChip("Feel ${pattern.name}", onClick = feel, labelColor = content) {
                            PatternThumbnail(pattern, Modifier.clearAndSetSemantics {}.width(32.dp).height(16.dp), showFrequency = false)
                        }
                    }
                }
            }
            Row(
                Modifier
                    .then(
                        if (failed) {
                            // Compose widens a pointer target to 48 dp (ViewConfiguration.minimumTouchTargetSize) where there is
                            // room, so the line keeps its drawn height under its bubble and is still a 48 dp target.
                            Modifier.clip(RoundedCornerShape(8.dp)).clickable(onClick = retry).then(HiddenFromTalkBack)
                        } else {
                            Modifier
                        },
                    )
                    .padding(horizontal = 6.dp, vertical = 2.dp),
                verticalAlignment = Alignment.CenterVertically,
                horizontalArrangement = Arrangement.spacedBy(4.dp),
            ) {
                Text(time, HiddenFromTalkBack, style = MaterialTheme.typography.labelSmall, color = colors.onSurfaceVariant)
                if (own) StateMark(message.state)
            }
        }
    }
}

/** "Feel hug" for a message with the hug, "Feel ramp" for one with that pattern; null for one without either. */
private fun feelLabelOf(message: StoredMessage): String? = (message.icon?.name ?: message.pattern?.name)?.let { "Feel $it" }

/**
 * What TalkBack says for a message: who wrote it ("You" for own messages), then what the bubble shows in its order
 * (sticker, text, the "Feel …" chip that names its icon or pattern), the time and, for own messages, the state, e.g.
 * "bob: Try this one, Feel hug, 14:52" or "You: Lovely, 15:12, Read". The drawn words come verbatim, so a
 * voice-control user who says "Feel hug" reaches the bubble (WCAG 2.5.3 Label in Name).
 */
fun spokenBubble(message: StoredMessage, time: String): String {
    val parts = listOfNotNull(
        message.sticker?.let { name -> Sticker.of(name)?.let { "Sticker: ${it.label}" } ?: "[$name]" },
        message.text.takeIf { it.isNotEmpty() },
        feelLabelOf(message),
        time,
        stateLabel(message.state).takeIf { message.outgoing },
    )
    return (if (message.outgoing) "You" else message.sender) + ": " + parts.joinToString(", ")
}

/**
 * The mark of an own message's state, told apart by shape and not by colour alone (WCAG 1.4.1): a clock while
 * sending, one tick once the broker has it, two ticks delivered, two ticks on a filled disc read, the vibration
 * glyph felt, and the red error glyph with its words when not sent. Drawn only: the bubble says the state.
 */
@Composable
private fun StateMark(state: MessageState) {
    val colors = MaterialTheme.colorScheme
    val size = Modifier.testTag(STATE_MARK_TAG).size(16.dp)
    when (state) {
        MessageState.SENDING -> Icon(HapticonIcons.Schedule, null, HiddenFromTalkBack.then(size), tint = colors.onSurfaceVariant)
        MessageState.SENT -> Icon(HapticonIcons.Check, null, HiddenFromTalkBack.then(size), tint = colors.onSurfaceVariant)
        MessageState.DELIVERED -> Icon(HapticonIcons.DoneAll, null, HiddenFromTalkBack.then(size), tint = colors.onSurfaceVariant)
        MessageState.READ -> Box(HiddenFromTalkBack.then(size).background(colors.primary, CircleShape), contentAlignment = Alignment.Center) {
            Icon(HapticonIcons.DoneAll, null, Modifier.size(12.dp), tint = colors.onPrimary)
        }
        MessageState.FELT -> Icon(HapticonIcons.Vibration, null, HiddenFromTalkBack.then(size), tint = colors.primary)
        MessageState.FAILED -> {
            Icon(HapticonIcons.Error, null, HiddenFromTalkBack.then(size), tint = colors.error)
            Text(stateLabel(state), HiddenFromTalkBack, style = MaterialTheme.typography.labelMedium, color = colors.error)
        }
        MessageState.RECEIVED -> Unit
    }
}

/** The test tag of an own message's state mark. */
const val STATE_MARK_TAG: String = "state-mark"

/** The spoken (and for failures, visible) label of an own message's state. */
fun stateLabel(state: MessageState): String = when (state) {
    MessageState.SENDING -> "Sending"
    MessageState.SENT -> "Sent"
    MessageState.DELIVERED -> "Delivered"
    MessageState.READ -> "Read"
    MessageState.FELT -> "Felt"
    MessageState.FAILED -> "Not sent, tap to retry"
    MessageState.RECEIVED -> "Received"
}

/** The test tag of the node that announces arriving messages. */
const val ARRIVAL_ANNOUNCER_TAG: String = "arrival-announcer"

/**
 * Announces a message that arrives while the conversation is open, as TalkBack users expect of a messenger: a polite
 * live region (Android's `View.ACCESSIBILITY_LIVE_REGION_POLITE`: said after what is being said, without taking the
 * focus) whose words change to the new message's ("bob: on my way, Feel knock"). The messages there when the screen
 * opened and the user's own are not announced. The words go after [ANNOUNCEMENT_MILLIS], so the node is no extra
 * stop when the user later swipes through the conversation: an empty node is no stop.
 */
@Composable
private fun ArrivalAnnouncer(messages: List<StoredMessage>, clock: ChatClock) {
    // The newest message when the screen opened; everything after it arrived while open.
    val openedWith = rememberSaveable { mutableStateOf(messages.lastOrNull()?.id) }
    var announcement by remember { mutableStateOf("") }
    val newest = messages.lastOrNull()
    LaunchedEffect(newest?.id) {
        if (newest == null || newest.id == openedWith.value) return@LaunchedEffect
        openedWith.value = newest.id
        if (newest.outgoing) return@LaunchedEffect
        announcement = spokenBubble(newest, clock.timeOfDay(newest.sentAtMillis)).substringBeforeLast(", ")
        kotlinx.coroutines.delay(ANNOUNCEMENT_MILLIS)
        announcement = ""
    }
    Box(
        Modifier.fillMaxWidth().height(1.dp).testTag(ARRIVAL_ANNOUNCER_TAG).semantics {
            liveRegion = LiveRegionMode.Polite
            if (announcement.isNotEmpty()) contentDescription = announcement
        },
    )
}

/** How long an announcement stays in its live region: long enough for TalkBack to read it after what it is saying. */
private const val ANNOUNCEMENT_MILLIS = 15_000L

/**
 * A message's "Feel …" chip, for a finger: TalkBack reaches it as its bubble's action, whose spoken words include
 * [label] ([spokenBubble]). The [thumbnail] is for sight only and must clear its own description.
 */
@Composable
private fun FeelChip(label: String, onClick: () -> Unit, labelColor: Color, thumbnail: @Composable () -> Unit) {
    AssistChip(
        onClick = onClick,
        label = { Text(label) },
        leadingIcon = thumbnail,
        colors = AssistChipDefaults.assistChipColors(labelColor = labelColor),
        modifier = HiddenFromTalkBack,
    )
}

@OptIn(ExperimentalFoundationApi::class, ExperimentalLayoutApi::class)
@Composable
private fun Composer(
    uiState: ConversationUiState.Success,
    actions: ConversationActions,
    enterSends: Boolean,
    sharedText: String? = null,
    onSharedTextUsed: () -> Unit = {},
) {
    var text by rememberSaveable { mutableStateOf("") }
    // Shared text joins what is typed already, and is not sent until the user sends it.
    LaunchedEffect(sharedText) {
        if (sharedText == null) return@LaunchedEffect
        text = if (text.isBlank()) sharedText else "$text $sharedText"
        onSharedTextUsed()
    }
    // The send button and, when the user chose so, the keyboard's Enter: the field keeps the focus (and the
    // keyboard stays up) for the next message, as in Google Messages.
    // The field empties once the message is stored; a send that fails (too long, say) keeps the text under its error.
    // Only what was sent is cleared: words typed meanwhile stay.
    val send = {
        val sent = text
        actions.onSend(sent) { if (text == sent) text = "" }
    }
    Surface(color = MaterialTheme.colorScheme.surfaceContainer) {
        Column(Modifier.fillMaxWidth().padding(horizontal = 8.dp, vertical = 6.dp), verticalArrangement = Arrangement.spacedBy(4.dp)) {
            IconRow(uiState, actions)
            // With the keyboard up the stickers wait (as Signal's sticker panel takes the keyboard's place), and the
            // "how it will feel there" line is its short form: at 360 dp and font 2.0 the latest message keeps its room.
            val keyboardUp = WindowInsets.isImeVisible
            val stickerRow = rememberLazyListState()
            if (!keyboardUp) StickerRow(stickerRow, uiState.selectedSticker, actions.onSelectSticker)
            (uiState.selectedIcon?.name ?: uiState.selectedPattern?.name)?.let { name ->
                PeerFeelLines(name, uiState.peer, uiState.peerFeel, short = keyboardUp)
            }
            uiState.error?.let { Text(it, color = MaterialTheme.colorScheme.error, modifier = Modifier.padding(horizontal = 4.dp)) }
            Row(verticalAlignment = Alignment.CenterVertically) {
                OutlinedTextField(
                    // The field's name is its description, which stays when text is typed; the placeholder is cleared
                    // for TalkBack, else an empty field was "Message, Message" (TalkBackNodeTreeTest).
                    text, { text = it }, placeholder = { Text("Message", Modifier.clearAndSetSemantics {}) }, shape = RoundedCornerShape(24.dp),
                    maxLines = 4,
                    // Sentences start with a capital; the IME's action key is Send or, by default, a new line.
                    keyboardOptions = KeyboardOptions(
                        capitalization = KeyboardCapitalization.Sentences,
                        imeAction = if (enterSends) ImeAction.Send else ImeAction.Default,
                    ),
                    keyboardActions = KeyboardActions(onSend = { send() }),
                    modifier = Modifier.weight(1f).semantics { contentDescription = "Message" }
                        // A hardware keyboard's Enter sends too when chosen; Shift+Enter still starts a new line.
                        .onPreviewKeyEvent { event ->
                            val enter = event.key == Key.Enter || event.key == Key.NumPadEnter
                            if (!enterSends || !enter || event.isShiftPressed) return@onPreviewKeyEvent false
                            if (event.type == KeyEventType.KeyDown) send()
                            true
                        },
                )
                FilledIconButton(
                    onClick = send,
                    modifier = Modifier.padding(start = 8.dp).size(48.dp),
                ) { Icon(HapticonIcons.Send, contentDescription = "Send") }
            }
        }
    }
}

/** The composer's icons, then the user's patterns, then "New icon…": one scrolling row of chips. */
@Composable
private fun IconRow(uiState: ConversationUiState.Success, actions: ConversationActions) {
    val iconRow = rememberLazyListState()
    LazyRow(
        state = iconRow,
        horizontalArrangement = Arrangement.spacedBy(6.dp),
        verticalAlignment = Alignment.CenterVertically,
        contentPadding = PaddingValues(horizontal = 4.dp),
        modifier = Modifier.fillMaxWidth().fadingEdges(iconRow).testTag(COMPOSER_ICONS_TAG),
    ) {
        items(uiState.icons, key = { it.name }) { icon ->
            IconChip(icon, selected = uiState.selectedIcon == icon, actions)
        }
        // The user's patterns after the icons; keyed apart, as a pattern may share an icon's name.
        items(uiState.patterns, key = { "pattern:" + it.name }) { pattern ->
            PatternChip(pattern, selected = uiState.selectedPattern == pattern, actions)
        }
        item { TextButton(onClick = actions.onEditIcon) { Text("New icon…") } }
    }
}

/**
 * The bundled stickers in one scrolling row; pressing the [selected] one again deselects it. [state] is the
 * composer's, so the row keeps its place while the keyboard hides it.
 */
@Composable
private fun StickerRow(state: LazyListState, selected: Sticker?, onSelect: (Sticker?) -> Unit) {
    LazyRow(
        state = state,
        horizontalArrangement = Arrangement.spacedBy(6.dp),
        contentPadding = PaddingValues(horizontal = 4.dp),
        modifier = Modifier.fillMaxWidth().fadingEdges(state),
    ) {
        items(Sticker.entries) { sticker ->
            val isSelected = selected == sticker
            Image(
                painterResource(sticker.drawable),
                contentDescription = "Sticker ${sticker.label}",
                modifier = Modifier.size(40.dp).clip(RoundedCornerShape(8.dp))
                    .then(if (isSelected) Modifier.border(2.dp, MaterialTheme.colorScheme.primary, RoundedCornerShape(8.dp)) else Modifier)
                    .semantics { stateDescription = if (isSelected) "selected" else "not selected" }
                    .clickable { onSelect(if (isSelected) null else sticker) },
            )
        }
    }
}

/** The test tag of the composer's "how it will feel there" control (present when it has details to expand). */
const val PEER_FEEL_TAG: String = "peer-feel"

/**
 * Under the composer, how the chosen icon or pattern [name] will feel on [peer]'s phone: the renderer line, then the
 * pitch and the envelope's control points (one line each). With details, the lines collapse to the short summary that
 * names the renderer first ("Envelope effect on bob's phone"), and a chevron; a tap (or TalkBack's double-tap, "collapsed, button, double-tap to show details")
 * shows them all. At font scale 2.0 the three wrapped lines took half the screen, pushing the messages away. The short
 * summary ([short], with the keyboard up, or collapsed) wraps rather than being cut: cut to one line at 360 dp and font
 * 2.0 it read "Amplitude waveform on bo…", losing whose phone and the fidelity. The whole
 * row is the control, at least 48 dp high; besides the click it offers Compose's expand/collapse semantics actions
 * (`AccessibilityNodeInfo.ACTION_EXPAND` / `ACTION_COLLAPSE` in TalkBack's actions menu).
 */
@Composable
private fun PeerFeelLines(name: String, peer: String, feel: PeerFeel?, short: Boolean = false) {
    val summary = if (feel == null) "How $name will feel there: unknown until $peer connects"
    else "How $name will feel there: ${feel.renderer.label}" + (feel.alternative?.let { " or ${it.label}" } ?: "") +
        (feel.fidelityPercent?.let { ", $it% fidelity" } ?: "")
    val details = listOfNotNull(feel?.pitch, feel?.envelope).map(::keepUnitsWithNumbers)
    // Collapsed, the renderer comes first: cut to one line at font 2.0, "How boing will feel there: am…" lost it.
    val collapsedSummary = feel?.let {
        it.renderer.label.replaceFirstChar(Char::uppercaseChar) + (it.alternative?.let { alt -> " or ${alt.label}" } ?: "") +
            " on $peer's phone" + (it.fidelityPercent?.let { percent -> ", $percent% fidelity" } ?: "")
    } ?: summary
    val style = MaterialTheme.typography.bodySmall
    val color = MaterialTheme.colorScheme.onSurfaceVariant
    if (details.isEmpty()) {
        Text(if (short) collapsedSummary else summary, style = style, color = color, modifier = Modifier.padding(horizontal = 4.dp))
        return
    }
    // Collapsed whenever a new choice brings the lines back (they leave the composition with the choice).
    var expanded by rememberSaveable { mutableStateOf(false) }
    Row(
        Modifier.fillMaxWidth().heightIn(min = 48.dp).clip(RoundedCornerShape(8.dp))
            .clickable(role = Role.Button, onClickLabel = if (expanded) "Hide details" else "Show details") { expanded = !expanded }
            .semantics {
                stateDescription = if (expanded) "expanded" else "collapsed"
                if (expanded) collapse { expanded = false; true } else expand { expanded = true; true }
            }
            .testTag(PEER_FEEL_TAG)
            .padding(horizontal = 4.dp, vertical = 4.dp),
        verticalAlignment = Alignment.CenterVertically,
    ) {
        Column(Modifier.weight(1f), verticalArrangement = Arrangement.spacedBy(4.dp)) {
            Text(if (expanded) summary else collapsedSummary, style = style, color = color)
            if (expanded) details.forEach { Text(it, style = style, color = color) }
        }
        Icon(
            if (expanded) HapticonIcons.ExpandLess else HapticonIcons.ExpandMore, contentDescription = null, tint = color,
            modifier = Modifier.padding(start = 8.dp),
        )
    }
}

/** A composer icon: a tap chooses it for the next message, a long press previews it on this phone. */
@Composable
private fun IconChip(icon: HapticIcon, selected: Boolean, actions: ConversationActions) =
    ComposerChip(
        icon.name, selected,
        onPreview = { actions.onPreview(icon) }, onToggle = { actions.onSelectIcon(if (selected) null else icon) },
    ) { EnvelopeThumbnail(icon, Modifier.clearAndSetSemantics {}.width(36.dp).height(18.dp)) }

/**
 * A composer pattern, after the icons: the same chip, told apart by its thumbnail's frequency line and a
 * "pattern" tag. A tap chooses it (the message travels as version 2), a long press previews it here.
 */
@Composable
private fun PatternChip(pattern: HapticPattern, selected: Boolean, actions: ConversationActions) =
    ComposerChip(
        pattern.name, selected,
        onPreview = { actions.onPreviewPattern(pattern) }, onToggle = { actions.onSelectPattern(if (selected) null else pattern) },
        tag = "pattern",
    ) { PatternThumbnail(pattern, Modifier.clearAndSetSemantics {}.width(36.dp).height(18.dp)) }

/**
 * The chip of the composer's icon row: [thumbnail] (for sight only: it must clear its own description), [name] and an
 * optional small [tag]. TalkBack names it by the visible words ("knock"; "ramp, pattern"), then its state and the
 * hints "add to message" and "feel knock here": WCAG 2.5.3 Label in Name (TalkBackNodeTreeTest), so that a
 * voice-control user saying "knock" matches it (a name such as "Icon knock" would not match from the start).
 */
@OptIn(ExperimentalFoundationApi::class)
@Composable
private fun ComposerChip(
    name: String,
    selected: Boolean,
    onPreview: () -> Unit,
    onToggle: () -> Unit,
    tag: String? = null,
    thumbnail: @Composable () -> Unit,
) {
    val colors = MaterialTheme.colorScheme
    Surface(
        shape = RoundedCornerShape(8.dp),
        color = if (selected) colors.secondaryContainer else colors.surfaceContainerLowest,
        contentColor = if (selected) colors.onSecondaryContainer else colors.onSurface,
        modifier = Modifier
            .border(1.dp, if (selected) colors.secondaryContainer else colors.outlineVariant, RoundedCornerShape(8.dp))
            .clip(RoundedCornerShape(8.dp))
            // A button to TalkBack ("knock, not selected, button, double-tap to add to message"): without the role it
            // announced no control type at all.
            .combinedClickable(
                role = Role.Button,
                onClickLabel = if (selected) "Remove from message" else "Add to message",
                onLongClickLabel = "Feel $name here",
                onLongClick = onPreview,
                onClick = onToggle,
            )
            .semantics {
                stateDescription = if (selected) "selected" else "not selected"
            },
    ) {
        Row(
            Modifier.padding(horizontal = 10.dp, vertical = 6.dp),
            verticalAlignment = Alignment.CenterVertically,
        ) {
            thumbnail()
            Text(name, style = MaterialTheme.typography.labelLarge, modifier = Modifier.padding(start = 6.dp))
            tag?.let { Text(it, style = MaterialTheme.typography.labelSmall, color = colors.onSurfaceVariant, modifier = Modifier.padding(start = 4.dp)) }
        }
    }
}

/**
 * Fades the row's edge where more content lies beyond it, the cue Material uses for a horizontally
 * scrolling row (a cut chip alone reads as a layout bug).
 */
fun Modifier.fadingEdges(state: LazyListState, width: androidx.compose.ui.unit.Dp = 32.dp): Modifier =
    graphicsLayer { compositingStrategy = CompositingStrategy.Offscreen }.drawWithContent {
        drawContent()
        val w = width.toPx().coerceAtMost(size.width / 2)
        if (state.canScrollForward) {
            drawRect(
                Brush.horizontalGradient(listOf(Color.Black, Color.Transparent), startX = size.width - w, endX = size.width),
                topLeft = Offset(size.width - w, 0f), size = Size(w, size.height), blendMode = BlendMode.DstIn,
            )
        }
        if (state.canScrollBackward) {
            drawRect(
                Brush.horizontalGradient(listOf(Color.Transparent, Color.Black), startX = 0f, endX = w),
                size = Size(w, size.height), blendMode = BlendMode.DstIn,
            )
        }
    }
