package org.hapticon.app.feature.study

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.Job
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import org.hapticon.app.data.IconRepository
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.StoredProtocol
import org.hapticon.app.study.StudyRepository
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.JsonException
import org.hapticon.study.LikertScale
import org.hapticon.study.ProtocolJson
import org.hapticon.study.Stimulus
import org.hapticon.study.StudyProtocol
import org.hapticon.study.StudyTask
import org.hapticon.study.design.OrderScheme

/**
 * A protocol being edited. Tasks and stimuli are the study module's own types (they validate only inside a
 * protocol); the scale is kept as [points] and [labels] because [LikertScale] refuses invalid combinations.
 */
data class ProtocolDraft(
    val id: String,
    val title: String,
    val revision: Int,
    val points: Int,
    val labels: List<String>,
    val taskOrder: OrderScheme,
    val fixedFirst: List<String>,
    val tasks: List<StudyTask>,
    val seed: Long,
    val masking: MaskingSetting,
) {
    /** The protocol; throws [org.hapticon.study.schema.ProtocolException] naming the path of the first problem. */
    fun build(): StudyProtocol = StudyProtocol(id, title, LikertScale(points, labels), tasks, taskOrder, fixedFirst, revision)

    companion object {
        /** The draft of [stored]. */
        fun of(stored: StoredProtocol): ProtocolDraft = with(stored.protocol) {
            ProtocolDraft(id, title, revision, scale.points, scale.labels, taskOrder, fixedFirst, tasks, stored.seed, stored.masking)
        }
    }
}

/** What the protocol editor shows. */
sealed interface ProtocolEditorUiState {
    /** The stored protocol is being read. */
    data object Loading : ProtocolEditorUiState

    /** The protocol cannot be edited (it does not exist, or it is the read-only default); [message] says so. */
    data class Error(val message: String) : ProtocolEditorUiState

    /** The draft being edited. */
    data class Success(
        val draft: ProtocolDraft,
        /** The study module's message for the first problem, or null when the draft is a valid protocol. */
        val problem: String? = null,
        val icons: List<HapticIcon> = emptyList(),
        /** The JSON text box: the protocol exported, or text pasted to import. */
        val json: String = "",
        val message: String? = null,
    ) : ProtocolEditorUiState
}

/**
 * Edits the stored protocol [protocolId] (never the read-only default): title, scale points, tasks, each stimulus's
 * icon (presets and custom icons), text and sticker, the designs and seed, the masking noise; JSON import and export.
 * Every edit re-validates through [StudyProtocol]; [save] stores only a valid protocol.
 */
class ProtocolEditorViewModel(
    private val protocolId: String,
    private val repository: StudyRepository,
    iconRepository: IconRepository,
) : ViewModel() {
    // The editor's own state; the icons come from the repository and are combined in below.
    private val local = MutableStateFlow<ProtocolEditorUiState>(ProtocolEditorUiState.Loading)

    /** Completes once the protocol is loaded. */
    val loaded: Job = viewModelScope.launch {
        val stored = repository.protocol(protocolId)
        if (stored == null || stored.readOnly) {
            local.value = ProtocolEditorUiState.Error("protocol $protocolId cannot be edited; duplicate it first")
        } else {
            setDraft(ProtocolDraft.of(stored))
        }
    }

    val uiState: StateFlow<ProtocolEditorUiState> = combine(local, iconRepository.icons()) { state, icons ->
        if (state is ProtocolEditorUiState.Success) state.copy(icons = icons) else state
    }.stateIn(viewModelScope, SharingStarted.Eagerly, ProtocolEditorUiState.Loading)

    private val editing: ProtocolEditorUiState.Success? get() = local.value as? ProtocolEditorUiState.Success

    // Changes the state while a draft is being edited; before (loading) and instead (error) there is nothing to change.
    private fun updateEditing(transform: (ProtocolEditorUiState.Success) -> ProtocolEditorUiState.Success) =
        local.update { if (it is ProtocolEditorUiState.Success) transform(it) else it }

    /** Changes the draft with [transform] and re-validates. */
    fun edit(transform: (ProtocolDraft) -> ProtocolDraft) {
        editing?.draft?.let { setDraft(transform(it)) }
    }

    /** Sets the scale's number of points, keeping the labels that still fit (per-point labels shrink to the two ends). */
    fun setPoints(points: Int) = edit { draft ->
        val labels = when (draft.labels.size) {
            0, 2, points -> draft.labels
            else -> listOf(draft.labels.first(), draft.labels.last())
        }
        draft.copy(points = points, labels = labels)
    }

    /** Replaces task [index] with [transform] of it. */
    fun editTask(index: Int, transform: (StudyTask) -> StudyTask) = edit { draft ->
        draft.copy(tasks = draft.tasks.mapIndexed { i, task -> if (i == index) transform(task) else task })
    }

    /** Replaces stimulus [stimulus] of task [task] with [transform] of it. */
    fun editStimulus(task: Int, stimulus: Int, transform: (Stimulus) -> Stimulus) = editTask(task) { t ->
        t.copy(stimuli = t.stimuli.mapIndexed { i, s -> if (i == stimulus) transform(s) else s })
    }

    /** Puts the draft's protocol JSON into the text box. */
    fun exportJson() {
        val draft = editing?.draft ?: return
        val json = runCatching { ProtocolJson.encode(draft.build()) }
        updateEditing { it.copy(json = json.getOrDefault(it.json), message = json.exceptionOrNull()?.message ?: "JSON exported below") }
    }

    /** Sets the text box. */
    fun setJson(text: String) = updateEditing { it.copy(json = text) }

    /** Replaces the draft's protocol by the text box's JSON; the id stays this protocol's. Shows the parse error otherwise. */
    fun importJson() {
        val current = editing ?: return
        val draft = current.draft
        try {
            val imported = ProtocolJson.decode(current.json)
            setDraft(ProtocolDraft.of(StoredProtocol(imported.copy(id = draft.id), draft.seed, draft.masking)))
            updateEditing { it.copy(message = "imported ${imported.tasks.size} tasks") }
        } catch (e: JsonException) {
            updateEditing { it.copy(message = "not JSON: ${e.message}") }
        } catch (e: IllegalArgumentException) {
            updateEditing { it.copy(message = e.message) }
        }
    }

    /**
     * Stores the draft when it is valid. A protocol whose stored revision already ran sessions gets the next revision,
     * so old sessions keep meaning what they meant.
     */
    fun save(): Job = viewModelScope.launch {
        val draft = editing?.draft ?: return@launch
        val protocol = try {
            draft.build()
        } catch (e: IllegalArgumentException) {
            updateEditing { it.copy(problem = e.message, message = "not saved: fix the problem first") }
            return@launch
        }
        val stored = repository.protocol(protocolId)?.protocol
        val ran = repository.sessionsOf(protocolId).any { it.protocol.revision == protocol.revision }
        val revised = if (ran && stored != protocol) protocol.copy(revision = protocol.revision + 1) else protocol
        repository.saveProtocol(StoredProtocol(revised, draft.seed, draft.masking))
        setDraft(draft.copy(revision = revised.revision))
        updateEditing { it.copy(message = "saved revision ${revised.revision}") }
    }

    private fun setDraft(draft: ProtocolDraft) {
        val problem = try {
            draft.build()
            null
        } catch (e: IllegalArgumentException) {
            e.message
        }
        local.update {
            (it as? ProtocolEditorUiState.Success)?.copy(draft = draft, problem = problem, message = null)
                ?: ProtocolEditorUiState.Success(draft, problem)
        }
    }
}
