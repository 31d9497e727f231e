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
    /** The protocol; throws [org.hapticon.study.ProtocolException] naming the path of the first problem. */
    fun build(): StudyProtocol = StudyProtocol(id, title, LikertScale(points, labels), tasks, taskOrder, fixedFirst, revision)

    companion object {
        /** The draft of [stored]. */
        fun of(stored: StoredProtocol): ProtocolDraft = with(stored.protocol) {
            ProtocolDraft(id, title, revision, scale.points, scale.labels, taskOrder, fixedFirst, tasks, stored.seed, stored.masking)
        }
    }
}

/** What the protocol editor shows. */
data class ProtocolEditorUiState(
    val draft: ProtocolDraft? = null,
    /** The study module's message for the first problem, or null when the draft is a valid protocol. */
    val problem: String? = null,
    val icons: List<HapticIcon> = emptyList(),
    /** The JSON text box: the protocol exported, or text pasted to import. */
    val json: String = "",
    val message: String? = null,
)

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
    private val local = MutableStateFlow(ProtocolEditorUiState())

    /** Completes once the protocol is loaded. */
    val loaded: Job = viewModelScope.launch {
        val stored = repository.protocol(protocolId)
        if (stored == null || stored.readOnly) {
            local.update { it.copy(message = "protocol $protocolId cannot be edited; duplicate it first") }
        } else {
            setDraft(ProtocolDraft.of(stored))
        }
    }

    val uiState: StateFlow<ProtocolEditorUiState> = combine(local, iconRepository.icons()) { state, icons -> state.copy(icons = icons) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, ProtocolEditorUiState())

    /** Changes the draft with [transform] and re-validates. */
    fun edit(transform: (ProtocolDraft) -> ProtocolDraft) {
        local.value.draft?.let { setDraft(transform(it)) }
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
        val draft = local.value.draft ?: return
        val json = runCatching { ProtocolJson.encode(draft.build()) }
        local.update { it.copy(json = json.getOrDefault(it.json), message = json.exceptionOrNull()?.message ?: "JSON exported below") }
    }

    /** Sets the text box. */
    fun setJson(text: String) = local.update { it.copy(json = text) }

    /** Replaces the draft's protocol by the text box's JSON; the id stays this protocol's. Shows the parse error otherwise. */
    fun importJson() {
        val draft = local.value.draft ?: return
        try {
            val imported = ProtocolJson.decode(local.value.json)
            setDraft(ProtocolDraft.of(StoredProtocol(imported.copy(id = draft.id), draft.seed, draft.masking)))
            local.update { it.copy(message = "imported ${imported.tasks.size} tasks") }
        } catch (e: JsonException) {
            local.update { it.copy(message = "not JSON: ${e.message}") }
        } catch (e: IllegalArgumentException) {
            local.update { it.copy(message = e.message) }
        }
    }

    /**
     * Stores the draft when it is valid. A protocol whose stored revision already ran sessions gets the next revision,
     * so old sessions keep meaning what they meant.
     */
    fun save(): Job = viewModelScope.launch {
        val draft = local.value.draft ?: return@launch
        val protocol = try {
            draft.build()
        } catch (e: IllegalArgumentException) {
            local.update { it.copy(problem = e.message, message = "not saved: fix the problem first") }
            return@launch
        }
        val stored = repository.protocol(protocolId)?.protocol
        val ran = repository.sessionsOf(protocolId).any { it.protocol.revision == protocol.revision }
        val revised = if (ran && stored != protocol) protocol.copy(revision = protocol.revision + 1) else protocol
        repository.saveProtocol(StoredProtocol(revised, draft.seed, draft.masking))
        setDraft(draft.copy(revision = revised.revision))
        local.update { it.copy(message = "saved revision ${revised.revision}") }
    }

    private fun setDraft(draft: ProtocolDraft) {
        val problem = try {
            draft.build()
            null
        } catch (e: IllegalArgumentException) {
            e.message
        }
        local.update { it.copy(draft = draft, problem = problem, message = null) }
    }
}
