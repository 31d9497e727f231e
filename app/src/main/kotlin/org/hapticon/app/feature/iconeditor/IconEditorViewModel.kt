package org.hapticon.app.feature.iconeditor

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.playback.HapticPlayer
import org.hapticon.app.playback.playOffMain
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException

/** The editor's fields, in the order shown; [key] is the field name HapticIcon's validation uses. */
enum class IconField(val key: String, val label: String) {
    NAME("name", "Name"),
    ATTACK("attack", "Attack (s)"),
    SUSTAIN("sustain", "Sustain (s)"),
    LEVEL("level", "Level (0–1)"),
    RELEASE("release", "Release (s)"),
    NOTE("note", "Note (MIDI)"),
    PERIOD("period", "Period (s)"),
    COUNT("count", "Count"),
}

/** The editor: the text of every field and either the icon they make or the first problem, by field. */
sealed interface IconEditorUiState {
    /** The text of every field, as typed. */
    val fields: Map<IconField, String>

    /** The icon the fields make, or null while they make none. */
    val icon: HapticIcon?

    /** The problem of each field that has one. */
    val errors: Map<IconField, String>

    /** The fields make [icon]: it can be played and saved. */
    data class Valid(override val fields: Map<IconField, String>, override val icon: HapticIcon) : IconEditorUiState {
        override val errors: Map<IconField, String> get() = emptyMap()
    }

    /** The fields make no icon: [errors] says why, by field. */
    data class Invalid(override val fields: Map<IconField, String>, override val errors: Map<IconField, String>) : IconEditorUiState {
        override val icon: HapticIcon? get() = null
    }
}

class IconEditorViewModel(
    private val icons: RoomIconRepository,
    private val player: HapticPlayer,
    start: HapticIcon = HapticIcon("custom", 0.1, 0.3, 0.8, 0.2, 60.0, 0.0, 1),
) : ViewModel() {
    private val fields = MutableStateFlow(
        mapOf(
            IconField.NAME to start.name, IconField.ATTACK to start.attack.toString(), IconField.SUSTAIN to start.sustain.toString(),
            IconField.LEVEL to start.level.toString(), IconField.RELEASE to start.release.toString(), IconField.NOTE to start.note.toString(),
            IconField.PERIOD to start.period.toString(), IconField.COUNT to start.count.toString(),
        ),
    )
    val uiState: StateFlow<IconEditorUiState> = fields.map { validate(it) }
        .stateIn(viewModelScope, SharingStarted.Eagerly, validate(fields.value))

    fun update(field: IconField, text: String) {
        fields.value = fields.value + (field to text)
    }

    fun play() {
        uiState.value.icon?.let { viewModelScope.launch { player.playOffMain(it, VibrationUsage.TOUCH) } }
    }

    fun save(onSaved: () -> Unit = {}) {
        val icon = uiState.value.icon ?: return
        viewModelScope.launch {
            icons.save(icon)
            onSaved()
        }
    }

    companion object {
        /** Parses and validates [fields]: numbers first, then HapticIcon's own rules, whose exception names the field. */
        fun validate(fields: Map<IconField, String>): IconEditorUiState {
            val errors = mutableMapOf<IconField, String>()
            fun number(field: IconField): Double = fields[field]?.trim()?.toDoubleOrNull()
                ?: 0.0.also { errors[field] = "Enter a number" }
            val attack = number(IconField.ATTACK)
            val sustain = number(IconField.SUSTAIN)
            val level = number(IconField.LEVEL)
            val release = number(IconField.RELEASE)
            val note = number(IconField.NOTE)
            val period = number(IconField.PERIOD)
            val count = fields[IconField.COUNT]?.trim()?.toIntOrNull() ?: 0.also { errors[IconField.COUNT] = "Enter a whole number" }
            if (errors.isNotEmpty()) return IconEditorUiState.Invalid(fields, errors)
            return try {
                val icon = HapticIcon(fields[IconField.NAME].orEmpty().trim(), attack, sustain, level, release, note, period, count)
                IconEditorUiState.Valid(fields, icon)
            } catch (e: IconValidationException) {
                val field = IconField.entries.firstOrNull { it.key == e.field } ?: IconField.NAME
                IconEditorUiState.Invalid(fields, mapOf(field to (e.message ?: "Not valid")))
            }
        }
    }
}
