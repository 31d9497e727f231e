package org.hapticon.app.data

import android.util.Log
import java.io.ByteArrayInputStream
import java.io.File
import java.io.IOException
import java.security.GeneralSecurityException
import java.security.KeyStore
import java.security.cert.X509Certificate
import java.time.Instant
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.messaging.mqtt.ClientCertificate

/** What Settings shows about the user's client certificate (docs/security.md, "Client certificates"). */
sealed interface ClientCertificateStatus {
    /** None imported: the broker password (if any) logs in. */
    data object None : ClientCertificateStatus

    /**
     * One is stored and opens: it logs in as [user] on `ssl://` brokers until [notAfter]; [studyCa] is the common
     * name of the study CA trusted for the broker's certificate, null when the system's trust store is used.
     */
    data class InUse(val user: String, val notAfter: Instant, val studyCa: String?) : ClientCertificateStatus

    /** One is stored but cannot be used ([reason], one line: expired, the Keystore key lost); import a new one. */
    data class Unusable(val reason: String) : ClientCertificateStatus
}

/** The client certificate and the certificates the broker's must chain to, ready for [org.hapticon.messaging.mqtt.MqttSettings]. */
class ClientCredentials(val certificate: ClientCertificate, val trusted: List<X509Certificate>)

/** Imports, keeps and removes the user's client certificate. */
interface ClientCertificateRepository {
    /** What is stored now. */
    val status: StateFlow<ClientCertificateStatus>

    /**
     * Validates [pkcs12] with [password] for [user] ([ClientCertificate.fromPkcs12]) and stores it, replacing any
     * previous one. Throws [IllegalArgumentException] with a one-line reason; nothing is stored then.
     */
    fun import(pkcs12: ByteArray, password: CharArray, user: String?): ClientCertificateStatus.InUse

    /** Forgets the stored certificate and its password. */
    fun remove()

    /** The stored certificate opened now, or null when there is none or it is [ClientCertificateStatus.Unusable]. */
    fun credentials(): ClientCredentials?
}

/**
 * The client certificate kept in [directory] (under the app's files): the PKCS#12 file and its password, each
 * sealed by [secrets] (AES-256-GCM under the Android Keystore key that seals the broker password, bound to its
 * purpose), so a copy of the app's files holds neither the key nor the password. The user types the password
 * once, at import. Where there is no Keystore at all, import is refused rather than storing a key in clear.
 *
 * The study CA needs no second file: `hapticon broker cert issue` puts the CA certificate in the PKCS#12 chain,
 * and `hapticon broker ca init` signs the broker's certificate with that same CA, so the chain's CA certificates
 * are what the broker's certificate must chain to (as `hapticon chat --ca ca.crt`). A PKCS#12 file without a CA in
 * its chain leaves the system's trust store in charge.
 */
class ClientCertificateStore(
    private val directory: File,
    private val secrets: KeystoreSecrets = KeystoreSecrets(),
    private val keystoreAvailable: () -> Boolean = KeystoreSecrets::keystoreAvailable,
    private val now: () -> Instant = Instant::now,
) : ClientCertificateRepository {
    private val pkcs12File get() = File(directory, PKCS12_FILE)
    private val passwordFile get() = File(directory, PASSWORD_FILE)
    private val state = MutableStateFlow<ClientCertificateStatus>(ClientCertificateStatus.None)
    override val status: StateFlow<ClientCertificateStatus> = state.asStateFlow()

    init {
        state.value = read().second
    }

    override fun import(pkcs12: ByteArray, password: CharArray, user: String?): ClientCertificateStatus.InUse {
        val (certificate, trusted) = open(pkcs12, password)
        require(user == null || certificate.user == user) {
            "this certificate is for ${certificate.user}, not $user: the broker takes the user name from the certificate"
        }
        require(keystoreAvailable()) { "this phone has no Android Keystore to protect the certificate's key" }
        directory.mkdirs()
        val sealedPassword = try {
            secrets.sealBytes(String(password).toByteArray(Charsets.UTF_8), PASSWORD_PURPOSE)
        } catch (e: GeneralSecurityException) {
            throw IllegalArgumentException("the certificate cannot be protected with the Keystore key: ${e.message}", e)
        }
        writeAtomically(passwordFile, sealedPassword)
        writeAtomically(pkcs12File, secrets.sealBytes(pkcs12, PKCS12_PURPOSE))
        return statusOf(certificate, trusted).also { state.value = it }
    }

    override fun remove() {
        pkcs12File.delete()
        passwordFile.delete()
        state.value = ClientCertificateStatus.None
    }

    override fun credentials(): ClientCredentials? = read().first

    /** The stored credentials and their status, read from disk (the certificate may have expired since). */
    private fun read(): Pair<ClientCredentials?, ClientCertificateStatus> {
        if (!pkcs12File.exists()) return null to ClientCertificateStatus.None
        val pkcs12 = runCatching { secrets.openBytes(pkcs12File.readBytes(), PKCS12_PURPOSE) }.getOrNull()
        val password = runCatching { secrets.openBytes(passwordFile.readBytes(), PASSWORD_PURPOSE) }.getOrNull()
        if (pkcs12 == null || password == null) {
            return null to ClientCertificateStatus.Unusable("the stored certificate no longer opens on this phone (Keystore key lost); import it again")
        }
        return try {
            val (certificate, trusted) = open(pkcs12, String(password, Charsets.UTF_8).toCharArray())
            ClientCredentials(certificate, trusted) to statusOf(certificate, trusted)
        } catch (e: IllegalArgumentException) {
            Log.w(TAG, "stored client certificate unusable: ${e.message}")
            null to ClientCertificateStatus.Unusable(e.message ?: "the stored certificate cannot be used")
        }.also { state.value = it.second }
    }

    private fun open(pkcs12: ByteArray, password: CharArray): Pair<ClientCertificate, List<X509Certificate>> {
        val certificate = ClientCertificate.fromPkcs12(pkcs12, password, now())
        return certificate to studyCas(pkcs12, password)
    }

    private companion object {
        const val TAG = "ClientCertificates"
        const val PKCS12_FILE = "client.p12.sealed"
        const val PASSWORD_FILE = "client.p12.password.sealed"
        const val PKCS12_PURPOSE = "hapticon client certificate"
        const val PASSWORD_PURPOSE = "hapticon client certificate password"

        fun statusOf(certificate: ClientCertificate, trusted: List<X509Certificate>) =
            ClientCertificateStatus.InUse(certificate.user, certificate.notAfter, trusted.firstOrNull()?.let(::commonName))

        /** The CA certificates (basic constraints CA) above the key's certificate in its PKCS#12 chain. */
        fun studyCas(pkcs12: ByteArray, password: CharArray): List<X509Certificate> = try {
            val store = KeyStore.getInstance("PKCS12").apply { load(ByteArrayInputStream(pkcs12), password) }
            val alias = store.aliases().toList().first { store.isKeyEntry(it) }
            store.getCertificateChain(alias).orEmpty().drop(1).filterIsInstance<X509Certificate>().filter { it.basicConstraints >= 0 }
        } catch (e: IOException) {
            emptyList() // fromPkcs12 opened it just before: not reached in practice
        } catch (e: GeneralSecurityException) {
            emptyList()
        }

        fun commonName(certificate: X509Certificate): String {
            val subject = certificate.subjectX500Principal.getName(javax.security.auth.x500.X500Principal.RFC2253)
            return Regex("""(?:^|,)CN=((?:\\.|[^,])*)""").find(subject)?.groupValues?.get(1) ?: subject
        }

        /** Written to a temporary file and renamed, so a crash never leaves half a file. */
        fun writeAtomically(file: File, bytes: ByteArray) {
            val temporary = File(file.parentFile, file.name + ".tmp")
            temporary.writeBytes(bytes)
            if (!temporary.renameTo(file)) {
                temporary.delete()
                throw IllegalArgumentException("the certificate could not be stored in ${file.parentFile}")
            }
        }
    }
}
