package org.hapticon.messaging.e2e

import com.google.crypto.tink.Aead
import com.google.crypto.tink.HybridDecrypt
import com.google.crypto.tink.InsecureSecretKeyAccess
import com.google.crypto.tink.KeysetHandle
import com.google.crypto.tink.PublicKeySign
import com.google.crypto.tink.RegistryConfiguration
import com.google.crypto.tink.TinkProtoKeysetFormat
import com.google.crypto.tink.hybrid.PredefinedHybridParameters
import com.google.crypto.tink.signature.PredefinedSignatureParameters
import org.hapticon.messaging.Topics
import java.io.ByteArrayOutputStream
import java.io.DataInputStream
import java.io.DataOutputStream
import java.io.EOFException
import java.io.File
import java.nio.file.Files
import java.nio.file.StandardCopyOption
import java.nio.file.attribute.PosixFilePermissions
import java.security.GeneralSecurityException

/**
 * A user's own private keys: the HPKE key others encrypt to and the Ed25519 key this user signs with
 * (see [KeyBundle] for the algorithms). One per user and device; [bundle] is what others pin.
 *
 * [serialize] writes both private keysets either wrapped by an [Aead] (the app: a key in Android Keystore)
 * or in clear (the CLI: a mode-600 file, like an SSH key without passphrase), with Tink's own keyset
 * formats (`TinkProtoKeysetFormat`).
 */
public class Identity private constructor(
    /** The user these keys belong to. */
    public val user: String,
    private val encryption: KeysetHandle,
    private val signature: KeysetHandle,
) {
    /** The public half, as others pin it. */
    public val bundle: KeyBundle = KeyBundle.of(user, encryption.publicKeysetHandle, signature.publicKeysetHandle)

    internal val decrypter: HybridDecrypt = encryption.getPrimitive(RegistryConfiguration.get(), HybridDecrypt::class.java)
    internal val signer: PublicKeySign = signature.getPrimitive(RegistryConfiguration.get(), PublicKeySign::class.java)

    /**
     * Both private keysets in one blob: encrypted with [wrap] (associated data binds each to this user and
     * its role), or in clear when [wrap] is null.
     */
    public fun serialize(wrap: Aead?): ByteArray = ByteArrayOutputStream().also { bytes ->
        DataOutputStream(bytes).apply {
            writeByte(if (wrap == null) CLEAR else WRAPPED)
            for ((handle, role) in listOf(encryption to "encryption", signature to "signing")) {
                val keyset = if (wrap == null) {
                    TinkProtoKeysetFormat.serializeKeyset(handle, InsecureSecretKeyAccess.get())
                } else {
                    TinkProtoKeysetFormat.serializeEncryptedKeyset(handle, wrap, associatedData(user, role))
                }
                writeInt(keyset.size)
                write(keyset)
            }
        }
    }.toByteArray()

    public companion object {
        private const val CLEAR = 1
        private const val WRAPPED = 2
        private const val MAX_KEYSET_BYTES = 4096

        /** New keys for [user]. */
        public fun generate(user: String): Identity {
            TinkSetup.ensure()
            return Identity(
                Topics.requireUserName(user),
                KeysetHandle.generateNew(PredefinedHybridParameters.HPKE_X25519_HKDF_SHA256_AES_128_GCM),
                KeysetHandle.generateNew(PredefinedSignatureParameters.ED25519),
            )
        }

        /**
         * Reads what [serialize] wrote for [user]. Throws [GeneralSecurityException] when it is damaged, belongs
         * to another user, or was wrapped and [wrap] is null or another key.
         */
        public fun deserialize(user: String, bytes: ByteArray, wrap: Aead?): Identity {
            TinkSetup.ensure()
            try {
                DataInputStream(bytes.inputStream()).run {
                    val form = readUnsignedByte()
                    if (form == WRAPPED && wrap == null) throw GeneralSecurityException("the keys of $user are wrapped and no wrapping key was given")
                    if (form != CLEAR && form != WRAPPED) throw GeneralSecurityException("unknown key file form $form")
                    val handles = listOf("encryption", "signing").map { role ->
                        val size = readInt()
                        if (size !in 1..MAX_KEYSET_BYTES) throw GeneralSecurityException("$role keyset of $size bytes")
                        val keyset = ByteArray(size).also(::readFully)
                        if (form == CLEAR) {
                            TinkProtoKeysetFormat.parseKeyset(keyset, InsecureSecretKeyAccess.get())
                        } else {
                            TinkProtoKeysetFormat.parseEncryptedKeyset(keyset, wrap!!, associatedData(user, role))
                        }
                    }
                    return Identity(Topics.requireUserName(user), handles[0], handles[1])
                }
            } catch (e: EOFException) {
                throw GeneralSecurityException("the key file of $user is cut short")
            }
        }

        /**
         * The identity of [user] kept in [file]: read when it exists, else generated and written (created
         * mode 600 where the file system has POSIX permissions, then moved into place, so a crash leaves
         * either no file or a whole one). Throws [GeneralSecurityException] for a damaged or foreign file,
         * [java.io.IOException] when it cannot be written.
         */
        public fun loadOrCreate(user: String, file: File, wrap: Aead? = null): Identity {
            if (file.exists()) return deserialize(user, file.readBytes(), wrap)
            val identity = generate(user)
            writePrivately(file, identity.serialize(wrap))
            return identity
        }

        internal fun writePrivately(file: File, bytes: ByteArray) {
            val dir = file.absoluteFile.parentFile
            dir.mkdirs()
            val temp = File(dir, file.name + ".tmp")
            temp.delete()
            val path = temp.toPath()
            runCatching { Files.createFile(path, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))) }
                .onFailure { Files.createFile(path) } // not POSIX (Windows): the user's profile folder protects it
            temp.writeBytes(bytes)
            Files.move(path, file.toPath(), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING)
        }

        private fun associatedData(user: String, role: String): ByteArray = "hapticon identity $user $role".toByteArray(Charsets.UTF_8)
    }
}
