package org.hapticon.app.feature.chat

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import java.io.File
import java.time.Duration
import java.time.Instant
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ClientCertificateStatus
import org.hapticon.app.data.ClientCertificateStore
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.TestAndroidKeyStore
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.broker.CertificateAuthority
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** Settings' client certificate: a picked file asks for its password, a wrong one says so and asks again, a right one is stored and reconnects. */
@RunWith(RobolectricTestRunner::class)
class SettingsCertificateTest {
    @get:Rule val main = MainDispatcherRule()
    @get:Rule val temp = TemporaryFolder()

    private val now = Instant.parse("2026-11-26T10:00:00Z")
    private lateinit var store: ClientCertificateStore
    private lateinit var p12: ByteArray
    private var restarts = 0

    @Before
    fun setUp() {
        TestAndroidKeyStore.install()
        val ca = CertificateAuthority.init(temp.newFolder("ca"), "Hapticon test study", listOf("127.0.0.1"), now)
        p12 = ca.issueClient("p01", "right".toCharArray(), Duration.ofDays(365), now)
        val files = ApplicationProvider.getApplicationContext<Context>().filesDir
        store = ClientCertificateStore(File(files, "client-certificate").apply { deleteRecursively() }, now = { now })
    }

    @After
    fun tearDown() = TestAndroidKeyStore.uninstall()

    private fun viewModel() = SettingsViewModel(
        InMemoryChatSettings(ChatPreferences(userName = "p01", brokerUrl = "ssl://10.0.0.2:8883")),
        MutableStateFlow(ConnectionState.Connected), MutableStateFlow(emptyList()), MutableStateFlow(emptySet()),
        renderers = { emptyList() }, canNotify = { true }, probe = { _, _, _ -> null }, trustKey = { true },
        exportJson = { "{}" }, republishCapabilities = {}, io = main.dispatcher, certificates = store, onCertificateChanged = { restarts++ },
    )

    @Test
    fun pickWrongPasswordThenRight_storedAndReconnected_thenRemoved() = runTest(main.dispatcher) {
        val vm = viewModel()
        val collector = backgroundScope.launchCollect(vm)
        vm.certificatePicked(p12, "p01.p12")
        advanceUntilIdle()
        assertEquals(CertificateImport("p01.p12"), vm.uiState.value.certificateImport)

        vm.unlockCertificate("wrong")
        advanceUntilIdle()
        assertEquals(
            CertificateImport("p01.p12", "the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file"),
            vm.uiState.value.certificateImport,
        )
        assertEquals(ClientCertificateStatus.None, vm.uiState.value.clientCertificate)
        assertEquals(0, restarts)

        vm.unlockCertificate("right")
        advanceUntilIdle()
        val state = vm.uiState.value
        assertNull(state.certificateImport)
        assertEquals(ClientCertificateStatus.InUse("p01", now.plus(Duration.ofDays(365)), "Hapticon test study"), state.clientCertificate)
        assertEquals("Client certificate of p01 in use until 2027-11-26", state.notice)
        assertEquals(1, restarts)

        vm.removeCertificate()
        advanceUntilIdle()
        assertEquals(ClientCertificateStatus.None, vm.uiState.value.clientCertificate)
        assertEquals("Client certificate removed", vm.uiState.value.notice)
        assertEquals(2, restarts)
        collector.cancel()
    }

    @Test
    fun unreadableFile_noticeSaysWhy() = runTest(main.dispatcher) {
        val vm = viewModel()
        val collector = backgroundScope.launchCollect(vm)
        vm.certificateUnreadable("p01.p12: larger than a client certificate (.p12) may be (65536 bytes)")
        advanceUntilIdle()
        assertEquals("Certificate not imported: p01.p12: larger than a client certificate (.p12) may be (65536 bytes)", vm.uiState.value.notice)
        collector.cancel()
    }

    private fun kotlinx.coroutines.CoroutineScope.launchCollect(vm: SettingsViewModel) = launch { vm.uiState.collect {} }
}
