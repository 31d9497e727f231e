package org.hapticon.core.io

import java.math.BigDecimal
import java.util.Locale

/**
 * Writes [JsonValue]s as JSON text into a [StringBuilder], compact when [indent] is empty and one member
 * or element per line otherwise.
 */
internal class JsonWriter(private val out: StringBuilder, private val indent: String) {
    init {
        require(indent.all { it == ' ' || it == '\t' }) { "indent must be spaces or tabs only" }
    }

    fun write(value: JsonValue, depth: Int = 0) {
        when (value) {
            is JsonObject -> writeContainer('{', '}', value.members.entries, depth) { (name, member) ->
                writeString(name)
                out.append(if (indent.isEmpty()) ":" else ": ")
                write(member, depth + 1)
            }
            is JsonArray -> writeContainer('[', ']', value.elements, depth) { write(it, depth + 1) }
            is JsonString -> writeString(value.value)
            is JsonNumber -> out.append(formatNumber(value))
            is JsonBoolean -> out.append(if (value.value) "true" else "false")
            JsonNull -> out.append("null")
        }
    }

    private inline fun <T> writeContainer(open: Char, close: Char, items: Collection<T>, depth: Int, writeItem: (T) -> Unit) {
        // The parser never builds deeper values; a hand-built one must not overflow the stack either.
        require(depth < Json.MAX_DEPTH_LIMIT) { "nesting deeper than ${Json.MAX_DEPTH_LIMIT} levels" }
        out.append(open)
        var first = true
        for (item in items) {
            if (!first) out.append(',')
            first = false
            newline(depth + 1)
            writeItem(item)
        }
        if (!first) newline(depth)
        out.append(close)
    }

    private fun newline(depth: Int) {
        if (indent.isEmpty()) return
        out.append('\n')
        repeat(depth) { out.append(indent) }
    }

    private fun writeString(value: String) {
        out.append('"')
        var runStart = 0 // characters that need no escape are appended in runs
        for (i in value.indices) {
            val c = value[i]
            val escape = when {
                c == '"' -> "\\\""
                c == '\\' -> "\\\\"
                c == '\n' -> "\\n"
                c == '\r' -> "\\r"
                c == '\t' -> "\\t"
                c == '\b' -> "\\b"
                c == '\u000C' -> "\\f"
                // U+2028/2029 are legal JSON but end lines in JavaScript, so embedded JSON would break.
                c < ' ' || c == '\u2028' || c == '\u2029' -> String.format(Locale.ROOT, "\\u%04x", c.code)
                c.isHighSurrogate() -> {
                    require(i + 1 < value.length && value[i + 1].isLowSurrogate()) { "unpaired surrogate at index $i" }
                    null
                }
                c.isLowSurrogate() -> {
                    require(i > 0 && value[i - 1].isHighSurrogate()) { "unpaired surrogate at index $i" }
                    null
                }
                else -> null
            }
            if (escape != null) {
                out.append(value, runStart, i).append(escape)
                runStart = i + 1
            }
        }
        out.append(value, runStart, value.length).append('"')
    }
}

/**
 * Integral numbers are written as plain integers, others with [Double.toString], whose output is valid JSON
 * and parses back to the identical double.
 */
private fun formatNumber(number: JsonNumber): String {
    val value = number.value
    require(value.isFinite()) { "JSON cannot represent $value" }
    return when {
        !number.isIntegral -> value.toString()
        value == 0.0 -> if (1.0 / value < 0) "-0" else "0"
        Math.abs(value) < 1e18 -> value.toLong().toString()
        else -> BigDecimal(value).toPlainString()
    }
}

/**
 * [value] as short JSON for an error message: at most about 40 characters, `…` marking a cut, and
 * non-finite numbers spelled out (they have no JSON form).
 */
internal fun snippet(value: JsonValue): String {
    if (value is JsonNumber && !value.value.isFinite()) {
        return if (value.value > 0) "a number too large for a double" else "a number too small for a double"
    }
    val text = StringBuilder()
    try {
        JsonWriter(text, indent = "").write(value)
    } catch (e: IllegalArgumentException) {
        return "an unencodable value" // only hand-built values get here; parsed ones always encode
    }
    return if (text.length <= 40) text.toString() else text.substring(0, 40) + "…"
}
