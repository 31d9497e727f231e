package org.hapticon.app.feature.study

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import java.io.IOException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import org.hapticon.app.study.ExportResult
import org.hapticon.app.study.SessionSummary
import org.hapticon.app.study.StoredProtocol
import org.hapticon.app.study.StudyComponent
import org.hapticon.app.study.UploadResult
import org.hapticon.study.ParticipantId

/** Whether the researcher screen is open. */
enum class LockState {
    /** First use: no PIN yet. */
    SET_PIN,

    /** A PIN is set and must be entered. */
    LOCKED,

    /** The researcher entered the PIN. */
    UNLOCKED,
}

/** The upload of the last export. */
sealed interface UploadState {
    data object Idle : UploadState
    data object Uploading : UploadState
    data class Done(val message: String) : UploadState

    /** Failed with [message]; the export files stay, and Retry sends them again. */
    data class Failed(val message: String) : UploadState
}

/**
 * What the researcher screen shows. The PIN gate ([lock], [pinError]) is known at once; the stored protocols,
 * sessions and the running session's id only once Room and the settings have answered ([Success]).
 */
sealed interface ResearcherUiState {
    /** Whether the researcher screen is open. */
    val lock: LockState

    /** Why the last PIN was refused, if it was. */
    val pinError: String?

    /** The stored protocols and sessions are being read: which screen to show (session, PIN, researcher) is not known yet. */
    data class Loading(override val lock: LockState, override val pinError: String? = null) : ResearcherUiState

    /** Everything read: the protocols, the selected one, the sessions run, and the last export and upload. */
    data class Success(
        override val lock: LockState,
        override val pinError: String? = null,
        val protocols: List<StoredProtocol> = emptyList(),
        val selected: StoredProtocol? = null,
        val sessions: List<SessionSummary> = emptyList(),
        val activeSessionId: Long? = null,
        /** The id the next session of the selected protocol gets. */
        val nextParticipant: String = ParticipantId.of(0),
        /** Masking noise is on but no headphones are connected: the researcher confirms or cancels the start. */
        val headphoneWarning: Boolean = false,
        val export: ExportResult? = null,
        val message: String? = null,
        val upload: UploadState = UploadState.Idle,
        val collectorUrl: String = "",
        val collectorToken: String = "",
    ) : ResearcherUiState
}

/**
 * The researcher's side: the PIN gate, picking a protocol, starting the next participant's session, the session list,
 * export, share and upload. Actions that write return their [Job].
 */
class ResearcherViewModel(
    private val study: StudyComponent,
    /** Where PINs are hashed: PBKDF2's 60,000 rounds take tens of milliseconds, too long for the main thread. */
    private val hashing: kotlinx.coroutines.CoroutineDispatcher = Dispatchers.Default,
) : ViewModel() {
    private data class Local(
        val lock: LockState,
        val pinError: String? = null,
        val headphoneWarning: Boolean = false,
        val export: ExportResult? = null,
        val message: String? = null,
        val upload: UploadState = UploadState.Idle,
    )

    private val local = MutableStateFlow(Local(if (study.pin.isSet) LockState.LOCKED else LockState.SET_PIN))

    val uiState: StateFlow<ResearcherUiState> = combine(
        study.repository.protocols(), study.repository.sessions(), study.settings.preferences, local,
    ) { protocols, sessions, prefs, l ->
        val selected = protocols.firstOrNull { it.protocol.id == prefs.selectedProtocolId } ?: protocols.firstOrNull()
        val last = sessions.filter { it.protocolId == selected?.protocol?.id }.maxOfOrNull { it.participantIndex } ?: -1
        ResearcherUiState.Success(
            lock = l.lock,
            pinError = l.pinError,
            protocols = protocols,
            selected = selected,
            sessions = sessions,
            activeSessionId = prefs.activeSessionId,
            nextParticipant = ParticipantId.of(last + 1),
            headphoneWarning = l.headphoneWarning,
            export = l.export,
            message = l.message,
            upload = l.upload,
            collectorUrl = prefs.collectorUrl,
            collectorToken = prefs.collectorToken,
        )
    }.stateIn(viewModelScope, SharingStarted.Eagerly, ResearcherUiState.Loading(local.value.lock))

    /** Sets the first PIN; [confirm] must repeat it. The state says when it is done. */
    fun setPin(pin: String, confirm: String): Job = viewModelScope.launch {
        val error = when {
            pin != confirm -> "the two PINs differ"
            else -> withContext(hashing) { runCatching { study.pin.set(pin) }.exceptionOrNull()?.message }
        }
        local.update { if (error == null) it.copy(lock = LockState.UNLOCKED, pinError = null) else it.copy(pinError = error) }
    }

    /** Opens the researcher screen when [pin] is right; a wrong PIN is refused with a message. */
    fun unlock(pin: String): Job = viewModelScope.launch { checkPin(pin) }

    private suspend fun checkPin(pin: String): Boolean {
        val ok = withContext(hashing) { study.pin.check(pin) }
        local.update { if (ok) it.copy(lock = LockState.UNLOCKED, pinError = null) else it.copy(pinError = "wrong PIN") }
        return ok
    }

    /** Locks the researcher screen again. */
    fun lock() = local.update { it.copy(lock = if (study.pin.isSet) LockState.LOCKED else LockState.SET_PIN, pinError = null) }

    /** Leaves the running session for the researcher screen; only with the right PIN. */
    fun exitSession(pin: String): Job = viewModelScope.launch {
        if (!checkPin(pin)) return@launch
        study.noise.stop()
        study.settings.update { it.copy(activeSessionId = null) }
    }

    /** Picks the protocol the next session runs and the export covers. */
    fun select(protocolId: String) {
        study.settings.update { it.copy(selectedProtocolId = protocolId) }
        local.update { it.copy(export = null, upload = UploadState.Idle, message = null) }
    }

    /**
     * Starts the next participant's session of the selected protocol. With masking noise on and no headphones it
     * first asks ([ResearcherUiState.Success.headphoneWarning]); [ignoreHeadphones] proceeds anyway.
     */
    fun startSession(ignoreHeadphones: Boolean = false): Job = viewModelScope.launch {
        val protocol = selectedProtocol() ?: return@launch
        if (protocol.masking.isOn && !ignoreHeadphones && !study.headphones.headphonesConnected()) {
            local.update { it.copy(headphoneWarning = true) }
            return@launch
        }
        val record = study.repository.startSession(protocol, study.clock())
        local.update { it.copy(headphoneWarning = false, lock = LockState.LOCKED, message = "started ${record.participant}") }
        study.settings.update { it.copy(activeSessionId = record.id) }
    }

    /** Cancels a start the headphone warning stopped. */
    fun dismissHeadphoneWarning() = local.update { it.copy(headphoneWarning = false) }

    /** Stores a copy of [protocol] under a free id ("…-copy", "…-copy2", …), editable, and selects it. Returns the new id. */
    fun duplicate(protocol: StoredProtocol): Job = viewModelScope.launch {
        val taken = study.repository.protocols().first().map { it.protocol.id }.toSet()
        // Ids are at most 64 characters: room for "-copy" and a two-digit number.
        val base = protocol.protocol.id.take(57) + "-copy"
        val id = generateSequence(1) { it + 1 }.map { if (it == 1) base else "$base$it" }.first { it !in taken }
        study.repository.saveProtocol(protocol.copy(protocol = protocol.protocol.copy(id = id, revision = 1), readOnly = false))
        select(id)
    }

    /** Deletes stored protocol [id] (not the default); its sessions are kept. */
    fun delete(id: String): Job = viewModelScope.launch {
        study.repository.deleteProtocol(id)
        if ((uiState.value as? ResearcherUiState.Success)?.selected?.protocol?.id == id) select(StoredProtocol.DEFAULT.protocol.id)
    }

    /** Writes the selected protocol's CSV and JSON to the export directory and checks every session's chain. */
    fun export(): Job = viewModelScope.launch {
        val protocol = selectedProtocol() ?: return@launch
        try {
            val result = withContext(Dispatchers.IO) {
                val sessions = study.repository.sessionsOf(protocol.protocol.id).map { it to study.repository.entries(it.id) }
                study.exporter.export(protocol.protocol, sessions)
            }
            local.update { it.copy(export = result, upload = UploadState.Idle, message = "exported ${result.rows} rows") }
        } catch (e: IOException) {
            local.update { it.copy(message = "export failed: ${e.message}") }
        } catch (e: IllegalArgumentException) {
            local.update { it.copy(message = "export failed: ${e.message}") }
        }
    }

    /** Stores the collector's base URL and bearer token (blank for none). */
    fun setCollector(url: String, token: String) = study.settings.update { it.copy(collectorUrl = url.trim(), collectorToken = token.trim()) }

    /** Uploads the last export's CSV (exporting first if there is none); a failure is shown and can be retried. */
    fun upload(): Job = viewModelScope.launch {
        if (local.value.export == null) export().join()
        val export = local.value.export ?: return@launch
        val protocol = selectedProtocol() ?: return@launch
        val prefs = study.settings.preferences.value
        local.update { it.copy(upload = UploadState.Uploading) }
        val result = study.uploader.upload(prefs.collectorUrl, prefs.collectorToken, protocol.protocol.id, export.csv)
        local.update {
            it.copy(
                upload = when (result) {
                    is UploadResult.Uploaded -> UploadState.Done("${export.rows} rows ${result.message}")
                    is UploadResult.Failed -> UploadState.Failed(result.message)
                },
            )
        }
    }

    private suspend fun selectedProtocol(): StoredProtocol? {
        val id = study.settings.preferences.value.selectedProtocolId ?: StoredProtocol.DEFAULT.protocol.id
        return study.repository.protocol(id) ?: StoredProtocol.DEFAULT
    }

}
