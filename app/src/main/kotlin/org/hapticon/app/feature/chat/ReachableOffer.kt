package org.hapticon.app.feature.chat

import android.Manifest
import android.content.pm.PackageManager
import android.os.Build
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.selection.toggleable
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedCard
import androidx.compose.material3.Surface
import androidx.compose.material3.Switch
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.rememberUpdatedState
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.heading
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import androidx.core.content.ContextCompat
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.sync.KeepAlive
import org.hapticon.app.sync.ReachableService

/**
 * What the chat list says, above the chats, about reaching this user while the app is closed, and what its
 * button does. Android ends the process of an app swiped out of Recents that runs no foreground service
 * (ActivityManagerService `killProcessesForRemovedTask`), so without "Stay reachable" nothing of Hapticon
 * runs then: its messages wait on the broker and their senders see one tick ("sent") until it opens again.
 */
enum class ReachableNote(val text: String, val action: String) {
    /** "Stay reachable" is off. */
    OFF(
        "While Hapticon is closed, messages wait on the server and their senders see one tick.",
        "Stay reachable",
    ),

    /**
     * On, but Android optimises Hapticon's battery use: while the phone sleeps the keep-alive may wait up to
     * 9 minutes ([KeepAlive.Mode.INEXACT]), and messages with it.
     */
    BATTERY_OPTIMISED(
        "Android may hold messages back for minutes while the phone sleeps.",
        "Allow in background",
    ),
}

/** The chat list's note for [stayReachable] and whether Android exempts the app from battery optimisation. */
fun reachableNote(stayReachable: Boolean, batteryExempt: Boolean): ReachableNote? = when {
    !stayReachable -> ReachableNote.OFF
    !batteryExempt -> ReachableNote.BATTERY_OPTIMISED
    else -> null
}

/**
 * The note under the chat list's top bar, as a Material banner: the text across the width, its button below at
 * the end (side by side, a large font squeezed the text into a column a word wide).
 */
@Composable
fun ReachableNoteRow(note: ReachableNote, onAction: (ReachableNote) -> Unit, modifier: Modifier = Modifier) {
    Surface(color = MaterialTheme.colorScheme.secondaryContainer, modifier = modifier.fillMaxWidth()) {
        Column(Modifier.padding(start = 16.dp, end = 8.dp, top = 8.dp)) {
            Text(
                note.text, Modifier.padding(end = 8.dp), style = MaterialTheme.typography.bodyMedium,
                color = MaterialTheme.colorScheme.onSecondaryContainer,
            )
            TextButton(onClick = { onAction(note) }, modifier = Modifier.align(Alignment.End)) { Text(note.action) }
        }
    }
}

/**
 * First launch, right after the account was saved: offers "Stay reachable" and autoplay plainly, with what each
 * costs, before the chat list, as Signal does on a phone without Google's push service (it explains its
 * background connection and asks for the battery exemption up front). Both start switched on, shown and
 * explained, and [onContinue] takes what the user left on; "Not now" turns both off. Android's own requests
 * (notifications, the battery exemption) follow in the route ([rememberReachableRequests]).
 */
@Composable
fun ReachableOfferScreen(user: String, onContinue: (stayReachable: Boolean, autoPlay: Boolean) -> Unit) {
    var stayReachable by rememberSaveable { mutableStateOf(true) }
    var autoPlay by rememberSaveable { mutableStateOf(true) }
    Column(
        Modifier.fillMaxSize().verticalScroll(rememberScrollState()).padding(24.dp),
        verticalArrangement = Arrangement.spacedBy(16.dp),
    ) {
        Icon(HapticonIcons.Vibration, contentDescription = null, tint = MaterialTheme.colorScheme.primary, modifier = Modifier.size(48.dp))
        Text("Feel messages in your pocket", style = MaterialTheme.typography.headlineMedium, modifier = Modifier.semantics { heading() })
        Text(
            "You are $user. Android stops apps you are not using, so by itself Hapticon receives only while it is open.",
            style = MaterialTheme.typography.bodyLarge,
        )
        OfferChoice(
            title = "Stay reachable",
            body = "Keeps one connection to your study's server open while Hapticon is closed, also after the phone restarts. " +
                "Android shows a permanent notification, \u201cReachable for haptic messages\u201d, while it runs. " +
                "It costs some battery: the phone wakes for a moment about once a minute to keep the connection. " +
                "Next, Android asks to let Hapticon run in the background.",
            checked = stayReachable, onChange = { stayReachable = it },
        )
        OfferChoice(
            title = "Play icons when messages arrive",
            body = "A message's haptic icon plays as it arrives, so you feel it without looking. Not in Do Not Disturb.",
            checked = autoPlay, onChange = { autoPlay = it },
        )
        Text(
            "You can change both at any time in Chats, Settings.",
            style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
        )
        Button(onClick = { onContinue(stayReachable, autoPlay) }, modifier = Modifier.fillMaxWidth()) { Text("Continue") }
        TextButton(onClick = { onContinue(false, false) }, modifier = Modifier.fillMaxWidth()) { Text("Not now") }
    }
}

/** One offered setting: its name and switch on one line (one toggle for TalkBack), what it does below. */
@Composable
private fun OfferChoice(title: String, body: String, checked: Boolean, onChange: (Boolean) -> Unit) {
    OutlinedCard(Modifier.fillMaxWidth()) {
        Column(Modifier.padding(16.dp), verticalArrangement = Arrangement.spacedBy(8.dp)) {
            Row(
                Modifier.fillMaxWidth().toggleable(checked, role = Role.Switch, onValueChange = onChange),
                verticalAlignment = Alignment.CenterVertically,
            ) {
                Text(title, Modifier.weight(1f), style = MaterialTheme.typography.titleMedium)
                Switch(checked, onCheckedChange = null)
            }
            Text(body, style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant)
        }
    }
}

/** Android's side of "Stay reachable" and arriving messages, asked in one order wherever the user turns them on. */
class ReachableRequests internal constructor(
    /**
     * Starts the service when [stayReachable], then asks for notifications (Android 13+, when not yet allowed) and,
     * when [stayReachable], for the battery exemption ([KeepAlive.exemptionRequests], when not yet exempt).
     */
    val afterChoice: (stayReachable: Boolean) -> Unit,
    /** Asks only for the battery exemption (the chat list's note). */
    val askBatteryExemption: () -> Unit,
)

/**
 * [ReachableRequests] for a screen; [onAnswered] runs when Android's dialogs are done (the battery exemption's
 * answer comes back only as the app's state, so the screen asks [KeepAlive.isBatteryExempt] again).
 */
@Composable
fun rememberReachableRequests(onAnswered: () -> Unit = {}): ReachableRequests {
    val context = LocalContext.current
    val answered by rememberUpdatedState(onAnswered)
    val battery = rememberLauncherForActivityResult(ActivityResultContracts.StartActivityForResult()) { answered() }
    val askBattery = {
        val opened = !KeepAlive.isBatteryExempt(context) && KeepAlive.exemptionRequests(context).any { request ->
            try {
                battery.launch(request)
                true
            } catch (e: android.content.ActivityNotFoundException) {
                false
            }
        }
        if (!opened) answered()
    }
    var batteryNext by rememberSaveable { mutableStateOf(false) }
    val notifications = rememberLauncherForActivityResult(ActivityResultContracts.RequestPermission()) {
        if (batteryNext) askBattery() else answered()
    }
    return remember(context) {
        ReachableRequests(
            afterChoice = { stayReachable ->
                if (stayReachable) {
                    runCatching { ReachableService.start(context) }
                        .onFailure { android.util.Log.w("ReachableRequests", "cannot start Stay reachable: ${it.message}") }
                }
                batteryNext = stayReachable
                val ask = Build.VERSION.SDK_INT >= 33 &&
                    ContextCompat.checkSelfPermission(context, Manifest.permission.POST_NOTIFICATIONS) != PackageManager.PERMISSION_GRANTED
                when {
                    ask -> notifications.launch(Manifest.permission.POST_NOTIFICATIONS)
                    stayReachable -> askBattery()
                    else -> answered()
                }
            },
            askBatteryExemption = askBattery,
        )
    }
}
