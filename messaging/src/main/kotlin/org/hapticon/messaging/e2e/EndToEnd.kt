package org.hapticon.messaging.e2e

import org.hapticon.messaging.MessageLimits
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import java.io.ByteArrayOutputStream
import java.io.DataOutputStream
import java.security.GeneralSecurityException
import java.util.concurrent.ConcurrentHashMap

/**
 * End-to-end protection of inbox payloads, so that the broker and its operator can neither read nor forge
 * them: each payload is encrypted to the recipient's HPKE key and signed with the sender's Ed25519 key
 * (Tink `HybridEncrypt` and `PublicKeySign`), and the keys are pinned on first contact ([KeyPins]).
 *
 * The sealed payload is one JSON document, so that a client without this layer names it instead of calling it
 * garbage (its schema is unknown to it):
 * ```
 * {"schema":"hapticon.sealed","version":1,"keys":"<sender's KeyBundle>","ct":"<HPKE ciphertext>","sig":"<Ed25519 signature>"}
 * ```
 * (base64 values; [SealedDocument], written by kotlinx-serialization and read through the strict reader). The HPKE context info and the signed bytes both name sender and recipient, so a sealed
 * payload cannot be replayed into another conversation (or re-signed by someone else, the "surreptitious
 * forwarding" flaw of naive sign-and-encrypt: Davis, USENIX 2001). The sender's public keys travel in every
 * payload, so a first message verifies even before the sender's retained key (`hapticon/v1/keys/<user>`)
 * has arrived; after first contact only the pinned keys are accepted.
 *
 * Encrypt-then-sign, with one fresh HPKE encapsulation per payload; no forward secrecy beyond that (a stolen
 * private key opens every recorded payload sent to it): see docs/security.md.
 */
public class EndToEnd(
    /** This user's own keys. */
    public val identity: Identity,
    private val pins: KeyPins,
) {
    /** The user this protects. */
    public val user: String get() = identity.user

    // Keys that arrived for a user who already has a different pin: held until the user trusts them.
    private val changed = ConcurrentHashMap<String, KeyBundle>()

    /**
     * [plaintext] sealed for [recipient]. Throws [E2eException] when [recipient]'s key is not known yet (it
     * has never published one and never written to us) or the sealed form would exceed the payload limit.
     */
    public fun seal(recipient: String, plaintext: ByteArray): ByteArray {
        val to = pins.pinned(Topics.requireUserName(recipient))
            ?: throw E2eException("no key of $recipient yet: $recipient has not published one (an old client, or never connected with end-to-end encryption)")
        val ciphertext = to.encrypter.encrypt(plaintext, contextInfo(user, recipient))
        val keys = identity.bundle.encoded
        val signature = identity.signer.sign(signedBytes(user, recipient, keys, ciphertext))
        val sealed = SealedPayload(keys, ciphertext, signature).encode()
        if (sealed.size > MessageLimits.MAX_PAYLOAD_BYTES) {
            throw E2eException("sealed payload of ${sealed.size} bytes exceeds the limit of ${MessageLimits.MAX_PAYLOAD_BYTES}")
        }
        return sealed
    }

    /** Opens a payload that arrived on [sender]'s topic in this user's inbox. Never throws. */
    public fun open(sender: String, payload: ByteArray): Opened {
        val parts = parse(payload)
            ?: return Opened.Refused(RejectionReason.NOT_ENCRYPTED, "unencrypted payload from $sender refused: this client requires end-to-end encryption ($sender's client is old or runs without it)")
        val (keys, ciphertext, signature) = parts
        if (keys.isEmpty()) return Opened.Refused(RejectionReason.MALFORMED_JSON, "sealed payload from $sender is not in the sealed form")
        val bundle = try {
            KeyBundle.decode(keys)
        } catch (e: GeneralSecurityException) {
            return Opened.Refused(RejectionReason.FORGED, "sealed payload from $sender carries unusable keys: ${e.message}")
        }
        if (bundle.user != sender) {
            return Opened.Refused(RejectionReason.FORGED, "sealed payload on the topic of $sender carries the keys of ${bundle.user}")
        }
        try {
            bundle.verifier.verify(signature, signedBytes(sender, user, keys, ciphertext))
        } catch (e: GeneralSecurityException) {
            return Opened.Refused(RejectionReason.FORGED, "signature of $sender does not verify: forged or altered on the way")
        }
        when (val pinned = pins.pinned(sender)) {
            null -> pins.pin(bundle) // first contact: trust on first use
            bundle -> Unit
            else -> {
                changed[sender] = bundle
                return Opened.Refused(
                    RejectionReason.KEY_CHANGED,
                    "$sender's key changed (safety number now ${SafetyNumber.of(identity.bundle, bundle)}, was ${SafetyNumber.of(identity.bundle, pinned)}); " +
                        "message held back until you trust the new key",
                )
            }
        }
        return try {
            Opened.Plain(identity.decrypter.decrypt(ciphertext, contextInfo(sender, user)))
        } catch (e: GeneralSecurityException) {
            Opened.Refused(RejectionReason.UNDECRYPTABLE, "cannot decrypt the payload from $sender: it was sealed for another key of $user (new keys here since $sender pinned them?)")
        }
    }

    /**
     * A key bundle retained on `hapticon/v1/keys/[owner]`: pinned on first contact; a bundle that differs
     * from the pin is held as changed (see [trust]). Never throws.
     */
    public fun learn(owner: String, encoded: ByteArray): KeyNews {
        val bundle = try {
            KeyBundle.decode(encoded)
        } catch (e: GeneralSecurityException) {
            return KeyNews.Invalid("unusable key of $owner: ${e.message}")
        }
        if (bundle.user != owner) return KeyNews.Invalid("the key topic of $owner holds the keys of ${bundle.user}")
        return when (val pinned = pins.pinned(owner)) {
            null -> KeyNews.Pinned(bundle).also { pins.pin(bundle) }
            bundle -> KeyNews.Unchanged
            else -> KeyNews.Changed(bundle, SafetyNumber.of(identity.bundle, bundle), SafetyNumber.of(identity.bundle, pinned)).also { changed[owner] = bundle }
        }
    }

    /** The changed key of [user] waiting for [trust], or null. */
    public fun changedKey(user: String): KeyBundle? = changed[user]

    /**
     * Accepts [user]'s changed key (after comparing safety numbers): pins it and returns it, or returns null
     * when no changed key is waiting. Messages the sender's outbox sends again are accepted from then on.
     */
    public fun trust(user: String): KeyBundle? = changed.remove(user)?.also(pins::pin)

    /**
     * Whether a key of [peer] is known (pinned): it published one, or wrote to us. A messenger that read the retained
     * keys (`hapticon/v1/keys/+`, on every connection) knows every user who ever published; false for anyone else means
     * nothing can be sealed for [peer] yet.
     */
    public fun hasKeyOf(peer: String): Boolean = pins.pinned(peer) != null

    /** The safety number of this user and [peer]'s pinned key, or null before first contact. */
    public fun safetyNumber(peer: String): String? = pins.pinned(peer)?.let { SafetyNumber.of(identity.bundle, it) }

    public companion object {
        /** `schema` of a sealed payload. */
        public const val SCHEMA: String = org.hapticon.messaging.WireFormats.SEALED_SCHEMA

        /** True when [payload] looks sealed (the schema is named), whether or not it opens. */
        public fun looksSealed(payload: ByteArray): Boolean =
            String(payload, 0, minOf(payload.size, 40), Charsets.ISO_8859_1).startsWith("{\"schema\":\"$SCHEMA\"")

        // Null for a payload that is not sealed at all; empty parts for one that names the schema but is not in the
        // sealed form (refused as malformed below).
        private fun parse(payload: ByteArray): Triple<ByteArray, ByteArray, ByteArray>? {
            if (!looksSealed(payload)) return null
            val sealed = SealedPayload.decode(payload) ?: return Triple(ByteArray(0), ByteArray(0), ByteArray(0))
            return Triple(sealed.keys, sealed.ciphertext, sealed.signature)
        }

        private fun contextInfo(sender: String, recipient: String): ByteArray = "$SCHEMA/1 $sender>$recipient".toByteArray(Charsets.UTF_8)

        private fun signedBytes(sender: String, recipient: String, keys: ByteArray, ciphertext: ByteArray): ByteArray =
            ByteArrayOutputStream().also { bytes ->
                DataOutputStream(bytes).apply {
                    for (field in listOf("$SCHEMA/1".toByteArray(), sender.toByteArray(), recipient.toByteArray(), keys, ciphertext)) {
                        writeInt(field.size)
                        write(field)
                    }
                }
            }.toByteArray()
    }
}

/** What [EndToEnd.open] made of a payload. */
public sealed interface Opened {
    /** The payload verified and decrypted to [plaintext]. */
    public class Plain(public val plaintext: ByteArray) : Opened

    /** The payload was refused; [detail] is one line for people. */
    public data class Refused(val reason: RejectionReason, val detail: String) : Opened
}

/** What [EndToEnd.learn] made of a published key. */
public sealed interface KeyNews {
    /** First contact: [bundle] is now pinned. */
    public data class Pinned(val bundle: KeyBundle) : KeyNews

    /** The same key as pinned. */
    public data object Unchanged : KeyNews

    /** A key other than the pinned one, held until trusted; the safety numbers with it and with the pinned key. */
    public data class Changed(val bundle: KeyBundle, val newSafetyNumber: String, val pinnedSafetyNumber: String) : KeyNews

    /** Not a usable key; [detail] says why. */
    public data class Invalid(val detail: String) : KeyNews
}

/** End-to-end protection cannot seal a payload; [message] says why in one line. */
public class E2eException(message: String) : Exception(message)
