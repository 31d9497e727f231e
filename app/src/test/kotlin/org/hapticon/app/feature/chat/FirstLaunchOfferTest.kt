package org.hapticon.app.feature.chat

import android.Manifest
import android.app.Application
import android.content.pm.PackageManager
import android.os.PowerManager
import android.os.Vibrator
import android.provider.Settings
import androidx.activity.ComponentActivity
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.compose.ui.test.performTextInput
import androidx.room.Room
import kotlinx.coroutines.CompletableDeferred
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.usageVibrator
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.sync.ChatSync
import org.hapticon.app.sync.ReachableService
import org.hapticon.app.sync.TestMessenger
import org.hapticon.messaging.Clock
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * First launch as a participant goes through it, on the Chats route with its ViewModel: a failed connection test
 * keeps the form and what was typed (nothing was saved, so no chat list flashes by); the test that passes leads
 * to the offer of "Stay reachable" and autoplay, never to the list first; Continue saves both, starts the
 * service and asks Android for notifications, then for the battery exemption, in that order.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE) // real JPEG pixels for the scanned invite
@Config(sdk = [35], qualifiers = "w411dp-h1400dp")
class FirstLaunchOfferTest {
    @get:Rule
    val compose = createAndroidComposeRule<ComponentActivity>()

    private val app get() = compose.activity.application
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val db by lazy { Room.inMemoryDatabaseBuilder(app, HapticonDatabase::class.java).build() }
    private val settings = InMemoryChatSettings()
    private val seen = mutableListOf<ChatPreferences>()
    private val probes = mutableListOf<List<String?>>()
    private var answers = ArrayDeque<CompletableDeferred<String?>>()

    private fun component(): ChatComponent {
        val repository = OfflineFirstChatRepository(db)
        val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
        val player = AdaptiveHapticPlayer(usageVibrator(app.getSystemService(Vibrator::class.java)), { device }, { null })
        val sync = ChatSync(
            repository, repository, settings, { user, _, _ -> TestMessenger(user) }, player, VibrationRateLimiter(Clock.MONOTONIC),
            { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        )
        // Every value the settings take, as the chat list's ViewModel would see it.
        scope.launch(Dispatchers.Unconfined) { settings.preferences.collect { synchronized(seen) { seen += it } } }
        return ChatComponent(
            repository, RoomIconRepository(db.iconDao()), settings, sync, player, { device },
            probe = { user, broker, password ->
                probes += listOf(user, broker.toString(), password)
                answers.removeFirst().await()
            },
        )
    }

    @org.junit.Before
    fun forgetFileProviderRoots() {
        // FileProvider caches each authority's roots in a static map, with the cache directory of the first test that
        // asked; Robolectric gives every test a new one.
        val cache = androidx.core.content.FileProvider::class.java.getDeclaredField("sCache").apply { isAccessible = true }
        synchronized(cache.get(null)!!) { (cache.get(null) as MutableMap<*, *>).clear() }
    }

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    @Test
    fun failedTest_keepsTheForm_passedTest_offersStayReachable_continue_asksAndroidInOrder() {
        val refused = CompletableDeferred<String?>().also { answers.addLast(it) }
        val answered = CompletableDeferred<String?>().also { answers.addLast(it) }
        val chat = component()
        compose.setContent { ChatsRoute(chat, iconEditor = {}) }

        awaitText("Welcome to Hapticon")
        compose.onNodeWithText("Welcome to Hapticon").assertIsDisplayed()
        assertFalse("no shell commands for a participant", compose.onAllNodesText().any { '`' in it })
        compose.onNodeWithContentDescription("Your user name").performTextInput("alice")
        compose.onNodeWithContentDescription("Server address").performTextInput("192.168.1.20")
        compose.onNodeWithContentDescription("Password").performTextInput("alice-secret")
        compose.onNodeWithText("Test connection and start").performScrollTo().performClick()
        compose.onNodeWithText("Connecting to tcp://192.168.1.20:1883…").assertIsDisplayed()
        refused.complete("No answer from tcp://192.168.1.20:1883 within 5 s.")
        compose.waitForIdle()

        compose.onNodeWithText("No answer from tcp://192.168.1.20:1883 within 5 s.").assertIsDisplayed()
        // Tried again without typing anything: name, address and password all survived the failure.
        compose.onNodeWithText("Test connection and start").performScrollTo().performClick()
        answered.complete(null)
        compose.waitForIdle()
        assertEquals(List(2) { listOf("alice", "tcp://192.168.1.20:1883", "alice-secret") }, probes)

        awaitText("Feel messages in your pocket")
        // The account appeared once, already with the offer pending: no empty chat list in between.
        val withAccount = synchronized(seen) { seen.firstOrNull { it.userName != null } }
        assertEquals(true, withAccount?.reachableOfferPending)

        shadowOf(app as Application).clearStartedServices()
        compose.onNodeWithText("Continue").performScrollTo().performClick()
        compose.waitForIdle()

        val prefs = settings.preferences.value
        assertEquals(listOf(true, true, true, false), listOf(prefs.stayReachable, prefs.reachableAfterBoot, prefs.autoPlay, prefs.reachableOfferPending))
        assertEquals(ReachableService::class.java.name, shadowOf(app as Application).nextStartedService?.component?.className)
        // Android 13+: notifications first.
        val asked = shadowOf(compose.activity).lastRequestedPermission
        assertEquals(listOf(Manifest.permission.POST_NOTIFICATIONS), asked.requestedPermissions.toList())
        shadowOf(app as Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        @Suppress("DEPRECATION")
        compose.activity.onRequestPermissionsResult(asked.requestCode, asked.requestedPermissions, intArrayOf(PackageManager.PERMISSION_GRANTED))
        compose.waitForIdle()
        // Then the battery exemption, for this app.
        val battery = shadowOf(compose.activity).nextStartedActivityForResult.intent
        assertEquals(Settings.ACTION_REQUEST_IGNORE_BATTERY_OPTIMIZATIONS, battery.action)
        assertEquals("package:${app.packageName}", battery.dataString)

        // The list says what battery optimisation costs until Android exempts the app; then nothing more.
        awaitText(ReachableNote.BATTERY_OPTIMISED.text)
        shadowOf(app.getSystemService(PowerManager::class.java)).setIgnoringBatteryOptimizations(app.packageName, true)
        shadowOf(compose.activity).receiveResult(battery, android.app.Activity.RESULT_OK, null)
        compose.waitForIdle()
        compose.onNodeWithText(ReachableNote.BATTERY_OPTIMISED.text).assertDoesNotExist()
        compose.onNodeWithText("No chats yet").assertIsDisplayed()
    }

    @Test
    fun notNow_turnsBothOff_andTheListSaysWhatThatMeans() {
        settings.update { it.copy(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883", reachableOfferPending = true) }
        val chat = component()
        compose.setContent { ChatsRoute(chat, iconEditor = {}) }

        awaitText("Not now")
        compose.onNodeWithText("Not now").performScrollTo().performClick()
        compose.waitForIdle()

        val prefs = settings.preferences.value
        assertEquals(listOf(false, false, false), listOf(prefs.stayReachable, prefs.autoPlay, prefs.reachableOfferPending))
        awaitText(ReachableNote.OFF.text)
        // Its button turns Stay reachable on, as the offer would have.
        shadowOf(app as Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        compose.onNodeWithText(ReachableNote.OFF.action).performClick()
        compose.waitForIdle()
        assertEquals(listOf(true, true), settings.preferences.value.let { listOf(it.stayReachable, it.reachableAfterBoot) })
        assertEquals(Settings.ACTION_REQUEST_IGNORE_BATTERY_OPTIMIZATIONS, shadowOf(compose.activity).nextStartedActivityForResult.intent.action)
        // Still battery-optimised: the note says what that costs.
        awaitText(ReachableNote.BATTERY_OPTIMISED.text)
    }

    /**
     * An invite scanned from inside the app: the camera app (Android's, started for its result) photographs bob's
     * invite on another phone's screen; the photo decodes, the invite fills in the server and adds bob.
     */
    @Test
    fun scanInvite_cameraPhotoOfTheCode_fillsTheServerAndAddsTheInviter() {
        val chat = component()
        compose.setContent { ChatsRoute(chat, iconEditor = {}) }
        awaitText("Scan invite code")
        compose.onNodeWithContentDescription("Your user name").performTextInput("alice")

        compose.onNodeWithText("Scan invite code").performClick()
        val camera = awaitCameraRequest()
        assertEquals(android.provider.MediaStore.ACTION_IMAGE_CAPTURE, camera.action)
        val output = checkNotNull(camera.getParcelableExtra(android.provider.MediaStore.EXTRA_OUTPUT, android.net.Uri::class.java))
        assertEquals("${app.packageName}.exports", output.authority)
        fileProviderRunning()
        // What the camera app writes there: a 12 MP photo with the code in its middle third.
        val link = org.hapticon.messaging.InviteLink("bob", org.hapticon.messaging.BrokerAddress("192.168.1.20", 1883)).toString()
        app.contentResolver.openOutputStream(output)!!.use { photoOf(link).compress(android.graphics.Bitmap.CompressFormat.JPEG, 85, it) }
        shadowOf(compose.activity).receiveResult(camera, android.app.Activity.RESULT_OK, null)
        // Decoding a 12 MP photo takes seconds on a busy machine.
        compose.waitUntil(60_000) { settings.preferences.value.brokerUrl.isNotEmpty() }
        compose.waitForIdle()

        assertEquals("tcp://192.168.1.20:1883", settings.preferences.value.brokerUrl)
        assertEquals(listOf("bob"), runBlocking { chat.repository.conversations().first().map { it.peer } })
        awaitText("bob added to your chats; broker filled in")
        compose.onNodeWithText("OK").performClick()
        // The form shows the filled-in server and keeps the name typed before the scan.
        compose.onNodeWithContentDescription("Server address").assert(hasText("tcp://192.168.1.20:1883"))
        compose.onNodeWithContentDescription("Your user name").assert(hasText("alice"))
    }

    @Test
    fun scanInvite_photoWithoutACode_saysSo() {
        val chat = component()
        compose.setContent { ChatsRoute(chat, iconEditor = {}) }
        awaitText("Scan invite code")
        compose.onNodeWithText("Scan invite code").performClick()
        val camera = awaitCameraRequest()
        val output = checkNotNull(camera.getParcelableExtra(android.provider.MediaStore.EXTRA_OUTPUT, android.net.Uri::class.java))
        fileProviderRunning()
        val blank = android.graphics.Bitmap.createBitmap(800, 600, android.graphics.Bitmap.Config.ARGB_8888).apply { eraseColor(android.graphics.Color.LTGRAY) }
        app.contentResolver.openOutputStream(output)!!.use { blank.compress(android.graphics.Bitmap.CompressFormat.JPEG, 85, it) }
        shadowOf(compose.activity).receiveResult(camera, android.app.Activity.RESULT_OK, null)
        compose.waitUntil(10_000) { compose.onAllNodes(hasText(InviteScan.NOT_FOUND)).fetchSemanticsNodes().isNotEmpty() }
        assertEquals("", settings.preferences.value.brokerUrl)
    }

    /**
     * The manifest's FileProvider, registered as Android runs it for the camera app's write and our read. Without it
     * Robolectric's `ShadowContentResolver.openOutputStream` hands back a stream that drops every byte (its "legacy
     * behavior" for a URI no provider serves), so the photo would never reach the decoder.
     */
    private fun fileProviderRunning() {
        org.robolectric.Robolectric.buildContentProvider(androidx.core.content.FileProvider::class.java).create()
    }

    /** A 4000×3000 photo, light grey with a little noise, holding [text]'s QR code (as the app draws it) in its middle third. */
    private fun photoOf(text: String): android.graphics.Bitmap {
        val matrix = qrMatrix(text)
        val photo = android.graphics.Bitmap.createBitmap(4000, 3000, android.graphics.Bitmap.Config.ARGB_8888)
        val canvas = android.graphics.Canvas(photo)
        canvas.drawColor(android.graphics.Color.rgb(200, 200, 195))
        val module = 1200f / (matrix.width + 8)
        val left = 1400f
        val top = 900f
        val paint = android.graphics.Paint()
        paint.color = android.graphics.Color.WHITE
        canvas.drawRect(left, top, left + 1200f, top + 1200f, paint)
        paint.color = android.graphics.Color.rgb(30, 30, 35)
        for (y in 0 until matrix.height) for (x in 0 until matrix.width) {
            if (matrix[x, y]) canvas.drawRect(left + (x + 4) * module, top + (y + 4) * module, left + (x + 5) * module, top + (y + 5) * module, paint)
        }
        return photo
    }

    /** The camera app's request, once the scanner has made its file (off the main thread) and started it. */
    private fun awaitCameraRequest(): android.content.Intent {
        compose.waitUntil(10_000) { shadowOf(compose.activity).peekNextStartedActivityForResult() != null }
        return shadowOf(compose.activity).nextStartedActivityForResult.intent
    }

    /**
     * Waits until [text] is on screen, laid out (the merged tree holds only placed nodes): the route's state comes
     * from Room, on a thread Compose's idling does not see.
     */
    private fun awaitText(text: String) = compose.waitUntil(10_000) {
        compose.onAllNodes(hasText(text)).fetchSemanticsNodes().isNotEmpty()
    }

    private fun androidx.compose.ui.test.junit4.ComposeContentTestRule.onAllNodesText(): List<String> =
        onAllNodes(androidx.compose.ui.test.SemanticsMatcher.keyIsDefined(androidx.compose.ui.semantics.SemanticsProperties.Text))
            .fetchSemanticsNodes().flatMap { node -> node.config[androidx.compose.ui.semantics.SemanticsProperties.Text].map { it.text } }
}
