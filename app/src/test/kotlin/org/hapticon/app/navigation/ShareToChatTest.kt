package org.hapticon.app.navigation

import android.content.Intent
import android.content.pm.PackageManager
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createEmptyComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.core.content.pm.ShortcutManagerCompat
import androidx.test.core.app.ActivityScenario
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.app.HapticonApplication
import org.hapticon.app.MainActivity
import org.hapticon.app.R
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.messaging.ChatMessage
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.xmlpull.v1.XmlPullParser

/**
 * Text shared from another app reaches a chat, as in Signal and Google Messages: picked in the share sheet as one of
 * the conversation shortcuts (Direct Share, `Intent.EXTRA_SHORTCUT_ID`) it lands in that conversation's message field;
 * shared to the app itself it waits for the chat the user opens. Nothing is sent until the user sends it.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class ShareToChatTest {
    @get:Rule
    val compose = createEmptyComposeRule()

    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val chat = app.container.chat!!

    private fun aliceWithAMessageFromBob() {
        chat.settings.update { it.copy(userName = "alice", brokerUrl = "") }
        runBlocking { chat.repository.receive(ChatMessage.compose("bob", "hello alice", clock = { 1_767_225_600_000L })) }
    }

    private fun share(text: String, shortcutId: String?): Intent =
        Intent(app, MainActivity::class.java).setAction(Intent.ACTION_SEND).setType("text/plain").putExtra(Intent.EXTRA_TEXT, text)
            .apply { shortcutId?.let { putExtra(ShortcutManagerCompat.EXTRA_SHORTCUT_ID, it) } }

    private fun fieldHolds(text: String) = compose.waitUntil(10_000) {
        compose.onAllNodes(hasSetTextAction() and hasText(text)).fetchSemanticsNodes().isNotEmpty()
    }

    @Test
    fun sharingShortcut_declaredForTheConversationShortcutsCategory_andTheActivityTakesText() {
        // The share target Android matches the shortcuts' categories against (res/xml/shortcuts.xml).
        val parser = app.resources.getXml(R.xml.shortcuts)
        var target: String? = null
        val mimeTypes = mutableListOf<String>()
        val categories = mutableListOf<String>()
        val android = "http://schemas.android.com/apk/res/android"
        while (parser.next() != XmlPullParser.END_DOCUMENT) {
            if (parser.eventType != XmlPullParser.START_TAG) continue
            when (parser.name) {
                "share-target" -> target = parser.getAttributeValue(android, "targetClass")
                "data" -> mimeTypes += parser.getAttributeValue(android, "mimeType")
                "category" -> categories += parser.getAttributeValue(android, "name")
            }
        }
        assertEquals(MainActivity::class.java.name, target)
        assertEquals(listOf("text/plain"), mimeTypes)
        assertEquals(listOf(MessageNotifier.SHORTCUT_CATEGORY), categories)

        val handlers = app.packageManager.queryIntentActivities(
            Intent(Intent.ACTION_SEND).setType("text/plain").setPackage(app.packageName), PackageManager.MATCH_DEFAULT_ONLY,
        )
        assertEquals(listOf(MainActivity::class.java.name), handlers.map { it.activityInfo.name })
    }

    @Test
    fun sharedToBobsShortcut_opensBobsChatWithTheTextInItsField() {
        aliceWithAMessageFromBob()
        ActivityScenario.launch<MainActivity>(share("look at this", MessageNotifier.shortcutId("bob"))).use {
            fieldHolds("look at this")
            compose.onNodeWithText("hello alice").assertIsDisplayed()
            runBlocking { assertEquals(listOf("hello alice"), chat.repository.messages("bob").first().map { m -> m.text }) }
        }
    }

    @Test
    fun sharedToTheApp_saysToOpenAChat_andTheOneOpenedGetsTheText() {
        aliceWithAMessageFromBob()
        ActivityScenario.launch<MainActivity>(share("look at this", shortcutId = null)).use {
            compose.waitUntil(10_000) { compose.onAllNodes(hasText("Open a chat", substring = true)).fetchSemanticsNodes().isNotEmpty() }
            compose.onNodeWithText("OK").performClick()
            compose.onNodeWithText("hello alice").performClick() // bob's row's preview
            fieldHolds("look at this")
        }
    }
}
