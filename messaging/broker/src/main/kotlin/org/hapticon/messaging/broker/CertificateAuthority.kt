package org.hapticon.messaging.broker

import org.bouncycastle.asn1.DERUTF8String
import org.bouncycastle.asn1.x500.X500Name
import org.bouncycastle.asn1.x500.X500NameBuilder
import org.bouncycastle.asn1.x500.style.BCStyle
import org.bouncycastle.asn1.x500.style.IETFUtils
import org.bouncycastle.asn1.x509.BasicConstraints
import org.bouncycastle.asn1.x509.ExtendedKeyUsage
import org.bouncycastle.asn1.x509.Extension
import org.bouncycastle.asn1.x509.GeneralName
import org.bouncycastle.asn1.x509.GeneralNames
import org.bouncycastle.asn1.x509.KeyPurposeId
import org.bouncycastle.asn1.x509.KeyUsage
import org.bouncycastle.cert.jcajce.JcaX509CertificateConverter
import org.bouncycastle.cert.jcajce.JcaX509ExtensionUtils
import org.bouncycastle.cert.jcajce.JcaX509v3CertificateBuilder
import org.bouncycastle.openssl.PEMParser
import org.bouncycastle.openssl.jcajce.JcaPEMKeyConverter
import org.bouncycastle.openssl.jcajce.JcaPEMWriter
import org.bouncycastle.openssl.jcajce.JcaPKCS8Generator
import org.bouncycastle.asn1.pkcs.PrivateKeyInfo
import org.bouncycastle.cert.X509CertificateHolder
import org.bouncycastle.operator.jcajce.JcaContentSignerBuilder
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.IOException
import java.io.StringWriter
import java.math.BigInteger
import java.net.InetAddress
import java.nio.file.Files
import java.nio.file.StandardCopyOption
import java.nio.file.attribute.PosixFilePermissions
import java.security.KeyPair
import java.security.KeyPairGenerator
import java.security.KeyStore
import java.security.PrivateKey
import java.security.SecureRandom
import java.security.cert.X509Certificate
import java.security.spec.ECGenParameterSpec
import java.time.Duration
import java.time.Instant
import java.util.Date

/**
 * A study's own certificate authority for mutual TLS, kept in [directory]:
 *
 * | file | what | mode |
 * |---|---|---|
 * | `ca.crt` | the CA certificate (PEM): Mosquitto's `cafile`, the embedded broker's client trust, and what clients trust the broker's certificate by | 644 |
 * | `ca.key` | the CA's private key (PKCS#8 PEM, unencrypted like an SSH key without passphrase) | 600 |
 * | `server.crt`, `server.key` | the broker's certificate for the host names and addresses given to [init], and its key | 644, 600 |
 *
 * [issueClient] makes a user's certificate (common name = the user name, which both brokers take as the user)
 * and returns it with its key as a password-protected PKCS#12 file.
 *
 * Keys are ECDSA P-256 (secp256r1), signatures SHA256withECDSA: supported by OpenSSL (Mosquitto), the JDK and
 * Android alike, and quick to make. X.509 building and PEM are BouncyCastle's (bcpkix); the JDK has no public API
 * to build a certificate, and its keytool can neither export a private key as PEM (Mosquitto's `keyfile`) nor
 * run without a process per step.
 */
public class CertificateAuthority private constructor(
    public val directory: File,
    private val caKey: PrivateKey,
    /** The CA certificate. */
    public val certificate: X509Certificate,
) {
    /** The broker's certificate (PEM). */
    public val serverCertificateFile: File get() = File(directory, SERVER_CERT)

    /** The broker's private key (PKCS#8 PEM, mode 600). */
    public val serverKeyFile: File get() = File(directory, SERVER_KEY)

    /** The CA certificate (PEM). */
    public val certificateFile: File get() = File(directory, CA_CERT)

    /**
     * A certificate for [user] (common name [user], extended key usage clientAuth) valid for [validity] from
     * [now], with a fresh key, as a PKCS#12 file encrypted with [password] (the JDK's PKCS12 key store: PBES2 with
     * AES-256 and an HMAC-SHA256 MAC). The chain includes the CA certificate.
     */
    public fun issueClient(user: String, password: CharArray, validity: Duration = DEFAULT_CLIENT_VALIDITY, now: Instant = Instant.now()): ByteArray {
        require(isValidUserName(user)) { "not a user name: '$user'" }
        require(!validity.isNegative && !validity.isZero) { "the validity must be positive" }
        require(password.isNotEmpty()) { "the PKCS#12 password must not be empty" }
        val keys = newKeyPair()
        val cert = sign(
            subject = name(user),
            publicKey = keys,
            notBefore = now.minus(CLOCK_SKEW),
            notAfter = now.plus(validity),
            ca = false,
            purpose = KeyPurposeId.id_kp_clientAuth,
            altNames = null,
        )
        val store = KeyStore.getInstance("PKCS12").apply { load(null, null) }
        store.setKeyEntry(user, keys.private, password, arrayOf(cert, certificate))
        return ByteArrayOutputStream().also { store.store(it, password) }.toByteArray()
    }

    private fun sign(subject: X500Name, publicKey: KeyPair, notBefore: Instant, notAfter: Instant, ca: Boolean, purpose: KeyPurposeId?, altNames: GeneralNames?): X509Certificate =
        build(X500Name.getInstance(certificate.subjectX500Principal.encoded), caKey, certificate, subject, publicKey, notBefore, notAfter, ca, purpose, altNames)

    public companion object {
        private const val CA_CERT = "ca.crt"
        private const val CA_KEY = "ca.key"
        private const val SERVER_CERT = "server.crt"
        private const val SERVER_KEY = "server.key"

        /** How long a user's certificate is valid unless told otherwise: a year, a study's usual length. */
        public val DEFAULT_CLIENT_VALIDITY: Duration = Duration.ofDays(365)

        /** The CA's validity. */
        public val CA_VALIDITY: Duration = Duration.ofDays(3650)

        /** The broker certificate's validity (825 days: the longest that Apple's TLS clients accept). */
        public val SERVER_VALIDITY: Duration = Duration.ofDays(825)

        // Certificates start a few minutes back, so that a phone whose clock is slightly behind accepts them.
        private val CLOCK_SKEW: Duration = Duration.ofMinutes(5)

        /** True when [directory] holds a CA made by [init]. */
        public fun exists(directory: File): Boolean = File(directory, CA_CERT).isFile && File(directory, CA_KEY).isFile

        /**
         * Makes a new CA named [name] in [directory] and a broker certificate for [hosts] (DNS names or IP
         * addresses; `localhost` and 127.0.0.1 are always included). Throws [IOException] when [directory] already
         * holds a CA (a new one would invalidate every certificate issued) or cannot be written.
         */
        public fun init(directory: File, name: String, hosts: List<String>, now: Instant = Instant.now()): CertificateAuthority {
            if (File(directory, CA_KEY).exists() || File(directory, CA_CERT).exists()) {
                throw IOException("$directory already holds a certificate authority; delete it first to start over (every certificate it issued stops working)")
            }
            if (!directory.isDirectory && !directory.mkdirs()) throw IOException("cannot create $directory")
            val caKeys = newKeyPair()
            val caName = X500NameBuilder(BCStyle.INSTANCE).addRDN(BCStyle.CN, name).addRDN(BCStyle.O, "Hapticon study CA").build()
            val caCert = build(caName, caKeys.private, null, caName, caKeys, now.minus(CLOCK_SKEW), now.plus(CA_VALIDITY), true, null, null)
            writePrivate(File(directory, CA_KEY), pem(caKeys.private))
            writePublic(File(directory, CA_CERT), pem(caCert))
            val ca = CertificateAuthority(directory, caKeys.private, caCert)
            ca.issueServer(hosts, now)
            return ca
        }

        /** The CA in [directory]. Throws [IOException] when it is missing or its files do not parse. */
        public fun load(directory: File): CertificateAuthority {
            if (!exists(directory)) throw IOException("no certificate authority in $directory (make one with: hapticon broker ca init)")
            return CertificateAuthority(directory, readPrivateKey(File(directory, CA_KEY)), readCertificates(File(directory, CA_CERT)).first())
        }

        /** The certificates in a PEM file. Throws [IOException] when there is none or the file does not parse. */
        public fun readCertificates(file: File): List<X509Certificate> {
            val found = mutableListOf<X509Certificate>()
            try {
                PEMParser(file.reader()).use { parser ->
                    while (true) {
                        val item = parser.readObject() ?: break
                        if (item is X509CertificateHolder) found += JcaX509CertificateConverter().getCertificate(item)
                    }
                }
            } catch (e: Exception) {
                if (e is IOException) throw IOException("$file: ${e.message}", e)
                throw IOException("$file is not a PEM certificate file: ${e.message}", e)
            }
            if (found.isEmpty()) throw IOException("$file holds no PEM certificate")
            return found
        }

        /** A PKCS#8 (or traditional OpenSSL) PEM private key. Throws [IOException] when the file holds none. */
        public fun readPrivateKey(file: File): PrivateKey {
            val item = try {
                PEMParser(file.reader()).use { it.readObject() }
            } catch (e: IOException) {
                throw IOException("$file: ${e.message}", e)
            }
            val converter = JcaPEMKeyConverter()
            return when (item) {
                is PrivateKeyInfo -> converter.getPrivateKey(item)
                is org.bouncycastle.openssl.PEMKeyPair -> converter.getPrivateKey(item.privateKeyInfo)
                else -> throw IOException("$file holds no unencrypted PEM private key")
            }
        }

        /**
         * The user a client [certificate] stands for: its one common name, when that is a valid user name, else
         * null (no CN, several, a multi-valued RDN). Mosquitto's `use_identity_as_username` takes the same CN.
         */
        public fun userOf(certificate: X509Certificate): String? {
            val rdns = X500Name.getInstance(certificate.subjectX500Principal.encoded).getRDNs(BCStyle.CN)
            val rdn = rdns.singleOrNull()?.takeIf { !it.isMultiValued } ?: return null
            return IETFUtils.valueToString(rdn.first.value).takeIf(::isValidUserName)
        }

        // The rule of org.hapticon.messaging.Topics.isValidUserName (this module does not depend on :messaging).
        private fun isValidUserName(name: String) = name.matches(Regex("[A-Za-z0-9][A-Za-z0-9._-]{0,31}"))

        private fun CertificateAuthority.issueServer(hosts: List<String>, now: Instant) {
            val names = (listOf("localhost", "127.0.0.1") + hosts).distinct()
            val altNames = GeneralNames(
                names.map { host ->
                    if (isIpAddress(host)) GeneralName(GeneralName.iPAddress, host) else GeneralName(GeneralName.dNSName, host)
                }.toTypedArray(),
            )
            val keys = newKeyPair()
            val cert = sign(name(names.first { !isIpAddress(it) }), keys, now.minus(CLOCK_SKEW), now.plus(SERVER_VALIDITY), false, KeyPurposeId.id_kp_serverAuth, altNames)
            writePrivate(serverKeyFile, pem(keys.private))
            writePublic(serverCertificateFile, pem(cert))
        }

        private fun isIpAddress(host: String): Boolean =
            host.matches(Regex("""\d{1,3}(\.\d{1,3}){3}""")) || (':' in host && runCatching { InetAddress.getByName(host) }.isSuccess)

        private fun name(commonName: String): X500Name =
            X500NameBuilder(BCStyle.INSTANCE).addRDN(BCStyle.CN, DERUTF8String(commonName)).build()

        private fun newKeyPair(): KeyPair = KeyPairGenerator.getInstance("EC").apply { initialize(ECGenParameterSpec("secp256r1"), SecureRandom()) }.generateKeyPair()

        private fun build(
            issuer: X500Name,
            issuerKey: PrivateKey,
            issuerCert: X509Certificate?,
            subject: X500Name,
            keys: KeyPair,
            notBefore: Instant,
            notAfter: Instant,
            ca: Boolean,
            purpose: KeyPurposeId?,
            altNames: GeneralNames?,
        ): X509Certificate {
            // RFC 5280 §4.1.2.2: a positive serial of at most 20 octets; 127 random bits make it unique.
            val serial = BigInteger(127, SecureRandom()).add(BigInteger.ONE)
            val ext = JcaX509ExtensionUtils()
            val builder = JcaX509v3CertificateBuilder(issuer, serial, Date.from(notBefore), Date.from(notAfter), subject, keys.public)
                .addExtension(Extension.basicConstraints, true, BasicConstraints(ca))
                .addExtension(Extension.keyUsage, true, KeyUsage(if (ca) KeyUsage.keyCertSign or KeyUsage.cRLSign else KeyUsage.digitalSignature))
                .addExtension(Extension.subjectKeyIdentifier, false, ext.createSubjectKeyIdentifier(keys.public))
            if (issuerCert != null) builder.addExtension(Extension.authorityKeyIdentifier, false, ext.createAuthorityKeyIdentifier(issuerCert))
            if (purpose != null) builder.addExtension(Extension.extendedKeyUsage, false, ExtendedKeyUsage(purpose))
            if (altNames != null) builder.addExtension(Extension.subjectAlternativeName, false, altNames)
            val signer = JcaContentSignerBuilder("SHA256withECDSA").build(issuerKey)
            return JcaX509CertificateConverter().getCertificate(builder.build(signer))
        }

        // A private key as PKCS#8 ("PRIVATE KEY"), which OpenSSL (Mosquitto's keyfile) and BouncyCastle both read;
        // JcaPEMWriter alone would write the traditional SEC1 "EC PRIVATE KEY".
        private fun pem(item: Any): String = StringWriter().also { w ->
            JcaPEMWriter(w).use { it.writeObject(if (item is PrivateKey) JcaPKCS8Generator(item, null) else item) }
        }.toString()

        /** Writes [text] to [file] created with mode 600 before any byte is written, then moved into place. */
        internal fun writePrivate(file: File, text: String) = writeAtomically(file, text.toByteArray(), "rw-------")

        private fun writePublic(file: File, text: String) = writeAtomically(file, text.toByteArray(), "rw-r--r--")

        /** Writes [bytes] to [file] with POSIX [mode], through a temporary file created with that mode. */
        public fun writeAtomically(file: File, bytes: ByteArray, mode: String = "rw-------") {
            val dir = file.absoluteFile.parentFile
            if (!dir.isDirectory && !dir.mkdirs()) throw IOException("cannot create $dir")
            val part = File(dir, ".${file.name}.part")
            Files.deleteIfExists(part.toPath())
            Files.createFile(part.toPath(), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString(mode)))
            part.writeBytes(bytes)
            Files.move(part.toPath(), file.toPath(), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
        }
    }
}
