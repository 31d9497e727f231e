package org.hapticon.study

/**
 * The placeholders of a task's question: `{n}` is the stimulus's [number][Stimulus.number] when it has one (the
 * paper's "icon 1" is stroke whatever the order), else its position in the participant's order (1-based),
 * `{label}`, `{icon}`, `{text}` and `{sticker}` are the stimulus's label, icon name, text and sticker id (empty when
 * absent). For example "Haptic icon {n} feels like {label}" becomes "Haptic icon 2 feels like hitting".
 */
public object QuestionTemplate {
    /** The placeholder names, without braces. */
    public val PLACEHOLDERS: Set<String> = setOf("n", "label", "icon", "text", "sticker")

    private val PLACEHOLDER = Regex("\\{([^{}]*)}")

    /**
     * The names in [template] that are not placeholders (for example `nn` in `{nn}`), or an empty list. A lone
     * brace is text, not a placeholder. Does not throw.
     */
    public fun unknownPlaceholders(template: String): List<String> =
        PLACEHOLDER.findAll(template).map { it.groupValues[1] }.filter { it !in PLACEHOLDERS }.distinct().toList()

    /** [template] with every placeholder replaced for [stimulus] at 1-based [position]. Does not throw. */
    public fun fill(template: String, stimulus: Stimulus, position: Int): String =
        PLACEHOLDER.replace(template) { match ->
            when (match.groupValues[1]) {
                "n" -> (stimulus.number ?: position).toString()
                "label" -> stimulus.label.orEmpty()
                "icon" -> stimulus.icon.name
                "text" -> stimulus.text.orEmpty()
                "sticker" -> stimulus.sticker.orEmpty()
                else -> match.value
            }
        }
}
