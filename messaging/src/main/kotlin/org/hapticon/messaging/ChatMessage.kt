package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import java.util.Locale
import java.util.UUID

/** What arrives in a user's inbox: a [ChatMessage], a [Receipt] or a [HandPose]. */
public sealed interface InboxPayload

/**
 * A chat message: text, optionally a sticker and a haptic icon, which travels by value.
 *
 * A value is always valid: the constructor throws [InvalidMessageException] naming the first bad field, so
 * every message encodes within [MessageLimits] and a decoded one has passed the same checks.
 *
 * @property id a UUID in canonical lower-case form; a message takes effect once per id.
 * @property sender the user who wrote it (see [Topics.isValidUserName]). Self-declared: MQTT 3.1.1 does not
 *   tell a receiver who published, so a broker ACL cannot vouch for it.
 * @property sentAtMillis when it was composed, in milliseconds since the epoch (the sender's clock).
 * @property text at most [MessageLimits.MAX_TEXT_LENGTH] code points; may be empty when there is a sticker or icon.
 * @property sticker a sticker name such as `hug` (lower-case letters, digits, `_`, `-`), or null.
 * @property icon the haptic icon to feel, at most [MessageLimits.MAX_ICON_PLAYBACK_SECONDS] long, or null.
 * @property pattern a haptic pattern to feel instead of an icon (an imported AHAP or `.haptic`, say): at most
 *   [MessageLimits.MAX_ICON_PLAYBACK_SECONDS] long with at most [MessageLimits.MAX_PATTERN_KEYS] keys and taps,
 *   or null. A message carries an icon or a pattern, not both; one with a pattern travels as version 2
 *   ([MessageCodec]), which older builds reject with a clear "unsupported version" instead of playing it wrong.
 */
public data class ChatMessage(
    val id: String,
    val sender: String,
    val sentAtMillis: Long,
    val text: String,
    val sticker: String? = null,
    val icon: HapticIcon? = null,
    val pattern: HapticPattern? = null,
) : InboxPayload {
    init {
        check(UUID_FORM.matches(id), RejectionReason.INVALID_VALUE, "id") { "expected a lower-case UUID, got ${quote(id)}" }
        check(Topics.isValidUserName(sender), RejectionReason.INVALID_VALUE, "sender") { "not a valid user name: ${quote(sender)}" }
        checkTimestamp(sentAtMillis, "sentAt")
        // Counting code points costs a pass over the text; the UTF-16 length bounds them from above and below.
        val tooLong = text.length > MessageLimits.MAX_TEXT_LENGTH &&
            (text.length > 2 * MessageLimits.MAX_TEXT_LENGTH || text.codePointCount(0, text.length) > MessageLimits.MAX_TEXT_LENGTH)
        check(!tooLong, RejectionReason.TEXT_TOO_LONG, "text") {
            "${text.codePointCount(0, text.length)} characters exceed the limit of ${MessageLimits.MAX_TEXT_LENGTH}"
        }
        checkEncodable(text, "text")
        if (sticker != null) {
            check(STICKER_FORM.matches(sticker), RejectionReason.INVALID_VALUE, "sticker") {
                "expected 1..${MessageLimits.MAX_STICKER_LENGTH} of a-z, 0-9, '_', '-', got ${quote(sticker)}"
            }
        }
        if (icon != null) {
            checkEncodable(icon.name, "icon.name")
            check(icon.duration <= MessageLimits.MAX_ICON_PLAYBACK_SECONDS, RejectionReason.ICON_TOO_LONG, "icon") {
                String.format(Locale.ROOT, "plays for %.3f s, more than the %.0f s a message may", icon.duration, MessageLimits.MAX_ICON_PLAYBACK_SECONDS)
            }
        }
        if (pattern != null) {
            check(icon == null, RejectionReason.INVALID_VALUE, "pattern") { "a message carries an icon or a pattern, not both" }
            checkEncodable(pattern.name, "pattern.name")
            val keys = pattern.amplitude.size + pattern.frequency.size + pattern.transients.size
            check(keys <= MessageLimits.MAX_PATTERN_KEYS, RejectionReason.INVALID_ICON, "pattern") {
                "has $keys keys and taps, more than the ${MessageLimits.MAX_PATTERN_KEYS} a message may"
            }
            check(pattern.duration <= MessageLimits.MAX_ICON_PLAYBACK_SECONDS, RejectionReason.ICON_TOO_LONG, "pattern") {
                String.format(Locale.ROOT, "plays for %.3f s, more than the %.0f s a message may", pattern.duration, MessageLimits.MAX_ICON_PLAYBACK_SECONDS)
            }
        }
        check(text.isNotBlank() || sticker != null || icon != null || pattern != null, RejectionReason.INVALID_VALUE, "text") {
            "a message needs text, a sticker, an icon or a pattern"
        }
    }

    public companion object {
        /**
         * A new message from [sender] with a random id, stamped with [clock]'s time. Throws
         * [InvalidMessageException] as the constructor does.
         */
        public fun compose(
            sender: String,
            text: String,
            sticker: String? = null,
            icon: HapticIcon? = null,
            clock: Clock = Clock.SYSTEM,
            pattern: HapticPattern? = null,
        ): ChatMessage = ChatMessage(UUID.randomUUID().toString(), sender, clock.nowMillis(), text, sticker, icon, pattern)
    }
}

/**
 * A receipt: [from] tells the original sender that message [messageId] reached the state [state] at
 * [atMillis]. Published into the original sender's inbox. A value is always valid: the constructor throws
 * [InvalidMessageException] naming the first bad field.
 *
 * @property messageId the id of the message this is about (a lower-case UUID).
 * @property from the user who received the message.
 * @property state how far the message got.
 * @property atMillis when, in milliseconds since the epoch (the receiver's clock).
 */
public data class Receipt(
    val messageId: String,
    val from: String,
    val state: ReceiptState,
    val atMillis: Long,
) : InboxPayload {
    init {
        check(UUID_FORM.matches(messageId), RejectionReason.INVALID_VALUE, "messageId") {
            "expected a lower-case UUID, got ${quote(messageId)}"
        }
        check(Topics.isValidUserName(from), RejectionReason.INVALID_VALUE, "from") { "not a valid user name: ${quote(from)}" }
        checkTimestamp(atMillis, "at")
    }
}

/** How far a message got, in order. */
public enum class ReceiptState(
    /** The value of the receipt's `state` member. */
    public val wireName: String,
) {
    /** Stored on the receiver's device. */
    DELIVERED("delivered"),

    /** Shown to the receiver. */
    READ("read"),

    /**
     * The receiver played the message's haptic icon (on arrival or by a press). Sent only for a
     * message with an icon, and only while the receiver lets it be sent (a setting, on by default).
     * An older client that does not know it rejects it as an unknown value and keeps the earlier state.
     */
    FELT("felt"),
}

internal val UUID_FORM = Regex("[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}")

private val STICKER_FORM = Regex("[a-z0-9_-]{1,${MessageLimits.MAX_STICKER_LENGTH}}")

internal inline fun check(ok: Boolean, reason: RejectionReason, field: String, detail: () -> String) {
    if (!ok) throw InvalidMessageException(reason, field, detail())
}

internal fun checkTimestamp(millis: Long, field: String) =
    check(millis in 0..MessageLimits.MAX_TIMESTAMP_MILLIS, RejectionReason.INVALID_VALUE, field) {
        "expected milliseconds since the epoch in 0..${MessageLimits.MAX_TIMESTAMP_MILLIS}, got $millis"
    }

// JSON (and UTF-8) cannot carry an unpaired surrogate; the decoder never produces one, but a caller could.
internal fun checkEncodable(text: String, field: String) {
    var i = 0
    while (i < text.length) {
        val c = text[i]
        if (Character.isHighSurrogate(c) && i + 1 < text.length && Character.isLowSurrogate(text[i + 1])) {
            i += 2
            continue
        }
        check(!Character.isSurrogate(c), RejectionReason.INVALID_VALUE, field) { "unpaired surrogate at index $i" }
        i++
    }
}

/** [text] quoted and cut to a snippet, for error details that must stay one short line. */
internal fun quote(text: String): String {
    val cut = if (text.length > 40) text.take(40) + "…" else text
    return "\"" + cut.replace(Regex("[\\p{Cntrl}\"\\\\]")) { "\\u%04x".format(it.value[0].code) } + "\""
}
