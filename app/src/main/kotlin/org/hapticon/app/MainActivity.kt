package org.hapticon.app

import android.content.Intent
import android.hardware.usb.UsbManager
import android.os.Bundle
import androidx.activity.ComponentActivity
import androidx.activity.compose.setContent
import androidx.activity.enableEdgeToEdge
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.app.di.AppContainer
import org.hapticon.app.navigation.HapticonApp
import org.hapticon.app.navigation.TopLevelDestination
import org.hapticon.app.sync.MessageNotifier
import androidx.lifecycle.compose.collectAsStateWithLifecycle

/**
 * The single activity: hosts the Compose UI. It is also what Android opens when a supported USB
 * board is plugged in (`USB_DEVICE_ATTACHED`, filtered by sensor-bridge's `device_filter.xml`): then
 * it shows the Sensors destination. `singleTop`, so a board plugged in while the app is open arrives
 * in [onNewIntent] instead of starting a second activity.
 */
class MainActivity : ComponentActivity() {
    private var destination by mutableStateOf(TopLevelDestination.CHATS)

    override fun onCreate(savedInstanceState: Bundle?) {
        super.onCreate(savedInstanceState)
        enableEdgeToEdge()
        val container = (application as HapticonApplication).container
        destination = savedInstanceState?.getString(KEY_DESTINATION)
            ?.let { name -> TopLevelDestination.entries.firstOrNull { it.name == name } }
            // A study session still running (the app was killed mid-session) reopens in front of the participant.
            // A messenger opens on its chats, as Signal and Google Messages do.
            ?: if (container.study?.settings?.preferences?.value?.activeSessionId != null) TopLevelDestination.STUDY else TopLevelDestination.CHATS
        handleIntent(intent, container)
        // The app opened in front of the user: "Stay reachable", if chosen, runs from now (Android may have stopped it).
        org.hapticon.app.sync.ReachableService.startIfChosen(this)
        setContent {
            val dynamicColor = container.chat?.settings?.preferences?.collectAsStateWithLifecycle()?.value?.dynamicColor ?: false
            HapticonTheme(dynamicColor = dynamicColor) {
                HapticonApp(container, selected = destination, onSelect = { destination = it })
            }
        }
    }

    override fun onNewIntent(intent: Intent) {
        super.onNewIntent(intent)
        setIntent(intent)
        handleIntent(intent, (application as HapticonApplication).container)
    }

    override fun onSaveInstanceState(outState: Bundle) {
        super.onSaveInstanceState(outState)
        outState.putString(KEY_DESTINATION, destination.name)
    }

    private fun handleIntent(intent: Intent?, container: AppContainer) {
        when (intent?.action) {
            UsbManager.ACTION_USB_DEVICE_ATTACHED -> {
                container.usbDevices.refresh()
                destination = TopLevelDestination.SENSORS
            }
            // A pattern file opened with Hapticon (content or file URI): the Icons screen imports it.
            Intent.ACTION_VIEW if intent.data?.scheme in PATTERN_SCHEMES -> {
                container.pendingPatternFile.value = intent.data
                destination = TopLevelDestination.ICONS
            }
            // An invite link: the Chats screen checks and applies it (and says why not, for a bad one).
            Intent.ACTION_VIEW -> intent.dataString?.let { link ->
                container.chat?.pendingInvite?.value = link
                destination = TopLevelDestination.CHATS
            }
            // Text shared from another app: to the conversation picked in the share sheet (a sharing shortcut), else to
            // the chat the user opens next.
            Intent.ACTION_SEND if intent.type == "text/plain" && intent.getStringExtra(Intent.EXTRA_TEXT) != null -> {
                val text = intent.getStringExtra(Intent.EXTRA_TEXT).orEmpty()
                val peer = MessageNotifier.peerOfShortcut(intent.getStringExtra(androidx.core.content.pm.ShortcutManagerCompat.EXTRA_SHORTCUT_ID))
                container.chat?.pendingShare?.value = org.hapticon.app.sync.SharedText(peer, text)
                destination = TopLevelDestination.CHATS
            }
            // A pattern file shared to Hapticon from another app's share sheet.
            Intent.ACTION_SEND -> sharedStream(intent)?.let { uri ->
                container.pendingPatternFile.value = uri
                destination = TopLevelDestination.ICONS
            }
            MessageNotifier.ACTION_OPEN_CHAT -> {
                container.chat?.pendingConversation?.value = intent.getStringExtra(MessageNotifier.EXTRA_PEER)
                destination = TopLevelDestination.CHATS
            }
        }
    }

    private fun sharedStream(intent: Intent): android.net.Uri? =
        if (android.os.Build.VERSION.SDK_INT >= 33) {
            intent.getParcelableExtra(Intent.EXTRA_STREAM, android.net.Uri::class.java)
        } else {
            @Suppress("DEPRECATION")
            intent.getParcelableExtra(Intent.EXTRA_STREAM)
        }

    private companion object {
        const val KEY_DESTINATION = "destination"
        val PATTERN_SCHEMES = setOf("content", "file")
    }
}
