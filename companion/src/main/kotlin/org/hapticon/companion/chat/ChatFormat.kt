package org.hapticon.companion.chat

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import java.util.Locale

/** How the terminal chat shows messages, icons and capabilities. Pure functions, so tests pin the wording. */
object ChatFormat {
    /**
     * `bob: hello [sticker hug] [icon knock: …]`, with [message]'s text made safe for a terminal. A text of several
     * lines continues under its sender, each further line starting with spaces as wide as the name and `│ `, so no
     * line a peer writes can start at the left edge and pass for another sender's message or for the chat's own news:
     * ```
     * bob: first line
     *    │ alice: not alice
     * ```
     */
    fun message(message: ChatMessage): String = buildString {
        append(message.sender).append(':')
        if (message.text.isNotEmpty()) {
            append(' ').append(terminalSafe(message.text).replace("\n", "\n" + " ".repeat(message.sender.length) + CONTINUATION))
        }
        message.sticker?.let { append(" [sticker ").append(it).append(']') }
        message.icon?.let { append(" [").append(icon(it)).append(']') }
        message.pattern?.let { append(" [").append(pattern(it)).append(']') }
    }

    /** What starts each further line of a message, after spaces as wide as the sender's name. */
    const val CONTINUATION: String = "│ "

    /** A pattern's name and shape, e.g. `pattern boing: 0.400 s, 3 amplitude keys, 110.0–220.0 Hz, 1 transient`. */
    fun pattern(pattern: HapticPattern): String = String.format(
        Locale.ROOT, "pattern %s: %.3f s, %d amplitude keys, %.1f–%.1f Hz, %d transient%s",
        oneLine(pattern.name), pattern.duration, pattern.amplitude.size, pattern.frequency.minOf { it.hertz },
        pattern.frequency.maxOf { it.hertz }, pattern.transients.size, if (pattern.transients.size == 1) "" else "s",
    )

    /**
     * An icon's name and parameters, e.g. `icon knock: attack 0.005 s, sustain 0.01 s, release 0.005 s,
     * level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s`.
     */
    fun icon(icon: HapticIcon): String {
        val repeats = if (icon.count > 1) ", ${icon.count}× every ${number(icon.period)} s" else ""
        return String.format(
            Locale.ROOT, "icon %s: attack %s s, sustain %s s, release %s s, level %s, note %s (%.1f Hz)%s, %.3f s",
            oneLine(icon.name), number(icon.attack), number(icon.sustain), number(icon.release), number(icon.level),
            number(icon.note), icon.frequency, repeats, icon.duration,
        )
    }

    /** `bob's device: amplitude waveform, amplitude control, Android API 34, resonance 170.0 Hz`. */
    fun capabilities(capabilities: Capabilities): String = buildString {
        append(capabilities.user).append("'s device: ")
        append(
            when (capabilities.renderer) {
                RendererKind.AUDIO_COUPLED -> "audio-coupled haptics"
                RendererKind.ENVELOPE -> "envelope effect"
                RendererKind.AMPLITUDE_WAVEFORM -> "amplitude waveform"
                RendererKind.ON_OFF -> "on/off vibration"
                RendererKind.AUDIO -> "audio only"
                RendererKind.NONE -> "no haptics"
                RendererKind.UNKNOWN -> "unknown renderer"
            },
        )
        if (capabilities.amplitudeControl) append(", amplitude control")
        capabilities.apiLevel?.let { append(", Android API ").append(it) }
        capabilities.resonantFrequencyHz?.let { append(String.format(Locale.ROOT, ", resonance %.1f Hz", it)) }
    }

    /**
     * [text] with control characters (other than line breaks and tabs) and bidirectional overrides shown as
     * `\uXXXX`, so a received message cannot move the cursor, clear the screen, retitle the terminal or
     * disguise its text.
     */
    fun terminalSafe(text: String): String = escape(text) { unsafeInTerminal(it) }

    /**
     * [text] for a place that must stay one line (an icon's name, the `wrote ….wav` line, a rejection's detail): like
     * [terminalSafe], and line breaks and tabs shown as `\u000a` and `\u0009` too.
     */
    fun oneLine(text: String): String = escape(text) { it == '\n' || it == '\t' || unsafeInTerminal(it) }

    private inline fun escape(text: String, unsafe: (Char) -> Boolean): String = buildString(text.length) {
        for (c in text) {
            if (unsafe(c)) {
                append(String.format(Locale.ROOT, "\\u%04x", c.code))
            } else {
                append(c)
            }
        }
    }

    // Control characters drive the terminal (ESC starts every escape sequence); bidirectional overrides
    // reorder what is shown; line and paragraph separators break lines in some terminals.
    private fun unsafeInTerminal(c: Char): Boolean =
        (Character.isISOControl(c) && c != '\n' && c != '\t') || c.code in 0x2028..0x2029 || c.code in 0x202A..0x202E || c.code in 0x2066..0x2069

    /** [name] reduced to letters, digits, `-` and `_` for a file name (an icon's name is any text). */
    fun fileSafe(name: String): String = name.replace(Regex("[^A-Za-z0-9_-]"), "_").take(40).ifEmpty { "icon" }

    private fun number(value: Double): String =
        if (value == Math.rint(value) && Math.abs(value) < 1e9) value.toLong().toString() else value.toString()
}
