package org.hapticon.app.feature.chat

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.ClientCertificateRepository
import org.hapticon.app.data.ClientCertificateStatus
import org.hapticon.app.sync.BrokerProbe
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.Topics
import java.io.OutputStream

/**
 * The chat settings screen's state and the changes that need more than a write: a new broker or password is
 * tested ([probe]) before it is saved, a user name is checked, the export is written off the main thread. What
 * needs an Activity (the permission prompt, Android's settings page, the reachable service) stays in the route.
 */
class SettingsViewModel(
    private val settings: ChatSettingsRepository,
    connection: StateFlow<ConnectionState>,
    securityWarnings: StateFlow<List<String>>,
    changedKeys: StateFlow<Set<String>>,
    /** The renderers this phone can play (asked again for every state: a test may change the device). */
    private val renderers: () -> List<RendererKind>,
    /** Whether Android shows this app's notifications now; null where there is no notifier to ask. */
    private val canNotify: () -> Boolean?,
    private val probe: BrokerProbe,
    private val trustKey: (peer: String) -> Boolean,
    /** Every stored message as the export's JSON ([org.hapticon.app.data.ChatExport]). */
    private val exportJson: suspend () -> String,
    /** Publishes this phone's capabilities again: the pitch setting and the renderer choice are part of them. */
    private val republishCapabilities: () -> Unit,
    private val io: CoroutineDispatcher = Dispatchers.IO,
    /** The user's client certificate; null where the container has none (its section then offers only import errors). */
    private val certificates: ClientCertificateRepository? = null,
    /** Called after a certificate was imported or removed, so the session reconnects with it. */
    private val onCertificateChanged: () -> Unit = {},
) : ViewModel() {
    private val notice = MutableStateFlow<String?>(null)
    private val notificationsAllowed = MutableStateFlow(canNotify() ?: true)
    private val certificateStatus: StateFlow<ClientCertificateStatus> = certificates?.status ?: MutableStateFlow(ClientCertificateStatus.None)
    private val certificateImport = MutableStateFlow<CertificateImport?>(null)

    // The picked file's bytes stay here, never in the UI state, until the password opens them.
    private var pickedCertificate: ByteArray? = null

    private data class Local(val notice: String?, val allowed: Boolean, val certificate: ClientCertificateStatus, val import: CertificateImport?)

    /** What the settings screen shows; it starts from the sources' current values, so the first frame is complete. */
    val uiState: StateFlow<SettingsUiState> = combine(
        settings.preferences, connection, securityWarnings, changedKeys,
        combine(notice, notificationsAllowed, certificateStatus, certificateImport, ::Local),
    ) { prefs, c, warnings, keys, local ->
        SettingsUiState(prefs, renderers(), connectionLabel(c), local.allowed, warnings, keys, local.notice, local.certificate, local.import)
    }.stateIn(
        viewModelScope, SharingStarted.WhileSubscribed(5_000),
        SettingsUiState(
            settings.preferences.value, renderers(), connectionLabel(connection.value), notificationsAllowed.value,
            securityWarnings.value, changedKeys.value, clientCertificate = certificateStatus.value,
        ),
    )

    /** The system file picker handed over [bytes] of [fileName]: its password is asked next. */
    fun certificatePicked(bytes: ByteArray, fileName: String) {
        pickedCertificate = bytes
        certificateImport.value = CertificateImport(fileName)
    }

    /** The picked file could not be read ([reason], one line). */
    fun certificateUnreadable(reason: String) {
        notice.value = "Certificate not imported: $reason"
    }

    /**
     * Opens the picked file with [password] and stores it ([ClientCertificateRepository.import]); a wrong password,
     * an expired certificate or one for another user keeps the password prompt open with the reason.
     */
    fun unlockCertificate(password: String): Job = viewModelScope.launch {
        val bytes = pickedCertificate ?: return@launch
        val pending = certificateImport.value ?: return@launch
        val store = certificates ?: run { certificateImport.value = pending.copy(error = "this app build keeps no certificates"); return@launch }
        val user = settings.preferences.value.userName
        val outcome = withContext(io) { runCatching { store.import(bytes, password.toCharArray(), user) } }
        outcome.onSuccess { inUse ->
            pickedCertificate = null
            certificateImport.value = null
            notice.value = "Client certificate of ${inUse.user} in use until ${certificateDate(inUse.notAfter)}"
            onCertificateChanged()
        }.onFailure { e ->
            if (e !is IllegalArgumentException) throw e
            certificateImport.value = pending.copy(error = e.message ?: "the certificate cannot be used")
        }
    }

    /** Drops the picked file without importing it. */
    fun cancelCertificateImport() {
        pickedCertificate = null
        certificateImport.value = null
    }

    /** Forgets the stored certificate; the password (if any) logs in again. */
    fun removeCertificate() {
        certificates?.remove() ?: return
        notice.value = "Client certificate removed"
        onCertificateChanged()
    }

    /** Asks Android again whether notifications are shown (the user may have changed it in Android's settings). */
    fun refreshNotifications() {
        notificationsAllowed.value = canNotify() ?: true
    }

    /** The notification permission prompt was answered; refused, the screen says that nothing will announce messages. */
    fun permissionAnswered(granted: Boolean) {
        notificationsAllowed.value = canNotify() ?: granted
        if (!granted) notice.value = "Notifications are off: messages still arrive, but nothing announces them."
    }

    /** Shows [text] as the screen's one-line notice (an outcome the route learnt, e.g. no settings page to open). */
    fun notify(text: String) {
        notice.value = text
    }

    /** Applies [transform] to the stored settings; a changed pitch setting or renderer is published to peers at once. */
    fun update(transform: (ChatPreferences) -> ChatPreferences) {
        val before = settings.preferences.value
        settings.update(transform)
        val after = settings.preferences.value
        if (before.pitchFit != after.pitchFit || before.rendererOverride != after.rendererOverride) republishCapabilities()
    }

    /**
     * Tests [url] as the new broker and saves it once it answered, as first launch does. Returns why not at once
     * (a bad address, no user name), null when the test started; its outcome becomes the notice.
     */
    fun setBroker(url: String): String? {
        val address = runCatching { BrokerAddress.parse(url) }.getOrElse { return it.message }
        val prefs = settings.preferences.value
        val user = prefs.userName ?: return "Set a user name first"
        notice.value = "Testing $address…"
        viewModelScope.launch {
            val problem = probe(user, address, prefs.brokerPassword)
            if (problem == null) settings.update { it.copy(brokerUrl = address.toString()) }
            notice.value = problem?.let { "Broker not changed: $it" } ?: "Broker changed to $address"
        }
        return null
    }

    /** Tests [password] (empty: none) with the stored broker; returns why not at once, null when the test started. */
    fun setPassword(password: String): String? {
        val prefs = settings.preferences.value
        val user = prefs.userName
        val address = runCatching { BrokerAddress.parse(prefs.brokerUrl) }.getOrNull()
        if (user == null || address == null) return "Set a user name and broker first"
        notice.value = "Testing the password with $address…"
        viewModelScope.launch {
            val problem = probe(user, address, password.takeIf { it.isNotEmpty() })
            notice.value = problem?.let { "Password not changed: $it" } ?: "Password changed"
        }
        return null
    }

    /** Saves [name] (trimmed) as the user name; returns why not, null when saved. */
    fun setUserName(name: String): String? {
        val trimmed = name.trim()
        if (!Topics.isValidUserName(trimmed)) return "Use 1 to 32 letters, digits, '.', '_' or '-'"
        settings.update { it.copy(userName = trimmed) }
        return null
    }

    /** Stores "Stay reachable"; off also turns off "after the phone restarts". */
    fun setStayReachable(on: Boolean) = settings.update { it.copy(stayReachable = on, reachableAfterBoot = on && it.reachableAfterBoot) }

    /** Accepts [peer]'s changed end-to-end key. */
    fun trust(peer: String) {
        trustKey(peer)
    }

    /** Writes every message's JSON to [open]'s stream (named [target] in the notice), off the main thread. */
    fun export(target: String, open: () -> OutputStream): Job = viewModelScope.launch {
        notice.value = withContext(io) {
            runCatching {
                val json = exportJson()
                open().use { it.write(json.toByteArray(Charsets.UTF_8)) }
                "Exported to $target"
            }.getOrElse { "Export failed: ${it.message}" }
        }
    }

    private companion object {
        fun connectionLabel(c: ConnectionState): String = when (c) {
            ConnectionState.Connected -> "connected"
            is ConnectionState.Connecting -> "connecting" + (c.lastFailure?.let { " ($it)" } ?: "")
            ConnectionState.Disconnected -> "not connected"
            is ConnectionState.Failed -> "refused: ${c.reason}"
        }
    }
}

/** A certificate's expiry as Settings shows it: the UTC date (ISO 8601), the same on every phone. */
internal fun certificateDate(instant: java.time.Instant): String =
    java.time.format.DateTimeFormatter.ISO_LOCAL_DATE.format(instant.atZone(java.time.ZoneOffset.UTC))

/** The settings screen's values, read from the chat settings. */
data class SettingsUiState(
    val preferences: ChatPreferences,
    val renderers: List<RendererKind>,
    val connection: String,
    /** False when Android will not show this app's notifications (permission refused, or turned off). */
    val notificationsAllowed: Boolean = true,
    /** End-to-end warnings (a peer's changed key, forged payloads), newest last ([org.hapticon.app.sync.ChatSync.securityWarnings]). */
    val securityWarnings: List<String> = emptyList(),
    /** Peers whose changed key waits for the user's trust. */
    val changedKeys: Set<String> = emptySet(),
    /** The outcome of the last action that takes a moment (broker test, export, permission), one line. */
    val notice: String? = null,
    /** The client certificate for mutual TLS, if one is stored. */
    val clientCertificate: org.hapticon.app.data.ClientCertificateStatus = org.hapticon.app.data.ClientCertificateStatus.None,
    /** A picked certificate file waiting for its password, null when none is. */
    val certificateImport: CertificateImport? = null,
)

/** A picked client certificate file ([fileName]) waiting for its password; [error] says why the last one did not open it. */
data class CertificateImport(val fileName: String, val error: String? = null)
