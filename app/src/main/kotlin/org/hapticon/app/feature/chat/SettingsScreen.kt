package org.hapticon.app.feature.chat

import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.AlertDialog
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.HorizontalDivider
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.material3.TextButton
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.testTag
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.text.style.TextOverflow
import androidx.compose.ui.unit.dp
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ClientCertificateStatus
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.app.playback.label
import org.hapticon.app.ui.DropdownField
import org.hapticon.app.ui.SingleChoice
import org.hapticon.app.ui.SwitchRow
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind

/** What the settings screen can change. */
data class SettingsActions(
    val onBack: () -> Unit = {},
    val update: ((ChatPreferences) -> ChatPreferences) -> Unit = {},
    /** Tests and saves a new broker address; returns why not, null when saved. */
    val onBroker: (String) -> String? = { null },
    /** Tests and saves a new broker password (empty = none); returns why not at once, null when the test started. */
    val onPassword: (String) -> String? = { null },
    /** Saves a new user name; returns why not, null when saved. */
    val onUserName: (String) -> String? = { null },
    /** Turns "Stay reachable" on or off (on may ask for the notification permission first). */
    val onStayReachable: (Boolean) -> Unit = {},
    /** Opens Android's notification settings of this app (after a refusal Android no longer asks). */
    val onAllowNotifications: () -> Unit = {},
    val onExport: () -> Unit = {},
    val onOpenStudy: () -> Unit = {},
    /** Accepts a peer's changed end-to-end key after the user compared safety numbers. */
    val onTrustKey: (peer: String) -> Unit = {},
    /** Opens the system file picker for a client certificate (.p12). */
    val onImportCertificate: () -> Unit = {},
    /** Opens the picked certificate with this password and stores it. */
    val onCertificatePassword: (String) -> Unit = {},
    val onCancelCertificate: () -> Unit = {},
    val onRemoveCertificate: () -> Unit = {},
)

/**
 * Every chat setting in one place, out of the chat list's way: account and broker, how icons play, felt
 * receipts, staying reachable, colours, data export and about.
 */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun SettingsScreen(
    uiState: SettingsUiState,
    actions: SettingsActions,
    version: String = "",
) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("Settings") },
                navigationIcon = { IconButton(onClick = actions.onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back to chats") } },
            )
        },
    ) { padding ->
        Column(
            Modifier.fillMaxSize().padding(padding).verticalScroll(rememberScrollState()).padding(horizontal = 16.dp, vertical = 8.dp),
            verticalArrangement = Arrangement.spacedBy(8.dp),
        ) {
            uiState.notice?.let { Notice(it) }
            AccountSection(uiState, actions)
            HapticIconsSection(uiState, actions)
            ReachableSection(uiState, actions)
            TypingSection(uiState.preferences, actions)
            PrivacySection(uiState, actions)
            AppearanceSection(uiState.preferences, actions)
            DataSection(actions)
            AboutSection(version)
        }
    }
}

/** A one-line notice over the settings (what the last change did, or why not). */
@Composable
private fun Notice(text: String) {
    androidx.compose.material3.Surface(color = MaterialTheme.colorScheme.secondaryContainer, shape = MaterialTheme.shapes.medium) {
        Text(text, style = MaterialTheme.typography.bodyMedium, modifier = Modifier.fillMaxWidth().padding(12.dp))
    }
}

/** Who the user is and how they reach the broker: name, broker, password, client certificate. */
@Composable
private fun AccountSection(uiState: SettingsUiState, actions: SettingsActions) {
    val prefs = uiState.preferences
    Section("Account", first = true)
    EditableField("User name", prefs.userName ?: "", actions.onUserName, "Others start a chat with you by this name.")
    EditableField("Broker", prefs.brokerUrl, actions.onBroker, "Connection: ${uiState.connection}", url = true)
    EditableField(
        "Broker password", if (prefs.brokerPassword == null) "" else "••••••••", actions.onPassword,
        "The password `hapticon broker adduser` set for you.", secret = true,
    )
    ClientCertificateField(uiState.clientCertificate, uiState.certificateImport, actions)
}

/** How received icons play: on arrival, felt receipts, the renderer and notes out of the phone's range. */
@Composable
private fun HapticIconsSection(uiState: SettingsUiState, actions: SettingsActions) {
    val prefs = uiState.preferences
    Section("Haptic icons")
    SwitchRow("Play icons when messages arrive", prefs.autoPlay, onCheckedChange = { on -> actions.update { it.copy(autoPlay = on) } })
    SwitchRow("Tell senders when I felt their icon", prefs.sendFeltReceipts, onCheckedChange = { on -> actions.update { it.copy(sendFeltReceipts = on) } })
    val selected = uiState.renderers.firstOrNull { it.name == prefs.rendererOverride }
    DropdownField(
        label = "Renderer",
        choice = SingleChoice(listOf<RendererKind?>(null) + uiState.renderers, selected) { it?.label ?: "Automatic (best for this phone)" },
        onSelect = { r -> actions.update { it.copy(rendererOverride = r?.name) } },
    )
    DropdownField(
        label = "Notes this phone cannot play",
        choice = SingleChoice(PitchFit.entries, prefs.pitchFit) { it.label },
        onSelect = { fit -> actions.update { it.copy(pitchFit = fit) } },
    )
    Text(
        "On Android 16 phones that report their actuator's frequency range. Senders see which pitch your phone plays.",
        style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
    )
    Text(
        "Masking noise is part of a study protocol; researchers set it in the Study tab.",
        style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
    )
    TextButton(onClick = actions.onOpenStudy) { Text("Open Study") }
}

/** Notifications and "Stay reachable": whether icons reach the user with the app closed. */
@Composable
private fun ReachableSection(uiState: SettingsUiState, actions: SettingsActions) {
    val prefs = uiState.preferences
    Section("Reachable")
    if (!uiState.notificationsAllowed) {
        androidx.compose.material3.Surface(color = MaterialTheme.colorScheme.errorContainer, shape = MaterialTheme.shapes.medium) {
            Column(Modifier.fillMaxWidth().padding(12.dp)) {
                Text(
                    NOTIFICATIONS_OFF, style = MaterialTheme.typography.bodyMedium,
                    color = MaterialTheme.colorScheme.onErrorContainer,
                )
                TextButton(onClick = actions.onAllowNotifications) { Text("Allow notifications") }
            }
        }
    }
    SwitchRow("Stay reachable when the app is closed", prefs.stayReachable, actions.onStayReachable)
    Text(
        "Keeps the broker connection open with an ongoing notification, so icons reach you in your pocket.",
        style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
    )
    SwitchRow(
        "Also after the phone restarts", prefs.reachableAfterBoot, enabled = prefs.stayReachable,
        onCheckedChange = { on -> actions.update { it.copy(reachableAfterBoot = on) } },
    )
}

/** The composer's Enter key. */
@Composable
private fun TypingSection(prefs: ChatPreferences, actions: SettingsActions) {
    Section("Typing")
    SwitchRow("Enter key sends", prefs.enterSends, onCheckedChange = { on -> actions.update { it.copy(enterSends = on) } })
}

/** End-to-end encryption, its warnings, and the peers whose changed keys wait for the user's trust. */
@Composable
private fun PrivacySection(uiState: SettingsUiState, actions: SettingsActions) {
    val prefs = uiState.preferences
    Section("Privacy")
    EndToEndRow(prefs.endToEnd) { on -> actions.update { it.copy(endToEnd = on) } }
    for (warning in uiState.securityWarnings) {
        Text("⚠ $warning", style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.error)
    }
    // Signal's rule: a changed key is accepted only by the user, after comparing safety numbers with the peer.
    for (peer in uiState.changedKeys.sorted()) {
        OutlinedButton(onClick = { actions.onTrustKey(peer) }) { Text("Trust $peer's new key (safety numbers compared)") }
    }
}

/** Colours. */
@Composable
private fun AppearanceSection(prefs: ChatPreferences, actions: SettingsActions) {
    Section("Appearance")
    SwitchRow("Colours from the wallpaper (Android 12+)", prefs.dynamicColor, onCheckedChange = { on -> actions.update { it.copy(dynamicColor = on) } })
}

/** The user's data: the chats as JSON. */
@Composable
private fun DataSection(actions: SettingsActions) {
    Section("Data")
    OutlinedButton(onClick = actions.onExport) { Text("Export chats as JSON…") }
}

/** The version and what the app does with messages. */
@Composable
private fun AboutSection(version: String) {
    Section("About")
    Text(
        "Hapticon $version: haptic icons as in the originating study (Table 3), felt through this phone's best renderer. " +
            "Messages go only through the broker you chose.",
        style = MaterialTheme.typography.bodyMedium,
    )
}

/** What the settings call a [PitchFit]. */
val PitchFit.label: String
    get() = when (this) {
        PitchFit.OCTAVES -> "Shift by octaves into range"
        PitchFit.CLAMP -> "Clamp to the nearest edge"
    }

/**
 * The end-to-end switch. Turning it off is an explicit choice confirmed in a dialog (a study that needs the broker to
 * see content); while off, a warning in the error colour says who can read the messages.
 */
@Composable
private fun EndToEndRow(on: Boolean, onChange: (Boolean) -> Unit) {
    var confirming by rememberSaveable { mutableStateOf(false) }
    SwitchRow("Encrypt messages end to end", on, onCheckedChange = { wanted -> if (wanted) onChange(true) else confirming = true })
    if (on) {
        Text(
            "Only you and your peer can read or write your messages, not whoever runs the broker.",
            style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
        )
    } else {
        Text(PLAINTEXT_WARNING, style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.error)
    }
    if (confirming) {
        AlertDialog(
            onDismissRequest = { confirming = false },
            title = { Text("Send messages unencrypted?") },
            text = {
                Text(
                    "Whoever runs the broker can then read every message you send and receive, and change them. " +
                        "Turn encryption off only for a study that needs the broker to see what participants write.",
                )
            },
            confirmButton = { TextButton(onClick = { confirming = false; onChange(false) }) { Text("Turn encryption off") } },
            dismissButton = { TextButton(onClick = { confirming = false }) { Text("Keep encryption") } },
        )
    }
}

/** What Settings says while end-to-end encryption is off. */
const val PLAINTEXT_WARNING: String = "⚠ Encryption is off: whoever runs the broker can read and change your messages."

@Composable
private fun Section(title: String, first: Boolean = false) {
    if (!first) HorizontalDivider(Modifier.padding(top = 8.dp))
    Text(title, style = MaterialTheme.typography.titleSmall, color = MaterialTheme.colorScheme.primary, modifier = Modifier.padding(top = 8.dp))
}

/**
 * A value shown as text with a "Change" button that turns it into a field; saving may be refused with a reason.
 *
 * A [url] stays on one line, cut in the middle when it does not fit (`TextOverflow.MiddleEllipsis`): wrapped, a large
 * font broke it at ":" and split the host from its port. Cut in the middle, the scheme and the port stay in sight; the
 * whole address is in the field "Change" opens, and TalkBack reads it whole (the cut is only drawn).
 */
@Composable
private fun EditableField(
    label: String,
    value: String,
    onSave: (String) -> String?,
    supporting: String,
    secret: Boolean = false,
    url: Boolean = false,
) {
    var editing by rememberSaveable { mutableStateOf(false) }
    // A secret starts empty: the stored one is never put back on screen.
    var text by rememberSaveable(value) { mutableStateOf(if (secret) "" else value) }
    var error by rememberSaveable { mutableStateOf<String?>(null) }
    if (editing) {
        OutlinedTextField(
            text, { text = it; error = null }, label = { Text(label) }, singleLine = true, isError = error != null,
            visualTransformation = if (secret) androidx.compose.ui.text.input.PasswordVisualTransformation() else androidx.compose.ui.text.input.VisualTransformation.None,
            supportingText = { Text(error ?: supporting) },
            modifier = Modifier.fillMaxWidth().semantics { contentDescription = label },
        )
        androidx.compose.foundation.layout.Row {
            TextButton(onClick = { error = onSave(text); if (error == null) editing = false }) { Text("Save") }
            TextButton(onClick = { editing = false; text = if (secret) "" else value; error = null }) { Text("Cancel") }
        }
    } else {
        androidx.compose.foundation.layout.Row(verticalAlignment = androidx.compose.ui.Alignment.CenterVertically) {
            Column(Modifier.weight(1f)) {
                Text(label, style = MaterialTheme.typography.labelMedium, color = MaterialTheme.colorScheme.onSurfaceVariant)
                Text(
                    value.ifEmpty { "not set" }, style = MaterialTheme.typography.bodyLarge,
                    maxLines = if (url) 1 else Int.MAX_VALUE, overflow = if (url) TextOverflow.MiddleEllipsis else TextOverflow.Clip,
                    modifier = if (url) Modifier.testTag(BROKER_URL_TAG) else Modifier,
                )
                Text(supporting, style = MaterialTheme.typography.bodySmall, color = MaterialTheme.colorScheme.onSurfaceVariant)
            }
            TextButton(onClick = { editing = true }) { Text("Change") }
        }
    }
}

/**
 * The client certificate: which one logs in (its user and expiry) and the study CA trusted for the broker, or an
 * import button; a picked file asks for its password here, once, and shows why it did not open.
 */
@Composable
private fun ClientCertificateField(status: ClientCertificateStatus, import: CertificateImport?, actions: SettingsActions) {
    // One block like the fields above (label, value, explanation without the screen's 8 dp gaps).
    Column {
        Text("Client certificate", style = MaterialTheme.typography.labelMedium, color = MaterialTheme.colorScheme.onSurfaceVariant)
        when (status) {
            ClientCertificateStatus.None -> {
                Text("none", style = MaterialTheme.typography.bodyLarge)
                Text(
                    "A study may give you a .p12 file instead of a password; it logs in on ssl:// brokers.",
                    style = MaterialTheme.typography.bodySmall, color = MaterialTheme.colorScheme.onSurfaceVariant,
                )
            }
            is ClientCertificateStatus.InUse -> {
                Text("${status.user}, valid until ${certificateDate(status.notAfter)}", style = MaterialTheme.typography.bodyLarge)
                Text(
                    "Logs in on ssl:// brokers. " +
                        (status.studyCa?.let { "The broker must hold a certificate of $it." } ?: "The broker is trusted by Android's certificates."),
                    style = MaterialTheme.typography.bodySmall, color = MaterialTheme.colorScheme.onSurfaceVariant,
                )
            }
            is ClientCertificateStatus.Unusable -> Text("⚠ ${status.reason}", style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.error)
        }
    }
    if (import != null) {
        var password by rememberSaveable(import.fileName) { mutableStateOf("") }
        OutlinedTextField(
            password, { password = it }, label = { Text("Password of ${import.fileName}") }, singleLine = true, isError = import.error != null,
            visualTransformation = androidx.compose.ui.text.input.PasswordVisualTransformation(),
            supportingText = { Text(import.error ?: "Asked once: the certificate is kept encrypted on this phone.") },
            modifier = Modifier.fillMaxWidth().semantics { contentDescription = "Certificate password" },
        )
        androidx.compose.foundation.layout.Row {
            TextButton(onClick = { actions.onCertificatePassword(password) }) { Text("Import") }
            TextButton(onClick = actions.onCancelCertificate) { Text("Cancel") }
        }
    } else {
        androidx.compose.foundation.layout.Row {
            TextButton(onClick = actions.onImportCertificate) {
                Text(if (status is ClientCertificateStatus.InUse) "Replace…" else "Import .p12…")
            }
            if (status != ClientCertificateStatus.None) TextButton(onClick = actions.onRemoveCertificate) { Text("Remove") }
        }
    }
}

/** The test tag of the broker address as Settings shows it (one line). */
const val BROKER_URL_TAG: String = "broker-url"

/** What Settings says while Android shows no notifications of this app. */
const val NOTIFICATIONS_OFF: String =
    "Notifications are off. Messages still arrive and wait in Chats with their unread count, but nothing announces them."
