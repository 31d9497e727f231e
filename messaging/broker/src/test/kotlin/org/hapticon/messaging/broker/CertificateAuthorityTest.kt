package org.hapticon.messaging.broker

import org.bouncycastle.asn1.x500.X500NameBuilder
import org.bouncycastle.asn1.x500.style.BCStyle
import org.bouncycastle.cert.jcajce.JcaX509CertificateConverter
import org.bouncycastle.cert.jcajce.JcaX509v3CertificateBuilder
import org.bouncycastle.operator.jcajce.JcaContentSignerBuilder
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayInputStream
import java.io.File
import java.io.IOException
import java.math.BigInteger
import java.nio.file.Files
import java.nio.file.attribute.PosixFilePermissions
import java.security.KeyPairGenerator
import java.security.KeyStore
import java.security.cert.CertPathValidator
import java.security.cert.CertPathValidatorException
import java.security.cert.CertificateFactory
import java.security.cert.PKIXParameters
import java.security.cert.TrustAnchor
import java.security.cert.X509Certificate
import java.time.Duration
import java.time.Instant
import java.util.Date

class CertificateAuthorityTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun mode(file: File) = PosixFilePermissions.toString(Files.getPosixFilePermissions(file.toPath()))

    /** Validates [chain] against [ca] as JSSE's PKIX trust manager would, at [at]. */
    private fun validate(chain: List<X509Certificate>, ca: X509Certificate, at: Instant) {
        val params = PKIXParameters(setOf(TrustAnchor(ca, null))).apply { isRevocationEnabled = false; date = Date.from(at) }
        CertPathValidator.getInstance("PKIX").validate(CertificateFactory.getInstance("X.509").generateCertPath(chain), params)
    }

    @Test
    fun init_writesCaAndServerFiles_privateOnesMode600_serverCertificateNamesTheHosts() {
        val dir = File(temp.root, "ca")
        val ca = CertificateAuthority.init(dir, "Study CA", listOf("192.168.1.20", "mqtt.example.org"))
        assertEquals(
            mapOf("ca.crt" to "rw-r--r--", "ca.key" to "rw-------", "server.crt" to "rw-r--r--", "server.key" to "rw-------"),
            dir.listFiles()!!.associate { it.name to mode(it) }.toSortedMap(),
        )
        val server = CertificateAuthority.readCertificates(ca.serverCertificateFile).single()
        // (2 = dNSName, 7 = iPAddress), RFC 5280 §4.2.1.6.
        assertEquals(
            listOf(2 to "localhost", 7 to "127.0.0.1", 7 to "192.168.1.20", 2 to "mqtt.example.org"),
            server.subjectAlternativeNames.map { (it[0] as Int) to (it[1] as String) },
        )
        assertEquals(listOf("1.3.6.1.5.5.7.3.1"), server.extendedKeyUsage) // serverAuth
        validate(listOf(server), ca.certificate, Instant.now())
        assertEquals(ca.certificate, CertificateAuthority.load(dir).certificate)
        assertEquals("EC", CertificateAuthority.readPrivateKey(ca.serverKeyFile).algorithm)
        assertEquals(ca.certificate.basicConstraints, Int.MAX_VALUE) // a CA without a path length limit
    }

    @Test
    fun init_refusesToReplaceAnExistingCa() {
        val dir = File(temp.root, "ca")
        CertificateAuthority.init(dir, "Study CA", emptyList())
        val before = File(dir, "ca.key").readText()
        val e = runCatching { CertificateAuthority.init(dir, "Study CA", emptyList()) }.exceptionOrNull()
        assertTrue(e is IOException && e.message!!.contains("already holds a certificate authority"))
        assertEquals(before, File(dir, "ca.key").readText())
    }

    @Test
    fun issueClient_pkcs12WithKeyAndChain_cnIsTheUser_validForTheGivenTime() {
        val ca = CertificateAuthority.init(File(temp.root, "ca"), "Study CA", emptyList())
        val now = Instant.parse("2026-11-26T10:00:00Z")
        val p12 = ca.issueClient("alice", "pw".toCharArray(), Duration.ofDays(30), now)
        val store = KeyStore.getInstance("PKCS12").apply { load(ByteArrayInputStream(p12), "pw".toCharArray()) }
        assertEquals(listOf("alice"), store.aliases().toList())
        val chain = store.getCertificateChain("alice").map { it as X509Certificate }
        assertEquals(listOf("CN=alice", ca.certificate.subjectX500Principal.name), chain.map { it.subjectX500Principal.name })
        assertEquals("alice", CertificateAuthority.userOf(chain[0]))
        assertEquals(listOf("1.3.6.1.5.5.7.3.2"), chain[0].extendedKeyUsage) // clientAuth
        assertEquals(-1, chain[0].basicConstraints) // not a CA: it cannot sign certificates for others
        assertEquals(Instant.parse("2026-12-26T10:00:00Z"), chain[0].notAfter.toInstant())
        validate(chain.take(1), ca.certificate, now)
        val expired = runCatching { validate(chain.take(1), ca.certificate, now.plus(Duration.ofDays(31))) }.exceptionOrNull()
        assertTrue(expired.toString(), expired is CertPathValidatorException)
        assertTrue(store.getKey("alice", "pw".toCharArray()) != null)
        val wrong = runCatching { KeyStore.getInstance("PKCS12").load(ByteArrayInputStream(p12), "guess".toCharArray()) }.exceptionOrNull()
        assertTrue(wrong is IOException)
    }

    @Test
    fun userOf_needsExactlyOneSingleValuedCnThatIsAUserName() {
        fun withSubject(build: X500NameBuilder.() -> Unit): X509Certificate {
            val keys = KeyPairGenerator.getInstance("EC").generateKeyPair()
            val name = X500NameBuilder(BCStyle.INSTANCE).apply(build).build()
            val holder = JcaX509v3CertificateBuilder(name, BigInteger.ONE, Date(), Date(System.currentTimeMillis() + 60_000), name, keys.public)
                .build(JcaContentSignerBuilder("SHA256withECDSA").build(keys.private))
            return JcaX509CertificateConverter().getCertificate(holder)
        }
        assertEquals("bob", CertificateAuthority.userOf(withSubject { addRDN(BCStyle.O, "Lab"); addRDN(BCStyle.CN, "bob") }))
        assertNull(CertificateAuthority.userOf(withSubject { addRDN(BCStyle.O, "Lab") }))
        assertNull(CertificateAuthority.userOf(withSubject { addRDN(BCStyle.CN, "bob"); addRDN(BCStyle.CN, "alice") }))
        assertNull(CertificateAuthority.userOf(withSubject { addMultiValuedRDN(arrayOf(BCStyle.CN, BCStyle.OU), arrayOf("bob", "x")) }))
        assertNull(CertificateAuthority.userOf(withSubject { addRDN(BCStyle.CN, "hapticon/v1/#") }))
        assertNull(CertificateAuthority.userOf(withSubject { addRDN(BCStyle.CN, "bob,CN=alice") }))
    }
}
