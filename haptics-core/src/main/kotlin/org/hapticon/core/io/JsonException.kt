package org.hapticon.core.io

/**
 * The text passed to [Json.decode] is not valid JSON, or exceeds a size or nesting limit.
 *
 * [offset] is the index of the offending character in the text (for [Json.decodeUtf8], in the
 * decoded text, or the byte index of a malformed UTF-8 sequence).
 */
public class JsonException(message: String, public val offset: Int) :
    IllegalArgumentException("$message at offset $offset")
