package org.hapticon.messaging

/** Why a payload was not accepted. Every rejection carries one, for the caller to log or count. */
public enum class RejectionReason {
    /** The payload exceeds [MessageLimits.MAX_PAYLOAD_BYTES]; it was not parsed. */
    PAYLOAD_TOO_LARGE,

    /** The payload is not valid UTF-8 JSON, or nests deeper than [MessageLimits.MAX_JSON_DEPTH]. */
    MALFORMED_JSON,

    /** The JSON is valid but not an object. */
    NOT_AN_OBJECT,

    /** `schema` is missing or names a schema this topic does not carry. */
    UNKNOWN_SCHEMA,

    /** `version` is missing, not an integer, or not a version this build reads. */
    UNSUPPORTED_VERSION,

    /** A required member is missing. */
    MISSING_FIELD,

    /** A member has the wrong JSON type (a string where a number belongs, say). */
    WRONG_TYPE,

    /** A member has the right type but an impossible value: not finite, out of range, badly formed. */
    INVALID_VALUE,

    /** The text exceeds [MessageLimits.MAX_TEXT_LENGTH]. */
    TEXT_TOO_LONG,

    /** The icon is not a valid icon (the core's checks, including its 30 s safety cap). */
    INVALID_ICON,

    /** The icon is valid but would play longer than [MessageLimits.MAX_ICON_PLAYBACK_SECONDS]. */
    ICON_TOO_LONG,

    /** The payload arrived on a topic this client does not expect. */
    UNEXPECTED_TOPIC,

    /** End-to-end protection is on and the payload is not sealed (an old client, or one without it). */
    NOT_ENCRYPTED,

    /** The payload is sealed and this client has no end-to-end keys to open it. */
    ENCRYPTED,

    /** The sealed payload's signature does not verify, or its keys are not the topic's sender's: forged or altered. */
    FORGED,

    /** The sender's key differs from the one pinned on first contact; held back until the user trusts it. */
    KEY_CHANGED,

    /** The sealed payload verified but does not decrypt with this user's key. */
    UNDECRYPTABLE,

    /**
     * A retained message on an inbox topic: the broker would replay it at every subscription, and each replay would
     * earn its sender a delivered receipt (telling it when this user is online). Never shown, never acknowledged.
     */
    RETAINED,
}

/**
 * A value that breaks a rule of the message schema: thrown by the constructors of [ChatMessage],
 * [Receipt] and [Capabilities], and turned into [Decoded.Rejected] by [MessageCodec].
 *
 * @property reason the rule broken.
 * @property field the JSON member at fault, for example `text` or `icon.attack`.
 */
public class InvalidMessageException(
    public val reason: RejectionReason,
    public val field: String,
    detail: String,
) : IllegalArgumentException("$field: $detail")

/** The result of decoding an untrusted payload: [Accepted] or [Rejected]. Decoding never throws. */
public sealed interface Decoded<out T> {
    /** The payload held a valid [value]. */
    public data class Accepted<out T>(val value: T) : Decoded<T>

    /**
     * The payload was refused.
     *
     * @property reason why, for logs and counters.
     * @property field the JSON member at fault, or null when the payload as a whole is.
     * @property detail a one-line description for a log; it quotes at most a short snippet of the input.
     */
    public data class Rejected(val reason: RejectionReason, val field: String?, val detail: String) : Decoded<Nothing>
}
