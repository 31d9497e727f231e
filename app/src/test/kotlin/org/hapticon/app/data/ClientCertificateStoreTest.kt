package org.hapticon.app.data

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import java.io.File
import java.time.Duration
import java.time.Instant
import org.hapticon.app.sync.ChatComponent
import org.hapticon.messaging.broker.CertificateAuthority
import org.hapticon.messaging.mqtt.DeviceId
import org.junit.After
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * The client certificate on the phone: validated at import with one-line reasons, kept only as Keystore-sealed
 * ciphertext, read back with the study CA from its chain, and carried into the messenger's [org.hapticon.messaging.mqtt.MqttSettings].
 */
@RunWith(RobolectricTestRunner::class)
class ClientCertificateStoreTest {
    @get:Rule val temp = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val now = Instant.parse("2026-11-26T10:00:00Z")
    private val password = "p01 pkcs12 secret".toCharArray()
    private lateinit var ca: CertificateAuthority
    private lateinit var directory: File

    @Before
    fun setUp() {
        TestAndroidKeyStore.install()
        ca = CertificateAuthority.init(temp.newFolder("ca"), "Hapticon test study", listOf("127.0.0.1"), now)
        directory = File(context.filesDir, "client-certificate")
    }

    @After
    fun tearDown() {
        TestAndroidKeyStore.uninstall()
        directory.deleteRecursively()
    }

    private fun store() = ClientCertificateStore(directory, now = { now })

    private fun p12(user: String = "p01", issued: Instant = now, validity: Duration = Duration.ofDays(365)) =
        ca.issueClient(user, password, validity, issued)

    private fun importError(bytes: ByteArray, pw: CharArray = password, user: String? = "p01"): String {
        val store = store()
        try {
            store.import(bytes, pw, user)
        } catch (e: IllegalArgumentException) {
            assertEquals("nothing is stored after a refused import", emptyList<String>(), directory.list()?.toList().orEmpty())
            assertEquals(ClientCertificateStatus.None, store.status.value)
            return e.message!!
        }
        fail("import was not refused")
        throw AssertionError()
    }

    @Test
    fun import_validCertificate_inUseWithUserExpiryAndStudyCa_storedOnlyAsCiphertext() {
        val bytes = p12()
        val status = store().import(bytes, password, "p01")
        assertEquals(ClientCertificateStatus.InUse("p01", now.plus(Duration.ofDays(365)), "Hapticon test study"), status)

        val files = directory.listFiles()!!.associate { it.name to it.readBytes() }
        assertEquals(setOf("client.p12.sealed", "client.p12.password.sealed"), files.keys)
        val sealed = files.getValue("client.p12.sealed")
        assertFalse("the PKCS#12 file is not on disk as it was imported", sealed.contentEquals(bytes))
        // Not even a 32-byte run of it: the whole file is AES-GCM ciphertext (Tink's prefix + nonce + tag around it).
        assertFalse(String(sealed, Charsets.ISO_8859_1).contains(String(bytes.copyOfRange(100, 132), Charsets.ISO_8859_1)))
        assertFalse(String(files.getValue("client.p12.password.sealed"), Charsets.ISO_8859_1).contains("p01 pkcs12 secret"))
        assertTrue(TestAndroidKeyStore.keys.containsKey(KeystoreSecrets.KEY_ALIAS))

        // A new process reads it back without asking for the password again.
        val reread = store()
        assertEquals(status, reread.status.value)
        val credentials = reread.credentials()!!
        assertEquals("p01", credentials.certificate.user)
        assertEquals(listOf(ca.certificate), credentials.trusted)
    }

    @Test
    fun import_wrongPassword_oneLineReason_nothingStored() {
        assertEquals(
            "the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file",
            importError(p12(), "wrong".toCharArray()),
        )
    }

    @Test
    fun import_notPkcs12_oneLineReason() {
        assertEquals(
            "the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file",
            importError(ca.certificateFile.readBytes()),
        )
    }

    @Test
    fun import_expired_saysWhenAndHowToGetANewOne() {
        val issued = now.minus(Duration.ofDays(40))
        assertEquals(
            "the client certificate of p01 expired on ${issued.plus(Duration.ofDays(30))}; ask for a new one (hapticon broker cert issue p01)",
            importError(p12(issued = issued, validity = Duration.ofDays(30))),
        )
    }

    @Test
    fun import_anotherUsersCertificate_refused() {
        assertEquals(
            "this certificate is for p02, not p01: the broker takes the user name from the certificate",
            importError(p12(user = "p02")),
        )
    }

    @Test
    fun import_withoutKeystore_refusedRatherThanStoredInClear() {
        val store = ClientCertificateStore(directory, keystoreAvailable = { false }, now = { now })
        val e = runCatching { store.import(p12(), password, "p01") }.exceptionOrNull()
        assertEquals("this phone has no Android Keystore to protect the certificate's key", e?.message)
        assertFalse(directory.exists() && directory.list()!!.isNotEmpty())
    }

    @Test
    fun remove_deletesBothFiles() {
        val store = store()
        store.import(p12(), password, "p01")
        store.remove()
        assertEquals(ClientCertificateStatus.None, store.status.value)
        assertEquals(emptyList<String>(), directory.list()!!.toList())
        assertNull(store().credentials())
    }

    @Test
    fun keystoreKeyLost_unusableWithReason() {
        store().import(p12(), password, "p01")
        TestAndroidKeyStore.keys.clear()
        val store = ClientCertificateStore(directory, now = { now })
        assertEquals(
            ClientCertificateStatus.Unusable("the stored certificate no longer opens on this phone (Keystore key lost); import it again"),
            store.status.value,
        )
        assertNull(store.credentials())
    }

    @Test
    fun expiredSinceImport_unusableWithTheExpiry() {
        store().import(p12(validity = Duration.ofDays(30)), password, "p01")
        val later = ClientCertificateStore(directory, now = { now.plus(Duration.ofDays(31)) })
        assertEquals(
            ClientCertificateStatus.Unusable("the client certificate of p01 expired on ${now.plus(Duration.ofDays(30))}; ask for a new one (hapticon broker cert issue p01)"),
            later.status.value,
        )
        assertNull(later.credentials())
    }

    @Test
    fun messengerSettings_carryTheStoredCertificateAndStudyCa_onTlsOnly() {
        store().import(p12(), password, "p01")
        val credentials = store().credentials()
        val tls = ChatComponent.mqttSettings("p01", "ssl://127.0.0.1:8883", null, DeviceId.generate(), credentials)
        assertEquals("p01", tls.clientCertificate?.user)
        assertArrayEquals(credentials!!.certificate.certificate.encoded, tls.clientCertificate!!.certificate.encoded)
        assertEquals(listOf(ca.certificate), tls.trustedCertificates)
        assertNull(tls.password)
        // A tcp:// broker cannot carry a certificate: the password logs in there.
        val plain = ChatComponent.mqttSettings("p01", "tcp://127.0.0.1:1883", "pw", DeviceId.generate(), credentials)
        assertNull(plain.clientCertificate)
        assertEquals(emptyList<Any>(), plain.trustedCertificates)
        assertEquals("pw", plain.password)
        assertNull(ChatComponent.mqttSettings("p01", "ssl://127.0.0.1:8883", "pw", DeviceId.generate(), null).clientCertificate)
    }
}
