package org.hapticon.app.data

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The broker password at rest: encrypted under a Keystore key (Tink's AndroidKeystore, on the test provider). */
@RunWith(RobolectricTestRunner::class)
class KeystoreSecretsTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val credentials get() = context.getSharedPreferences("chat_credentials", Context.MODE_PRIVATE)

    @Before
    fun installKeystore() = TestAndroidKeyStore.install()

    @After
    fun removeKeystore() = TestAndroidKeyStore.uninstall()

    @Test
    fun password_savedAndReread_isStoredOnlyAsCiphertext() {
        SharedPreferencesChatSettings(context).update { it.copy(userName = "alice", brokerPassword = "correct horse battery") }
        val stored = credentials.all
        assertEquals(setOf("broker_password_sealed"), stored.keys)
        val sealed = stored["broker_password_sealed"] as String
        assertFalse(sealed, sealed.contains("correct") || String(android.util.Base64.decode(sealed, 0)).contains("correct"))
        assertTrue(TestAndroidKeyStore.keys.containsKey(KeystoreSecrets.KEY_ALIAS)) // the key was made in the Keystore
        assertEquals("correct horse battery", SharedPreferencesChatSettings(context).preferences.value.brokerPassword)
        SharedPreferencesChatSettings(context).update { it.copy(brokerPassword = null) }
        assertEquals(emptySet<String>(), credentials.all.keys)
    }

    @Test
    fun password_storedInClearByAnOlderVersion_isEncryptedOnFirstRead() {
        credentials.edit().putString("broker_password", "old secret").commit()
        assertEquals("old secret", SharedPreferencesChatSettings(context).preferences.value.brokerPassword)
        assertEquals(setOf("broker_password_sealed"), credentials.all.keys)
        assertEquals("old secret", SharedPreferencesChatSettings(context).preferences.value.brokerPassword)
    }

    @Test
    fun password_keystoreKeyLost_readsAsNoPassword() {
        SharedPreferencesChatSettings(context).update { it.copy(brokerPassword = "secret") }
        TestAndroidKeyStore.keys.clear() // the Keystore key is gone (another phone's backup restored)
        assertNull(SharedPreferencesChatSettings(context).preferences.value.brokerPassword)
    }

    @Test
    fun secrets_boundToTheirPurpose() {
        val secrets = KeystoreSecrets()
        val sealed = secrets.seal("x", "broker password")
        assertEquals("x", secrets.open(sealed, "broker password"))
        assertNull(secrets.open(sealed, "collector token"))
        assertNull(secrets.open("not base64!", "broker password"))
    }
}
