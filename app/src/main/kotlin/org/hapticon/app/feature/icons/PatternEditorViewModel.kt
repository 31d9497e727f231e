package org.hapticon.app.feature.icons

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.RoomPatternRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternException
import org.hapticon.core.pattern.edited

/** The pattern editor's fields, in the order shown; [key] is the field name [edited] and [HapticPattern] report. */
enum class PatternEditField(val key: String, val label: String) {
    NAME("name", "Name"),
    GAIN("gain", "Strength (0–1, × every amplitude)"),
    SEMITONES("semitones", "Pitch shift (semitones)"),
    TIME_SCALE("timeScale", "Time scale (× every time)"),
}

/**
 * The editor: each field's text, the edited pattern (or the first problem, by field) and how this phone would
 * play it ([PatternPlan.summary]); [saved] after a save.
 */
data class PatternEditorUiState(
    val original: HapticPattern,
    val fields: Map<PatternEditField, String>,
    val preview: HapticPattern?,
    val errors: Map<PatternEditField, String>,
    val playedAs: String?,
)

/**
 * Edits a stored pattern as a whole ([edited]: softer, higher or lower, faster or slower) with a live preview;
 * saving under a new name keeps the original. Breakpoint-by-breakpoint editing belongs in the designers' own tools
 * (Core Haptics, Meta Haptics Studio), whose files Hapticon reads.
 */
class PatternEditorViewModel(
    private val original: HapticPattern,
    private val repository: RoomPatternRepository,
    private val player: HapticPlayer,
) : ViewModel() {
    private val fields = MutableStateFlow(
        mapOf(PatternEditField.NAME to original.name, PatternEditField.GAIN to "1", PatternEditField.SEMITONES to "0", PatternEditField.TIME_SCALE to "1"),
    )

    val uiState: StateFlow<PatternEditorUiState> = fields.map { validate(original, it, player) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, validate(original, fields.value, player))

    fun update(field: PatternEditField, text: String) {
        fields.value = fields.value + (field to text)
    }

    fun play() {
        uiState.value.preview?.let { player.play(it, org.hapticon.core.platform.VibrationUsage.TOUCH) }
    }

    fun save(onSaved: () -> Unit = {}) {
        val pattern = uiState.value.preview ?: return
        viewModelScope.launch {
            repository.save(pattern, source = if (pattern.name == original.name) null else "edited from ${original.name}")
            onSaved()
        }
    }

    companion object {
        /** Parses [fields] and applies them to [original]; a problem is reported on the field it names. */
        fun validate(original: HapticPattern, fields: Map<PatternEditField, String>, player: HapticPlayer?): PatternEditorUiState {
            val errors = mutableMapOf<PatternEditField, String>()
            fun number(field: PatternEditField): Double =
                fields[field]?.trim()?.toDoubleOrNull()?.takeIf { it.isFinite() } ?: 0.0.also { errors[field] = "Enter a number" }
            val gain = number(PatternEditField.GAIN)
            val semitones = number(PatternEditField.SEMITONES)
            val scale = number(PatternEditField.TIME_SCALE)
            if (errors.isNotEmpty()) return PatternEditorUiState(original, fields, null, errors, null)
            return try {
                val preview = original.edited(fields[PatternEditField.NAME].orEmpty().trim(), gain, semitones, scale)
                PatternEditorUiState(original, fields, preview, emptyMap(), player?.let { planFor(it, preview).summary })
            } catch (e: PatternException) {
                // A result that breaks a pattern rule (the 30 s cap, say) is the time scale's doing; frequencies the pitch's.
                val field = PatternEditField.entries.firstOrNull { it.key == e.field }
                    ?: if (e.field.startsWith("frequency")) PatternEditField.SEMITONES else PatternEditField.TIME_SCALE
                PatternEditorUiState(original, fields, null, mapOf(field to (e.message ?: "Not valid").removePrefix("${e.field}: ")), null)
            }
        }
    }
}
