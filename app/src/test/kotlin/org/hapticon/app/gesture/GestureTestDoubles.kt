package org.hapticon.app.gesture

import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestDispatcher
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.setMain
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.PendingReceipt
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.gesture.Recording
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Receipt
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.junit.rules.TestWatcher
import org.junit.runner.Description
import java.io.File

/** A source the test drives: [play] pushes a recording's frames, one by one, on the calling thread. */
class TestGestureSource(override val channels: List<GestureChannel>, override val sampleRate: Double) : GestureSource {
    private var sink: GestureSink? = null
    override val label: String get() = "Test source"
    override val running: Boolean get() = sink != null

    override fun start(sink: GestureSink) {
        check(this.sink == null) { "already running" }
        this.sink = sink
    }

    override fun stop() {
        sink = null
    }

    /** Pushes every frame of [recording] (its channels in order) while running. */
    fun play(recording: Recording) {
        val frame = DoubleArray(recording.channels.size)
        for (i in 0 until recording.frameCount) {
            val target = sink ?: return
            for (c in frame.indices) frame[c] = recording.channels[c][i]
            target.onFrame(frame)
        }
    }

    companion object {
        fun of(recording: Recording) = TestGestureSource(recording.channels.map { GestureChannel(it.name, it.unit, it.fullScale) }, recording.sampleRate)
    }
}

/** A gesture component whose sensor board is [board], storing its files under [dir]. */
fun testGestureComponent(board: GestureSource, dir: File) = GestureComponent(
    touch = TouchGestureSource(autoTick = false),
    accelerometer = null,
    sensorBoard = board,
    recordings = FileRecordingStore(File(dir, "recordings")),
    models = FileGestureModelStore(File(dir, "gesture-model.json")),
    socialTouch = FileSocialTouchModelStore(File(dir, "social-touch-model.json")),
)

/** A chat repository with one conversation per [peers] that records what is sent; receiving is not part of these tests. */
class SendRecordingChatRepository(private val peers: List<String>) : ChatRepository {
    val sent = ArrayList<StoredMessage>()

    override fun conversations(): Flow<List<ConversationSummary>> = flowOf(peers.map { ConversationSummary(it, null, null, 0) })
    override fun messages(peer: String): Flow<List<StoredMessage>> = flowOf(sent.filter { it.conversation == peer })
    override suspend fun startConversation(peer: String) = Unit

    override suspend fun send(sender: String, peer: String, text: String, sticker: String?, icon: HapticIcon?, pattern: HapticPattern?): StoredMessage =
        StoredMessage("m${sent.size}", peer, sender, sent.size.toLong(), text, sticker, icon, true, MessageState.SENDING, null).also { sent += it }

    override suspend fun receive(message: ChatMessage): Boolean = error("not used by the gesture tests")
    override suspend fun applyReceipt(receipt: Receipt) = error("not used by the gesture tests")
    override suspend fun markRead(peer: String, nowMillis: Long): List<StoredMessage> = emptyList()
    override suspend fun queueReceipt(peer: String, receipt: Receipt) = error("not used by the gesture tests")
    override suspend fun pendingReceipts(): List<PendingReceipt> = emptyList()
    override suspend fun receiptSent(receipt: Receipt) = error("not used by the gesture tests")
    override suspend fun message(id: String): StoredMessage? = sent.firstOrNull { it.id == id }
    override suspend fun allMessages(): List<StoredMessage> = sent.toList()
    override suspend fun retryNow(messageId: String) = error("not used by the gesture tests")
    override suspend fun deleteConversation(peer: String) = error("not used by the gesture tests")
}

/** Makes [dispatcher] the Main dispatcher (where viewModelScope runs) for each test, and undoes it after. */
@OptIn(ExperimentalCoroutinesApi::class)
class MainDispatcherRule(val dispatcher: TestDispatcher = StandardTestDispatcher()) : TestWatcher() {
    override fun starting(description: Description) = Dispatchers.setMain(dispatcher)
    override fun finished(description: Description) = Dispatchers.resetMain()
}

/** A source with the synthetic people's channels and rate (test-fixtures), which the recognition tests play takes through. */
fun syntheticSource() = TestGestureSource(SyntheticGestures.CHANNELS.map { GestureChannel(it) }, SyntheticGestures.SAMPLE_RATE)
