package org.hapticon.messaging.e2e

import com.google.crypto.tink.HybridEncrypt
import com.google.crypto.tink.KeysetHandle
import com.google.crypto.tink.PublicKeyVerify
import com.google.crypto.tink.RegistryConfiguration
import com.google.crypto.tink.TinkProtoKeysetFormat
import com.google.crypto.tink.hybrid.HybridConfig
import com.google.crypto.tink.hybrid.PredefinedHybridParameters
import com.google.crypto.tink.signature.PredefinedSignatureParameters
import com.google.crypto.tink.signature.SignatureConfig
import org.hapticon.messaging.Topics
import java.io.ByteArrayOutputStream
import java.io.DataInputStream
import java.io.DataOutputStream
import java.io.EOFException
import java.security.GeneralSecurityException
import java.security.MessageDigest

/** Registers the key managers [RegistryConfiguration] hands out, once (Tink's documented set-up). */
internal object TinkSetup {
    init {
        HybridConfig.register()
        SignatureConfig.register()
    }

    fun ensure() = Unit
}

/**
 * A user's public keys for end-to-end protection: an HPKE key that others encrypt to (RFC 9180,
 * DHKEM(X25519, HKDF-SHA256), HKDF-SHA256, AES-128-GCM: Tink's `HPKE_X25519_HKDF_SHA256_AES_128_GCM`) and an
 * Ed25519 key that checks what the user signs (Tink's `ED25519`). Each is a Tink public keyset of exactly one
 * key of exactly these parameters: a bundle naming any other algorithm is refused, so nobody can downgrade a
 * conversation to a weaker one.
 *
 * [encoded] is the form that travels (on `hapticon/v1/keys/<user>` and inside every sealed payload) and is
 * pinned; two bundles are equal when their encodings are.
 */
public class KeyBundle private constructor(
    /** The user these keys belong to. */
    public val user: String,
    internal val encryptionKeyset: ByteArray,
    internal val signatureKeyset: ByteArray,
) {
    /** Version byte, then user, HPKE public keyset and Ed25519 public keyset, each length-prefixed. */
    public val encoded: ByteArray = ByteArrayOutputStream().also { bytes ->
        DataOutputStream(bytes).apply {
            writeByte(FORMAT_VERSION)
            writeField(user.toByteArray(Charsets.UTF_8))
            writeField(encryptionKeyset)
            writeField(signatureKeyset)
        }
    }.toByteArray()

    internal val encrypter: HybridEncrypt
    internal val verifier: PublicKeyVerify

    init {
        TinkSetup.ensure()
        Topics.requireUserName(user)
        val encryption = parseOne(encryptionKeyset, "encryption")
        if (encryption.primary.key.parameters != PredefinedHybridParameters.HPKE_X25519_HKDF_SHA256_AES_128_GCM) {
            throw GeneralSecurityException("the encryption key of $user is not HPKE X25519/HKDF-SHA256/AES-128-GCM")
        }
        val signature = parseOne(signatureKeyset, "signing")
        if (signature.primary.key.parameters != PredefinedSignatureParameters.ED25519) {
            throw GeneralSecurityException("the signing key of $user is not Ed25519")
        }
        encrypter = encryption.getPrimitive(RegistryConfiguration.get(), HybridEncrypt::class.java)
        verifier = signature.getPrimitive(RegistryConfiguration.get(), PublicKeyVerify::class.java)
    }

    /** SHA-256 of [encoded]. */
    public val fingerprint: ByteArray get() = MessageDigest.getInstance("SHA-256").digest(encoded)

    override fun equals(other: Any?): Boolean = other is KeyBundle && encoded.contentEquals(other.encoded)

    override fun hashCode(): Int = encoded.contentHashCode()

    override fun toString(): String = "KeyBundle($user, ${fingerprint.take(4).joinToString("") { "%02x".format(it) }}…)"

    public companion object {
        private const val FORMAT_VERSION = 1

        // Largest keyset we accept: ours are about 100 bytes; the cap keeps a hostile bundle from costing much.
        private const val MAX_FIELD_BYTES = 1024

        /** The bundle of [user] made from two Tink public keysets. Throws [GeneralSecurityException] for anything but one HPKE and one Ed25519 key. */
        internal fun of(user: String, encryption: KeysetHandle, signature: KeysetHandle): KeyBundle = KeyBundle(
            user,
            TinkProtoKeysetFormat.serializeKeysetWithoutSecret(encryption),
            TinkProtoKeysetFormat.serializeKeysetWithoutSecret(signature),
        )

        /** Reads [encoded]; throws [GeneralSecurityException] with a one-line reason when it is not a valid bundle. */
        public fun decode(encoded: ByteArray): KeyBundle {
            try {
                DataInputStream(encoded.inputStream()).run {
                    val version = readUnsignedByte()
                    if (version != FORMAT_VERSION) throw GeneralSecurityException("key bundle version $version, expected $FORMAT_VERSION")
                    val user = String(readField(), Charsets.UTF_8)
                    if (!Topics.isValidUserName(user)) throw GeneralSecurityException("key bundle of an invalid user name")
                    val bundle = KeyBundle(user, readField(), readField())
                    if (available() != 0) throw GeneralSecurityException("key bundle has ${available()} bytes too many")
                    return bundle
                }
            } catch (e: EOFException) {
                throw GeneralSecurityException("key bundle cut short")
            }
        }

        private fun parseOne(keyset: ByteArray, what: String): KeysetHandle {
            val handle = TinkProtoKeysetFormat.parseKeysetWithoutSecret(keyset)
            if (handle.size() != 1) throw GeneralSecurityException("the $what keyset holds ${handle.size()} keys, expected 1")
            return handle
        }

        private fun DataOutputStream.writeField(bytes: ByteArray) {
            writeShort(bytes.size)
            write(bytes)
        }

        private fun DataInputStream.readField(): ByteArray {
            val size = readUnsignedShort()
            if (size > MAX_FIELD_BYTES) throw GeneralSecurityException("key bundle field of $size bytes exceeds $MAX_FIELD_BYTES")
            return ByteArray(size).also(::readFully)
        }
    }
}
