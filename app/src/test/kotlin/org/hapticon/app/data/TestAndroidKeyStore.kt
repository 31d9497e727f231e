package org.hapticon.app.data

import android.security.keystore.KeyGenParameterSpec
import java.io.InputStream
import java.io.OutputStream
import java.security.Key
import java.security.KeyStoreSpi
import java.security.Provider
import java.security.SecureRandom
import java.security.Security
import java.security.cert.Certificate
import java.security.spec.AlgorithmParameterSpec
import java.util.Collections
import java.util.Date
import java.util.Enumeration
import java.util.concurrent.ConcurrentHashMap
import javax.crypto.KeyGeneratorSpi
import javax.crypto.SecretKey
import javax.crypto.spec.SecretKeySpec

/**
 * An in-memory stand-in for the "AndroidKeyStore" JCA provider, which Robolectric lacks: `KeyStore` entries and an
 * AES `KeyGenerator` that takes a [KeyGenParameterSpec] and stores the key under its alias. Enough for Tink's
 * `AndroidKeystore` (hasKey, generateNewAes256GcmKey, getAead), so tests run the production code. The key is a
 * plain software key here; what the real Keystore adds (keys that never leave it) cannot be tested on a JVM.
 */
object TestAndroidKeyStore {
    internal val keys = ConcurrentHashMap<String, SecretKey>()

    private class TestProvider : Provider("AndroidKeyStore", "1.0", "in-memory AndroidKeyStore for Robolectric tests") {
        init {
            put("KeyStore.AndroidKeyStore", TestKeyStoreSpi::class.java.name)
            put("KeyGenerator.AES", TestAesKeyGeneratorSpi::class.java.name)
        }
    }

    /** Installs the provider (once) and forgets every key. */
    fun install() {
        keys.clear()
        if (Security.getProvider("AndroidKeyStore") == null) Security.addProvider(TestProvider())
    }

    /** Removes the provider: the code under test then sees a machine without a Keystore. */
    fun uninstall() {
        Security.removeProvider("AndroidKeyStore")
        keys.clear()
    }
}

class TestKeyStoreSpi : KeyStoreSpi() {
    private val keys get() = TestAndroidKeyStore.keys
    override fun engineGetKey(alias: String, password: CharArray?): Key? = keys[alias]
    override fun engineGetCertificateChain(alias: String): Array<Certificate>? = null
    override fun engineGetCertificate(alias: String): Certificate? = null
    override fun engineGetCreationDate(alias: String): Date? = if (keys.containsKey(alias)) Date(0) else null
    override fun engineSetKeyEntry(alias: String, key: Key, password: CharArray?, chain: Array<out Certificate>?) {
        keys[alias] = key as SecretKey
    }
    override fun engineSetKeyEntry(alias: String, key: ByteArray, chain: Array<out Certificate>?) = throw UnsupportedOperationException()
    override fun engineSetCertificateEntry(alias: String, cert: Certificate) = throw UnsupportedOperationException()
    override fun engineDeleteEntry(alias: String) {
        keys.remove(alias)
    }
    override fun engineAliases(): Enumeration<String> = Collections.enumeration(keys.keys.toList())
    override fun engineContainsAlias(alias: String): Boolean = keys.containsKey(alias)
    override fun engineSize(): Int = keys.size
    override fun engineIsKeyEntry(alias: String): Boolean = keys.containsKey(alias)
    override fun engineIsCertificateEntry(alias: String): Boolean = false
    override fun engineGetCertificateAlias(cert: Certificate): String? = null
    override fun engineStore(stream: OutputStream?, password: CharArray?) = Unit
    override fun engineLoad(stream: InputStream?, password: CharArray?) = Unit
}

class TestAesKeyGeneratorSpi : KeyGeneratorSpi() {
    private var alias: String? = null
    private var bits = 256
    private var random = SecureRandom()

    override fun engineInit(random: SecureRandom) {
        this.random = random
    }

    override fun engineInit(params: AlgorithmParameterSpec, random: SecureRandom?) {
        val spec = params as KeyGenParameterSpec
        alias = spec.keystoreAlias
        if (spec.keySize > 0) bits = spec.keySize
        if (random != null) this.random = random
    }

    override fun engineInit(keysize: Int, random: SecureRandom) {
        bits = keysize
        this.random = random
    }

    override fun engineGenerateKey(): SecretKey {
        val key = SecretKeySpec(ByteArray(bits / 8).also(random::nextBytes), "AES")
        alias?.let { TestAndroidKeyStore.keys[it] = key }
        return key
    }
}
