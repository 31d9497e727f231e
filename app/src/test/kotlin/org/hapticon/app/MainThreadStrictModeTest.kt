package org.hapticon.app

import android.Manifest
import android.database.sqlite.SQLiteDatabase
import android.os.Looper
import android.os.StrictMode
import android.os.Vibrator
import android.os.strictmode.CustomViolation
import android.os.strictmode.DiskReadViolation
import android.os.strictmode.DiskWriteViolation
import android.os.strictmode.Violation
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.compose.ui.test.longClick
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performTouchInput
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.app.playback.PROCESSING_KNOCK
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.label
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.sync.BrokerProcess
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import java.io.File
import java.util.concurrent.CopyOnWriteArrayList

/**
 * The debug build's main-thread policy ([mainThreadPolicy]) with a penalty that fails the test. The
 * whole app (its real container: Room on a database file, SharedPreferences settings, the MQTT sync against a
 * real broker, the adaptive player) is driven as a user would: the chat list, a conversation with a received
 * icon, pressing that icon, choosing an icon in the composer (its "how it will feel there" figure) and
 * previewing it. Every StrictMode violation on the main thread is recorded with its stack and fails the test.
 *
 * How violations reach the listener under Robolectric (Android 15's `StrictMode.java`): on a thread with a
 * Looper, `AndroidBlockGuardPolicy.handleViolationWithTimingAttempt` does not call the listener at once; it
 * posts the batch to the front of the looper's queue (to time the violation), so the listener runs only when
 * the main looper next runs its messages. Robolectric's paused main looper runs them at `idle()`, which
 * Compose's `waitForIdle` does; [assertNoViolations] idles before it looks.
 *
 * What reaches StrictMode here: rendering (the players and `RendererChoice.fidelityPercent` call
 * `StrictMode.noteSlowCall`), SQLite on a database file (the framework's `SQLiteConnection.applyBlockGuardPolicy`
 * reports every statement to `BlockGuard`, Robolectric runs that Java code) and SharedPreferences read before
 * loaded (`SharedPreferencesImpl.awaitLoadedLocked`). What cannot: plain file and socket I/O, which on a phone
 * goes through libcore's `BlockGuardOs` and here goes through the JVM's own `java.io`/`java.net` that never
 * call `BlockGuard` (docs/performance.md). [controls] proves the first three are caught, so a green run means
 * something.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35], qualifiers = "w411dp-h891dp")
class MainThreadStrictModeTest {
    @get:Rule
    val rule = createAndroidComposeRule<MainActivity>()

    @get:Rule
    val temp = TemporaryFolder()

    private val violations = CopyOnWriteArrayList<Violation>()

    private fun failOnViolations() = recordMainThreadViolations(violations)

    @After
    fun tearDown() = stopRecordingMainThreadViolations()

    private fun describe(v: Violation) =
        "${v.javaClass.simpleName}: ${v.message}\n" + v.stackTrace.take(25).joinToString("\n") { "    at $it" }

    /** Each step's violations; every step is driven before the test fails, so one run names all of them. */
    private val byStep = LinkedHashMap<String, List<Violation>>()

    /** Delivers what [step] violated (through the main looper) and files it under [step]. */
    private fun endStep(step: String) {
        rule.waitForIdle()
        shadowOf(Looper.getMainLooper()).idle()
        byStep[step] = violations.toList()
        violations.clear()
    }

    /** Runs step [index]; a step that fails outright reports the violations seen so far with it. */
    private fun step(index: Int, action: () -> Unit) {
        try {
            action()
        } catch (e: Throwable) {
            byStep[STEPS[index] + " (failed: $e)"] = violations.toList()
            throw AssertionError("step '${STEPS[index]}' failed; violations so far:\n" + byStep.entries.joinToString("\n") { (s, list) -> "while $s:\n" + list.joinToString("\n") { describe(it) } }, e)
        }
        endStep(STEPS[index])
    }

    private fun assertNoViolations() {
        val found = byStep.filterValues { it.isNotEmpty() }
        assertTrue(
            "StrictMode violations on the main thread:\n" +
                found.entries.joinToString("\n") { (step, list) -> "while $step:\n" + list.joinToString("\n") { describe(it) } },
            found.isEmpty(),
        )
        assertEquals(STEPS, byStep.keys.toList())
    }

    private fun awaitTrue(what: String, condition: suspend () -> Boolean) = runBlocking {
        withTimeoutOrNull(30_000) { while (!condition()) delay(20) } ?: throw AssertionError("timed out waiting for $what")
    }

    @Test
    fun chatListConversationAndIconPresses_doNoDiskNetworkOrRenderingOnTheMainThread() {
        val app = rule.activity.application as HapticonApplication
        val chat = app.container.chat!!
        shadowOf(app).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        val broker = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).also { it.start() }
        val address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
        val bob = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate()))
        try {
            // alice's account through the settings (the sync connects, off the main thread); bob on his own client
            // publishes what his phone can do and sends alice a knock.
            // bob's client speaks plaintext, so alice chooses it too (end to end is the default; this test is about threads).
            chat.settings.update { it.copy(userName = "alice", brokerUrl = address.toString(), brokerPassword = "alice-secret", endToEnd = false) }
            awaitTrue("alice connected") { chat.sync.connection.value == ConnectionState.Connected }
            runBlocking {
                bob.connect(InboxListener { })
                bob.publishCapabilities(Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 35))
                bob.send("alice", ChatMessage.compose("bob", "feel this", null, HapticIcon.KNOCK, Clock.SYSTEM))
            }
            awaitTrue("the knock stored") { chat.repository.messages("bob").first().any { it.text == "feel this" } }
            awaitTrue("bob's capabilities") { chat.sync.peerCapabilities.value["bob"] != null }
            // Computed here, before the policy: the figure the composer must show once it has computed it off main.
            val figure = RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.HIT)
            val vibrator = app.getSystemService(Vibrator::class.java)
            shadowOf(vibrator).setHasAmplitudeControl(true)

            failOnViolations()
            step(0) {
                rule.onNode(hasText("Chats") and hasClickAction()).performClick()
                rule.waitUntil(10_000) { rule.onAllNodesWithText("bob").fetchSemanticsNodes().isNotEmpty() }
            }
            step(1) {
                rule.onNodeWithText("bob").performClick()
                rule.waitUntil(10_000) { rule.onAllNodes(org.hapticon.app.feature.chat.feelChip("knock")).fetchSemanticsNodes().isNotEmpty() }
            }
            step(2) {
                rule.onNode(org.hapticon.app.feature.chat.feelChip("knock")).performClick()
                rule.waitUntil(10_000) { lastVibration(vibrator) != null }
                assertEquals(PROCESSING_KNOCK, lastVibration(vibrator))
            }
            step(3) {
                rule.onNode(org.hapticon.app.feature.chat.composerIconChip("hit")).performClick()
                // Collapsed (bob's phone publishes its frequency profile, so there is a pitch line): renderer first.
                val line = "${RendererKind.AMPLITUDE_WAVEFORM.label.replaceFirstChar(Char::uppercaseChar)} on bob's phone, $figure% fidelity"
                rule.waitUntil(10_000) { rule.onAllNodesWithText(line).fetchSemanticsNodes().isNotEmpty() }
            }
            step(4) {
                rule.onNode(org.hapticon.app.feature.chat.composerIconChip("hit")).performTouchInput { longClick() }
                rule.waitUntil(10_000) { lastVibration(vibrator) != PROCESSING_KNOCK }
            }
            assertNoViolations()
        } finally {
            StrictMode.setThreadPolicy(StrictMode.ThreadPolicy.LAX)
            runBlocking {
                runCatching { bob.disconnect() }
                // No account: the application's sync ends its session before the broker goes.
                chat.settings.update { it.copy(userName = null) }
                withTimeoutOrNull(10_000) { chat.sync.connection.first { it != ConnectionState.Connected } }
            }
            broker.stop()
        }
    }

    private companion object {
        val STEPS = listOf(
            "opening the chat list", "opening the conversation", "pressing the received knock",
            "choosing hit in the composer (its figure)", "previewing hit",
        )
    }

    /**
     * The same policy and listener catch main-thread work Robolectric lets StrictMode see, so the test above can
     * fail: rendering a figure, and a write and a query on a SQLite database file. (A SharedPreferences read is
     * caught only when the file has not finished loading on its own thread, a race, so it is no control.)
     */
    @Test
    fun controls_renderingAndSqliteOnTheMainThread_areCaught() {
        val db = SQLiteDatabase.openOrCreateDatabase(File(temp.root, "control.db"), null)
        db.execSQL("CREATE TABLE t(a INTEGER)")
        failOnViolations()
        fun caught(action: () -> Unit): List<Pair<String, String?>> {
            action()
            shadowOf(Looper.getMainLooper()).idle() // the batch is delivered through the main looper
            return violations.map { it.javaClass.simpleName to (it as? CustomViolation)?.message }.also { violations.clear() }
        }

        val rendering = caught { RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.KNOCK) }
        val write = caught { db.execSQL("INSERT INTO t VALUES (1)") }
        val read = caught { db.rawQuery("SELECT count(*) FROM t", null).use { it.moveToFirst() } }
        StrictMode.setThreadPolicy(StrictMode.ThreadPolicy.LAX)
        db.close()

        assertEquals(listOf("CustomViolation" to "fidelity of knock"), rendering)
        assertTrue("write: $write", write.isNotEmpty() && write.all { it.first == DiskWriteViolation::class.java.simpleName })
        assertTrue("read: $read", read.isNotEmpty() && read.all { it.first == DiskReadViolation::class.java.simpleName })
    }
}

/**
 * Sets the debug build's policy ([mainThreadPolicy]) on the main thread with a listener instead of the log, so
 * every violation on the main thread lands in [into]. A canary slow call proves the listener hears this thread
 * before anything is driven. [stopRecordingMainThreadViolations] undoes it.
 */
fun recordMainThreadViolations(into: MutableList<Violation>) {
    assertTrue(Looper.myLooper() == Looper.getMainLooper()) // the test, Compose and viewModelScope share this thread
    forgetUndeliveredViolations()
    StrictMode.setThreadPolicy(
        mainThreadPolicy().penaltyListener(java.util.concurrent.Executor { it.run() }, StrictMode.OnThreadViolationListener { into += it }).build(),
    )
    StrictMode.noteSlowCall("canary")
    shadowOf(Looper.getMainLooper()).idle()
    assertEquals(listOf("canary"), into.map { it.message })
    into.clear()
}

/** The main thread outlives a test in Robolectric: leaves it without a policy or a pending batch. */
fun stopRecordingMainThreadViolations() {
    StrictMode.setThreadPolicy(StrictMode.ThreadPolicy.LAX)
    forgetUndeliveredViolations()
}

/**
 * StrictMode keeps the violations of the current looper message in a per-thread list (`violationsBeingTimed`)
 * and posts one message to deliver them all; while the list is not empty it posts no other, and at 10 entries
 * it drops every new violation (`tooManyViolationsThisLoop`). Robolectric empties the main looper's queue after
 * each test but the main thread and StrictMode's statics live on, so a batch recorded late in an earlier test
 * (the debug policy is in force from `HapticonApplication.onCreate`) is never delivered and silences every
 * later one: why an earlier attempt "never received a noted slow call". Tests only: a phone's looper runs its
 * messages.
 */
private fun forgetUndeliveredViolations() {
    val field = StrictMode::class.java.getDeclaredField("violationsBeingTimed").apply { isAccessible = true }
    ((field.get(null) as ThreadLocal<*>).get() as MutableList<*>).clear()
}
