package org.hapticon.messaging

/**
 * Bounds on what a message may hold. Receivers check them before anything else is done with a payload,
 * so that a hostile or broken sender costs little; senders cannot build a message outside them.
 */
public object MessageLimits {
    /**
     * Largest payload accepted, in bytes, checked before parsing. Every valid message is smaller (4000
     * characters escaped as `\uXXXX` are 24000 bytes), so only hostile or broken payloads reach it.
     */
    public const val MAX_PAYLOAD_BYTES: Int = 64 * 1024

    /** Longest message text, in Unicode code points (what a user counts as characters, roughly). */
    public const val MAX_TEXT_LENGTH: Int = 4_000

    /**
     * Longest icon a message may carry, in seconds of playback. Below [org.hapticon.core.HapticIcon.MAX_DURATION_SECONDS]
     * (which bounds what any icon may be) because a chat message is a gesture, not a session: the longest
     * preset (stroke) lasts 10.8 s.
     */
    public const val MAX_ICON_PLAYBACK_SECONDS: Double = 15.0

    /**
     * Most keys and taps (amplitude + frequency keys + transients) in a message's pattern. Chosen so that the
     * largest valid message still fits [MAX_PAYLOAD_BYTES]: a tap written with 17-digit numbers takes about
     * 90 bytes, so 360 of them and a fully escaped 4000-character text stay under 64 KiB (MessageCodecTest).
     * Imported files may hold more ([org.hapticon.core.pattern.HapticPattern.MAX_KEYS]); sending one asks the
     * user to simplify it first.
     */
    public const val MAX_PATTERN_KEYS: Int = 360

    /** Longest sticker name. */
    public const val MAX_STICKER_LENGTH: Int = 32

    /** Deepest JSON nesting accepted; a message with an icon needs 2, one with a pattern 4. */
    public const val MAX_JSON_DEPTH: Int = 8

    /** Latest timestamp accepted: 9999-12-31T23:59:59.999Z, in milliseconds since the epoch. */
    public const val MAX_TIMESTAMP_MILLIS: Long = 253_402_300_799_999L
}
