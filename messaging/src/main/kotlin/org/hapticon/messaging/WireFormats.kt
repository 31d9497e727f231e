package org.hapticon.messaging

import org.hapticon.core.io.HapticFormats

/**
 * Every schema name and version of the chat wire family, in one place: what [MessageCodec] writes and reads
 * and the sealed envelope of [org.hapticon.messaging.e2e.EndToEnd]. Icons and patterns travel inside messages
 * in their own file formats, whose versions live in [HapticFormats]; the study, gesture and sensor families keep
 * theirs in `StudyFormats`, `GestureFormats` and `SensorFormats` (docs/json.md lists every family).
 *
 * A build reads the versions it writes; a message carries the lowest version that can hold it, so a build
 * that predates patterns still reads every message without one (docs/messaging.md).
 */
public object WireFormats {
    /** `schema` of a chat message. */
    public const val MESSAGE_SCHEMA: String = "hapticon.message"

    /** `schema` of a receipt. */
    public const val RECEIPT_SCHEMA: String = "hapticon.receipt"

    /** `schema` of a tele-handshake sample. */
    public const val HAND_SCHEMA: String = "hapticon.hand"

    /** `schema` of a capabilities document. */
    public const val CAPABILITIES_SCHEMA: String = "hapticon.capabilities"

    /** `schema` of an end-to-end sealed payload (its version, 1, is part of the fixed form it is matched against). */
    public const val SEALED_SCHEMA: String = "hapticon.sealed"

    /** The version of receipts, poses, capabilities and messages without a pattern. */
    public const val VERSION: Int = 1

    /** The version of a message that carries a pattern; messages are read in versions [VERSION]..[PATTERN_MESSAGE_VERSION]. */
    public const val PATTERN_MESSAGE_VERSION: Int = 2

    /** The icon document embedded in a message's `icon` ([HapticFormats.ICON_SCHEMA], version [HapticFormats.ICON_VERSION]). */
    public const val EMBEDDED_ICON_SCHEMA: String = HapticFormats.ICON_SCHEMA

    /** The pattern document embedded in a message's `pattern` ([HapticFormats.PATTERN_SCHEMA], version [HapticFormats.PATTERN_VERSION]). */
    public const val EMBEDDED_PATTERN_SCHEMA: String = HapticFormats.PATTERN_SCHEMA
}
