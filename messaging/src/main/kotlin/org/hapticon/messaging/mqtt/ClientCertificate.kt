package org.hapticon.messaging.mqtt

import org.hapticon.messaging.Topics
import java.io.ByteArrayInputStream
import java.io.IOException
import java.security.GeneralSecurityException
import java.security.KeyStore
import java.security.PrivateKey
import java.security.cert.CertificateException
import java.security.cert.CertificateFactory
import java.security.cert.X509Certificate
import java.time.Instant
import javax.net.ssl.KeyManagerFactory
import javax.net.ssl.TrustManagerFactory
import javax.security.auth.x500.X500Principal

/**
 * A user's client certificate and private key for mutual TLS, read from a PKCS#12 file (what
 * `hapticon broker cert issue USER` writes). The broker takes the user name from the certificate's
 * common name (Mosquitto `use_identity_as_username`; the embedded broker's authenticator does the same),
 * so [user] is that name, and [MqttSettings] requires it to be the settings' user.
 *
 * Runs on Android and the JVM: only `java.security` and `javax.net.ssl`.
 *
 * @property user the certificate's common name, a valid user name ([Topics.isValidUserName]).
 * @property certificate the client certificate itself (its chain stays in the key store).
 * @property notAfter when the certificate expires.
 */
public class ClientCertificate private constructor(
    public val user: String,
    public val certificate: X509Certificate,
    private val keyStore: KeyStore,
    private val password: CharArray,
) {
    /** When the certificate expires. */
    public val notAfter: Instant get() = certificate.notAfter.toInstant()

    /** The key manager that presents this certificate in the TLS handshake. */
    public fun keyManagerFactory(): KeyManagerFactory =
        KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm()).apply { init(keyStore, password) }

    /** Names the user and expiry, never the key. */
    override fun toString(): String = "ClientCertificate(user=$user, notAfter=$notAfter)"

    public companion object {
        /** A PKCS#12 file of one key and its chain is a few KiB; anything above this is not one. */
        public const val MAX_PKCS12_BYTES: Int = 64 * 1024

        /**
         * Reads a PKCS#12 file's bytes protected by [password]. Throws [IllegalArgumentException] with a one-line
         * reason: too large, not PKCS#12 or a wrong password, no private key, no user name as common name, not yet
         * valid or expired at [now].
         */
        public fun fromPkcs12(bytes: ByteArray, password: CharArray, now: Instant = Instant.now()): ClientCertificate {
            require(bytes.size <= MAX_PKCS12_BYTES) { "the client certificate file is larger than ${MAX_PKCS12_BYTES / 1024} KiB: not a PKCS#12 file of one key" }
            val store = KeyStore.getInstance("PKCS12")
            try {
                store.load(ByteArrayInputStream(bytes), password)
            } catch (e: IOException) {
                // The JDK reports a wrong password as an IOException caused by UnrecoverableKeyException or BadPaddingException.
                throw IllegalArgumentException("the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file", e)
            } catch (e: GeneralSecurityException) {
                throw IllegalArgumentException("the client certificate cannot be opened: ${e.message}", e)
            }
            val alias = store.aliases().toList().firstOrNull { store.isKeyEntry(it) }
                ?: throw IllegalArgumentException("the client certificate file holds no private key")
            try {
                store.getKey(alias, password) as? PrivateKey ?: throw IllegalArgumentException("the client certificate file holds no private key")
            } catch (e: GeneralSecurityException) {
                throw IllegalArgumentException("the client certificate's key cannot be opened with this password", e)
            }
            val certificate = store.getCertificate(alias) as? X509Certificate
                ?: throw IllegalArgumentException("the client certificate file holds no X.509 certificate")
            val user = userOf(certificate)
                ?: throw IllegalArgumentException("the client certificate's subject (${certificate.subjectX500Principal.name}) has no user name as its one common name (CN)")
            if (now.isBefore(certificate.notBefore.toInstant())) {
                throw IllegalArgumentException("the client certificate of $user is not valid before ${certificate.notBefore.toInstant()}")
            }
            if (now.isAfter(certificate.notAfter.toInstant())) {
                throw IllegalArgumentException("the client certificate of $user expired on ${certificate.notAfter.toInstant()}; ask for a new one (hapticon broker cert issue $user)")
            }
            return ClientCertificate(user, certificate, store, password.copyOf())
        }

        /**
         * The user name a broker takes from [certificate]: its one common name, when that is a valid user name;
         * null otherwise (no CN, several, or one with characters a user name cannot have).
         *
         * Read from the RFC 2253 form of the subject (`X500Principal.RFC2253`): a user name has no character that
         * form escapes, so `CN=` followed by a user name and then an unescaped `,` or the end is exactly one
         * attribute. A multi-valued RDN (`CN=bob+OU=x`) or an escaped comma before `CN=` is not matched: refused,
         * never misread. (javax.naming's LdapName would parse it fully but does not exist on Android.)
         */
        public fun userOf(certificate: X509Certificate): String? {
            val subject = certificate.subjectX500Principal.getName(X500Principal.RFC2253)
            val names = COMMON_NAME.findAll(subject).map { it.groupValues[1] }.toList()
            val anyCn = Regex("""(?:^|,)\s*CN=""", RegexOption.IGNORE_CASE).findAll(subject).count()
            return names.singleOrNull()?.takeIf { anyCn == 1 && Topics.isValidUserName(it) }
        }

        /** Trust exactly [certificates] (e.g. the study's own CA) instead of the system's trust store. */
        public fun trustManagerFactory(certificates: List<X509Certificate>): TrustManagerFactory {
            require(certificates.isNotEmpty()) { "no trusted certificates given" }
            val store = KeyStore.getInstance(KeyStore.getDefaultType()).apply { load(null, null) }
            certificates.forEachIndexed { i, certificate -> store.setCertificateEntry("trusted-$i", certificate) }
            return TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm()).apply { init(store) }
        }

        /**
         * The X.509 certificates in [pem] (PEM text, e.g. the study's `ca.crt`). Throws [IllegalArgumentException]
         * when there is none or one does not parse.
         */
        public fun certificatesFromPem(pem: ByteArray): List<X509Certificate> {
            require(pem.size <= MAX_PKCS12_BYTES) { "the certificate file is larger than ${MAX_PKCS12_BYTES / 1024} KiB" }
            val certificates = try {
                CertificateFactory.getInstance("X.509").generateCertificates(ByteArrayInputStream(pem)).map { it as X509Certificate }
            } catch (e: CertificateException) {
                throw IllegalArgumentException("not a PEM certificate file: ${e.message}", e)
            }
            require(certificates.isNotEmpty()) { "no certificate in the file" }
            return certificates
        }

        private val COMMON_NAME = Regex("""(?:^|(?<!\\),)CN=([A-Za-z0-9._-]{1,${Topics.MAX_USER_NAME_LENGTH}})(?=,|$)""")
    }
}
