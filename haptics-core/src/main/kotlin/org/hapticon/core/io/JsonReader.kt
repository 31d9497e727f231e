package org.hapticon.core.io

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import java.util.Locale

/**
 * A strict RFC 8259 recursive-descent parser over one string, building kotlinx-serialization [JsonElement]s (the
 * one JSON tree of the project).
 *
 * Why it exists beside kotlinx's own parser: kotlinx keeps the last of duplicate member names without a word
 * (`JsonTreeReader`: `result[key] = element`) and its maintainers declined an option to refuse them
 * (Kotlin/kotlinx.serialization#1990, "we would prefer not to introduce such a feature"); kotlinx 1.12.0's
 * `JsonBuilder` still has none. Our formats refuse duplicates (parsers disagree on which wins, so one document
 * could mean two things), reject unpaired surrogates and report the offset of the offending character
 * ([JsonException.offset]). This is a strictness requirement, not a speed one.
 *
 * Recursion is bounded by [maxDepth] (at most [Json.MAX_DEPTH_LIMIT]), so hostile nesting fails with a
 * [JsonException] instead of a StackOverflowError. Every loop advances [pos], so it cannot hang.
 */
internal class JsonReader(
    private val text: String,
    private val maxDepth: Int,
    // Apple's own AHAP samples end lists with a comma; RFC 8259 does not allow it, so only callers that read such files opt in.
    private val allowTrailingCommas: Boolean = false,
) {
    private var pos = 0

    fun readDocument(): JsonElement {
        skipWhitespace()
        val value = readValue(depth = 0)
        skipWhitespace()
        if (pos < text.length) fail("unexpected ${describe(text[pos])} after the JSON value")
        return value
    }

    private fun readValue(depth: Int): JsonElement {
        if (pos >= text.length) fail("unexpected end of input, expected a value")
        return when (val c = text[pos]) {
            '{' -> readObject(depth + 1)
            '[' -> readArray(depth + 1)
            '"' -> JsonPrimitive(readString())
            't' -> readLiteral("true", TRUE)
            'f' -> readLiteral("false", FALSE)
            'n' -> readLiteral("null", JsonNull)
            '-', in '0'..'9' -> readNumber()
            else -> fail("unexpected ${describe(c)}, expected a value")
        }
    }

    private fun readObject(depth: Int): JsonObject {
        checkDepth(depth)
        pos++ // '{'
        val members = LinkedHashMap<String, JsonElement>()
        skipWhitespace()
        if (peek() == '}') {
            pos++
            return JsonObject(members)
        }
        while (true) {
            skipWhitespace()
            if (peek() != '"') failExpected("a member name in double quotes")
            val nameOffset = pos
            val name = readString()
            skipWhitespace()
            if (peek() != ':') failExpected("':'")
            pos++
            skipWhitespace()
            // Duplicate names are legal but ambiguous (parsers disagree on which wins), so refuse them.
            if (members.put(name, readValue(depth)) != null) fail("duplicate member name ${snippet(JsonPrimitive(name))}", nameOffset)
            skipWhitespace()
            when (peek()) {
                ',' -> if (trailingCommaBefore('}')) return JsonObject(members)
                '}' -> {
                    pos++
                    return JsonObject(members)
                }
                else -> failExpected("',' or '}'")
            }
        }
    }

    private fun readArray(depth: Int): JsonArray {
        checkDepth(depth)
        pos++ // '['
        val elements = ArrayList<JsonElement>()
        skipWhitespace()
        if (peek() == ']') {
            pos++
            return JsonArray(elements)
        }
        while (true) {
            skipWhitespace()
            elements.add(readValue(depth))
            skipWhitespace()
            when (peek()) {
                ',' -> if (trailingCommaBefore(']')) return JsonArray(elements)
                ']' -> {
                    pos++
                    return JsonArray(elements)
                }
                else -> failExpected("',' or ']'")
            }
        }
    }

    /** Reads a string starting at its opening quote; rejects control characters and unpaired surrogates. */
    private fun readString(): String {
        pos++ // opening quote
        val start = pos
        var builder: StringBuilder? = null // only needed once an escape appears
        var expectLowSurrogate = false
        while (true) {
            if (pos >= text.length) fail("unterminated string", start - 1)
            val c = text[pos]
            val decoded: Char
            val charOffset = pos
            when {
                c == '"' -> {
                    if (expectLowSurrogate) fail("unpaired surrogate in string", pos)
                    pos++
                    return builder?.toString() ?: text.substring(start, pos - 1)
                }
                c == '\\' -> {
                    if (builder == null) builder = StringBuilder().append(text, start, pos)
                    decoded = readEscape()
                }
                c < ' ' -> fail("unescaped control character ${describe(c)} in string")
                else -> {
                    decoded = c
                    pos++
                }
            }
            if (expectLowSurrogate != decoded.isLowSurrogate()) fail("unpaired surrogate in string", charOffset)
            expectLowSurrogate = decoded.isHighSurrogate()
            builder?.append(decoded)
        }
    }

    private fun readEscape(): Char {
        pos++ // backslash
        if (pos >= text.length) fail("unterminated escape")
        val c = text[pos++]
        return when (c) {
            '"' -> '"'
            '\\' -> '\\'
            '/' -> '/'
            'b' -> '\b'
            'f' -> '\u000C'
            'n' -> '\n'
            'r' -> '\r'
            't' -> '\t'
            'u' -> readHex4()
            else -> fail("invalid escape ${describe(c)}", pos - 1)
        }
    }

    private fun readHex4(): Char {
        if (pos + 4 > text.length) fail("unterminated \\u escape")
        var code = 0
        repeat(4) {
            val digit = Character.digit(text[pos], 16)
            if (digit < 0) fail("invalid hex digit ${describe(text[pos])} in \\u escape")
            code = code * 16 + digit
            pos++
        }
        return code.toChar()
    }

    private fun readNumber(): JsonPrimitive {
        val start = pos
        val negative = peek() == '-'
        if (negative) pos++
        // The digits are gathered into a mantissa on the way, so that short literals (nearly all of them)
        // can skip the slower general conversion below.
        var mantissa = 0L
        var significantDigits = 0
        var fractionDigits = 0
        var fitsMantissa = true
        fun gather(digit: Int) {
            if (significantDigits >= MAX_MANTISSA_DIGITS) {
                fitsMantissa = false
                return
            }
            mantissa = mantissa * 10 + digit
            if (mantissa != 0L) significantDigits++
        }
        when (peek()) {
            '0' -> {
                pos++
                if (peek() in '0'..'9') fail("leading zeros are not allowed")
            }
            in '1'..'9' -> while (peek() in '0'..'9') gather(text[pos++] - '0')
            else -> failExpected("a digit")
        }
        var isIntegral = true
        if (peek() == '.') {
            isIntegral = false
            pos++
            if (peek() !in '0'..'9') failExpected("a digit after '.'")
            while (peek() in '0'..'9') {
                gather(text[pos++] - '0')
                fractionDigits++
            }
        }
        var exponent = 0
        if (peek() == 'e' || peek() == 'E') {
            isIntegral = false
            pos++
            val exponentNegative = peek() == '-'
            if (peek() == '+' || peek() == '-') pos++
            if (peek() !in '0'..'9') failExpected("a digit in the exponent")
            while (peek() in '0'..'9') {
                val digit = text[pos++] - '0'
                if (exponent < 100_000) exponent = exponent * 10 + digit // beyond that only the slow path applies
            }
            if (exponentNegative) exponent = -exponent
        }
        // Clinger's fast path: a mantissa below 2^53 and a power of ten up to 1e22 are exact doubles, so a
        // single multiplication or division gives the correctly rounded value, as the general conversion would.
        val scale = exponent - fractionDigits
        if (fitsMantissa && mantissa <= MAX_EXACT_MANTISSA && scale in -MAX_EXACT_POWER..MAX_EXACT_POWER) {
            val magnitude = if (scale >= 0) mantissa * EXACT_POWERS_OF_TEN[scale] else mantissa / EXACT_POWERS_OF_TEN[-scale]
            return number(if (negative) -magnitude else magnitude, isIntegral)
        }
        // Overlong literals such as 1e400 become ±infinity here; callers decide whether that is acceptable.
        return number(text.substring(start, pos).toDouble(), isIntegral)
    }

    /**
     * A literal without fraction or exponent stays an integer (`3`, and `-0` becomes `0`), as a `Long` while it
     * fits; anything else is a double (`3.0`, `3e0` → `3.0`; `1e400` → `Infinity`, kept so that the schema check
     * can name the member). The content is what kotlinx decodes and what [SchemaJson.check] inspects.
     */
    private fun number(value: Double, isIntegral: Boolean): JsonPrimitive =
        if (isIntegral && Math.abs(value) < 9.2E18) JsonPrimitive(value.toLong()) else JsonPrimitive(value)

    private fun readLiteral(literal: String, value: JsonElement): JsonElement {
        if (!text.startsWith(literal, pos)) fail("invalid literal, expected '$literal'")
        pos += literal.length
        return value
    }

    // Consumes a ',' and, when trailing commas are allowed and [close] follows, the closer too (returns true).
    private fun trailingCommaBefore(close: Char): Boolean {
        pos++
        skipWhitespace()
        if (!allowTrailingCommas || peek() != close) return false
        pos++
        return true
    }

    private fun skipWhitespace() {
        while (pos < text.length) {
            when (text[pos]) {
                ' ', '\t', '\n', '\r' -> pos++
                else -> return
            }
        }
    }

    /** The character at [pos], or a NUL sentinel at the end (NUL is never valid outside strings). */
    private fun peek(): Char = if (pos < text.length) text[pos] else '\u0000'

    private fun checkDepth(depth: Int) {
        if (depth > maxDepth) fail("nesting deeper than $maxDepth levels")
    }

    private fun failExpected(what: String): Nothing =
        if (pos >= text.length) fail("unexpected end of input, expected $what")
        else fail("unexpected ${describe(text[pos])}, expected $what")

    private fun fail(message: String, offset: Int = pos): Nothing = throw JsonException(message, offset)

    private companion object {
        const val MAX_MANTISSA_DIGITS = 18 // 10^18 − 1 still fits a Long
        const val MAX_EXACT_MANTISSA = 1L shl 53
        const val MAX_EXACT_POWER = 22
        val EXACT_POWERS_OF_TEN = DoubleArray(MAX_EXACT_POWER + 1) { "1e$it".toDouble() }
        val TRUE = JsonPrimitive(true)
        val FALSE = JsonPrimitive(false)
    }
}

/** A character for an error message: `'x'` when printable ASCII, `U+0001` style otherwise. */
private fun describe(c: Char): String =
    if (c in ' '..'~') "'$c'" else String.format(Locale.ROOT, "U+%04X", c.code)
