package org.hapticon.app.feature.chat

import android.content.Context
import org.hapticon.app.playback.usageVibrator
import android.os.Vibrator
import androidx.compose.runtime.collectAsState
import androidx.compose.runtime.getValue
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.junit4.ComposeContentTestRule
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.messaging.Capabilities
import org.robolectric.Shadows.shadowOf

/**
 * Alice's conversation with bob, wired as the app wires it for the composer tests ([ComposerSendTest],
 * [ComposerPatternSendTest], [TalkBackSendTest]): an in-memory Room database, the offline-first repository on a
 * fixed clock, the real player on Robolectric's vibrator (amplitude control, API 35), the [ConversationViewModel]
 * and the [ConversationScreen] with every composer action bound to it. Each test says only what differs: how the
 * outbox is woken, where felt receipts go, which patterns the user has.
 *
 * [allowMainThreadQueries] keeps each test's database as it was: the tests that read Room from the test thread
 * allow it, the one with a running sync does not.
 */
class ComposerFixture(
    private val compose: ComposeContentTestRule,
    val now: Long = 1_767_225_600_000L,
    allowMainThreadQueries: Boolean = true,
) {
    val context: Context = ApplicationProvider.getApplicationContext()
    val vibrator: Vibrator = context.getSystemService(Vibrator::class.java)
    val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    val db: HapticonDatabase = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java)
        .apply { if (allowMainThreadQueries) allowMainThreadQueries() }.build()
    val repository = OfflineFirstChatRepository(db, clock = { now })

    init {
        shadowOf(vibrator).setHasAmplitudeControl(true)
    }

    /** The app's player on this phone's vibrator. */
    fun player(): HapticPlayer = AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null })

    /**
     * Shows the conversation with bob, the ViewModel taking [onSent] (wakes the outbox), [onFelt] (the felt
     * receipt) and the user's [patterns], and waits until the composer's text field is there.
     */
    fun show(
        onSent: () -> Unit = {},
        onFelt: (peer: String, messageId: String) -> Unit = { _, _ -> },
        patterns: Flow<List<HapticPattern>> = flowOf(emptyList()),
        player: HapticPlayer = player(),
    ) {
        val viewModel = ConversationViewModel(
            "bob", { "alice" }, repository, RoomIconRepository(db.iconDao()), player,
            MutableStateFlow<Map<String, Capabilities>>(emptyMap()), onSent,
            onFelt = onFelt, patterns = patterns,
        )
        compose.setContent {
            val state by viewModel.uiState.collectAsState()
            ConversationScreen(
                state,
                ConversationActions(
                    onSend = viewModel::send, onSelectIcon = viewModel::selectIcon, onSelectSticker = viewModel::selectSticker,
                    onPreview = viewModel::play, onFeel = viewModel::feel,
                    onSelectPattern = viewModel::selectPattern, onPreviewPattern = viewModel::play,
                ),
            )
        }
        compose.waitUntil(5_000) { compose.onAllNodes(hasSetTextAction()).fetchSemanticsNodes().isNotEmpty() }
    }

    /** The messages of the conversation with bob, as Room has them now. */
    fun stored(): List<StoredMessage> = runBlocking { repository.messages("bob").first() }

    /** Closes the database (call it from the test's `@After`). */
    fun close() = db.close()
}
