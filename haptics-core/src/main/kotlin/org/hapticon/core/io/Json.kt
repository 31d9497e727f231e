package org.hapticon.core.io

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import java.nio.ByteBuffer
import java.nio.CharBuffer
import java.nio.charset.CodingErrorAction

/**
 * Strict JSON (RFC 8259) decoding into kotlinx-serialization [JsonElement]s; writing is kotlinx's
 * ([SchemaJson.encode], [SchemaJson.encodeElement]).
 *
 * Decoding is safe for hostile input: the text length and nesting depth are capped, malformed input
 * fails with a [JsonException] giving the character offset, duplicate member names and unpaired
 * surrogates are rejected, and nothing may follow the value. Why this reader and not kotlinx's: see
 * [JsonReader] (kotlinx keeps the last of duplicate names, Kotlin/kotlinx.serialization#1990).
 */
public object Json {
    /** Default cap on the input size, in characters for [decode] and bytes for [decodeUtf8]: 1 MiB. */
    public const val DEFAULT_MAX_LENGTH: Int = 1 shl 20

    /** Default cap on the number of nested objects and arrays. */
    public const val DEFAULT_MAX_DEPTH: Int = 64

    /** Largest nesting depth that may be requested; it keeps recursion far from the stack limit. */
    public const val MAX_DEPTH_LIMIT: Int = 512

    /**
     * Parses [text], which must hold exactly one JSON value (surrounding whitespace allowed).
     *
     * Throws [JsonException] when the text is malformed, longer than [maxLength] characters or nested
     * deeper than [maxDepth] objects and arrays; [IllegalArgumentException] when [maxLength] is negative
     * or [maxDepth] is outside 1..[MAX_DEPTH_LIMIT].
     */
    public fun decode(text: String, maxLength: Int = DEFAULT_MAX_LENGTH, maxDepth: Int = DEFAULT_MAX_DEPTH): JsonElement {
        checkLimits(maxLength, maxDepth)
        if (text.length > maxLength) {
            throw JsonException("input of ${text.length} characters exceeds the limit of $maxLength", maxLength)
        }
        return JsonReader(text, maxDepth).readDocument()
    }

    /**
     * Parses UTF-8 [bytes] (for example a message payload) like [decode]. [maxLength] counts bytes.
     *
     * Throws [JsonException] when the bytes are not valid UTF-8 (offset = byte index), when the text is
     * malformed or exceeds a limit (offset = character index); [IllegalArgumentException] for bad limits.
     */
    public fun decodeUtf8(bytes: ByteArray, maxLength: Int = DEFAULT_MAX_LENGTH, maxDepth: Int = DEFAULT_MAX_DEPTH): JsonElement =
        decodeUtf8(bytes, maxLength, maxDepth, allowTrailingCommas = false)

    /**
     * Like [decodeUtf8], but also accepts a comma before a closing `]` or `}` — a JSON5 liberty found in
     * files such as Apple's own AHAP samples. Everything else stays strict.
     */
    public fun decodeUtf8AllowingTrailingCommas(bytes: ByteArray, maxLength: Int = DEFAULT_MAX_LENGTH): JsonElement =
        decodeUtf8(bytes, maxLength, DEFAULT_MAX_DEPTH, allowTrailingCommas = true)

    internal fun decodeUtf8(bytes: ByteArray, maxLength: Int, maxDepth: Int, allowTrailingCommas: Boolean): JsonElement {
        checkLimits(maxLength, maxDepth)
        if (bytes.size > maxLength) {
            throw JsonException("input of ${bytes.size} bytes exceeds the limit of $maxLength", maxLength)
        }
        return JsonReader(decodeUtf8Strictly(bytes), maxDepth, allowTrailingCommas).readDocument()
    }

    private fun checkLimits(maxLength: Int, maxDepth: Int) {
        require(maxLength >= 0) { "maxLength must be >= 0, was $maxLength" }
        require(maxDepth in 1..MAX_DEPTH_LIMIT) { "maxDepth must be in 1..$MAX_DEPTH_LIMIT, was $maxDepth" }
    }

    // String(bytes, UTF_8) silently replaces each malformed sequence with U+FFFD, so its result is used only when it
    // holds no U+FFFD (then nothing was replaced, and it is exactly what the strict decoder gives); otherwise the strict
    // decoder runs and reports the offset (or accepts a U+FFFD that was in the input). String's own decoding is the
    // JDK's fast path; a CharsetDecoder per call was a few per cent of a chat message's decoding (docs/json.md).
    private fun decodeUtf8Strictly(bytes: ByteArray): String {
        val fast = String(bytes, Charsets.UTF_8)
        return if (fast.indexOf('\uFFFD') < 0) fast else decodeUtf8Reporting(bytes)
    }

    private fun decodeUtf8Reporting(bytes: ByteArray): String {
        val decoder = Charsets.UTF_8.newDecoder()
            .onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT)
        val input = ByteBuffer.wrap(bytes)
        val output = CharBuffer.allocate(bytes.size) // UTF-8 never yields more UTF-16 units than bytes
        val result = decoder.decode(input, output, true)
        if (result.isError) throw JsonException("malformed UTF-8", input.position())
        decoder.flush(output)
        output.flip()
        return output.toString()
    }
}

/**
 * [value] as short JSON for an error message: at most about 40 characters, `…` marking a cut, and
 * non-finite numbers spelled out (they have no JSON form; the reader keeps `1e400` as `Infinity`).
 */
internal fun snippet(value: JsonElement): String {
    if (value is JsonPrimitive && !value.isString && value.doubleOrNull?.isInfinite() == true) {
        return if (value.content.startsWith("-")) "a number too small for a double" else "a number too large for a double"
    }
    val text = SchemaJson.encodeElement(value)
    return if (text.length <= 40) text else text.substring(0, 40) + "…"
}
