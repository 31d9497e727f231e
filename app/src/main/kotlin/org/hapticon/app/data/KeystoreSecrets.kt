package org.hapticon.app.data

import android.util.Base64
import android.util.Log
import com.google.crypto.tink.Aead
import com.google.crypto.tink.integration.android.AndroidKeystore
import java.security.GeneralSecurityException
import java.security.Security

/**
 * Small secrets at rest (the broker password) encrypted with AES-256-GCM under a key that never leaves Android
 * Keystore (Tink's `AndroidKeystore`: the key is made in the Keystore, hardware-backed where the phone has it,
 * and only used through it). A copy of the app's files — a backup, a rooted phone's dump — holds ciphertext
 * only. Each value is bound to its [purpose] (GCM associated data), so one cannot be swapped for another.
 *
 * [aead] is asked for the first time a secret is sealed or opened. Robolectric has no Keystore: tests install
 * an in-memory "AndroidKeyStore" JCA provider (`TestAndroidKeyStore`) and so run this very code.
 */
class KeystoreSecrets(private val aead: () -> Aead = { keystoreAead(KEY_ALIAS) }) {
    private val key by lazy(aead)

    /** The Keystore-backed AEAD itself, for wrapping Tink keysets (the end-to-end keys, [AppKeys]). */
    val wrappingKey: Aead get() = key

    /** [plaintext] sealed for [purpose], as base64 text for SharedPreferences. Throws [GeneralSecurityException]. */
    fun seal(plaintext: String, purpose: String): String =
        Base64.encodeToString(key.encrypt(plaintext.toByteArray(Charsets.UTF_8), purpose.toByteArray(Charsets.UTF_8)), Base64.NO_WRAP)

    /** [plaintext] bytes (a client certificate's PKCS#12 file) sealed for [purpose]. Throws [GeneralSecurityException]. */
    fun sealBytes(plaintext: ByteArray, purpose: String): ByteArray = key.encrypt(plaintext, purpose.toByteArray(Charsets.UTF_8))

    /** What [sealBytes] made of [sealed] for [purpose], or null when it does not open (logged, as [open]). */
    fun openBytes(sealed: ByteArray, purpose: String): ByteArray? = try {
        key.decrypt(sealed, purpose.toByteArray(Charsets.UTF_8))
    } catch (e: GeneralSecurityException) {
        Log.w(TAG, "stored $purpose does not decrypt with the Keystore key; it must be imported again", e)
        null
    }

    /**
     * What [seal] made of [sealed] for [purpose], or null when it does not open (the Keystore key is gone, as
     * after restoring another phone's backup: the user enters the secret again) — logged, never thrown.
     */
    fun open(sealed: String, purpose: String): String? = try {
        String(key.decrypt(Base64.decode(sealed, Base64.NO_WRAP), purpose.toByteArray(Charsets.UTF_8)), Charsets.UTF_8)
    } catch (e: GeneralSecurityException) {
        Log.w(TAG, "stored $purpose does not decrypt with the Keystore key; it must be entered again", e)
        null
    } catch (e: IllegalArgumentException) {
        Log.w(TAG, "stored $purpose is not base64; it must be entered again")
        null
    }

    companion object {
        private const val TAG = "KeystoreSecrets"

        /** The Keystore alias of the app's secrets key. */
        const val KEY_ALIAS: String = "hapticon-secrets"

        /** True where an Android Keystore exists (every phone; not a plain JVM or Robolectric without the test provider). */
        fun keystoreAvailable(): Boolean = Security.getProvider("AndroidKeyStore") != null

        /** The AES-256-GCM key [alias] in Android Keystore, made on first use. */
        fun keystoreAead(alias: String): Aead {
            if (!AndroidKeystore.hasKey(alias)) AndroidKeystore.generateNewAes256GcmKey(alias)
            return AndroidKeystore.getAead(alias)
        }
    }
}
