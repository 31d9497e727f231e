package org.hapticon.app.feature.chat

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.update
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.advanceUntilIdle
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.wireName
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Rule
import org.junit.Test
import java.io.ByteArrayOutputStream

/** The settings screen's state comes from its view model: the stored settings, the connection, the notices of broker tests and the export. */
class SettingsViewModelTest {
    @get:Rule val main = MainDispatcherRule()

    private class TestChatSettings(initial: ChatPreferences) : ChatSettingsRepository {
        private val state = MutableStateFlow(initial)
        override val preferences: StateFlow<ChatPreferences> = state
        override fun update(transform: (ChatPreferences) -> ChatPreferences) = state.update(transform)
    }

    private val settings = TestChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://10.0.0.2:1883"))
    private val connection = MutableStateFlow<ConnectionState>(ConnectionState.Connecting("timed out"))
    private val probed = mutableListOf<Triple<String, BrokerAddress, String?>>()
    private var probeAnswer: String? = null
    private var allowed: Boolean? = true
    private var republished = 0

    private fun viewModel() = SettingsViewModel(
        settings, connection, MutableStateFlow(listOf("bob's key changed")), MutableStateFlow(setOf("bob")),
        renderers = { listOf(RendererKind.ON_OFF) },
        canNotify = { allowed },
        probe = { user, broker, password -> probed += Triple(user, broker, password); probeAnswer },
        trustKey = { true },
        exportJson = { "{\"messages\":[]}" },
        republishCapabilities = { republished++ },
        io = main.dispatcher,
    )

    @Test
    fun firstState_isCompleteBeforeAnySourceEmits() {
        val vm = viewModel()
        assertEquals(
            SettingsUiState(
                settings.preferences.value, listOf(RendererKind.ON_OFF), "connecting (timed out)",
                securityWarnings = listOf("bob's key changed"), changedKeys = setOf("bob"),
            ),
            vm.uiState.value,
        )
    }

    @Test
    fun brokerIsSavedOnlyOnceItAnswered_andTheNoticeSaysWhy() = runTest(main.dispatcher) {
        val vm = viewModel()
        backgroundScope.launch { vm.uiState.collect {} }
        assertEquals("broker URL \"http://x\": scheme must be tcp, mqtt, ssl or mqtts", vm.setBroker("http://x"))
        assertEquals(emptyList<Any>(), probed)
        probeAnswer = "connection refused"
        assertNull(vm.setBroker("tcp://10.0.0.9:1883"))
        advanceUntilIdle()
        assertEquals("tcp://10.0.0.2:1883", settings.preferences.value.brokerUrl)
        assertEquals("Broker not changed: connection refused", vm.uiState.value.notice)

        probeAnswer = null
        assertNull(vm.setBroker("tcp://10.0.0.9:1883"))
        advanceUntilIdle()
        assertEquals("tcp://10.0.0.9:1883", settings.preferences.value.brokerUrl)
        assertEquals("Broker changed to tcp://10.0.0.9:1883", vm.uiState.value.notice)
        assertEquals(listOf("alice", "alice"), probed.map { it.first })

        connection.value = ConnectionState.Failed("not authorised")
        advanceUntilIdle()
        assertEquals("refused: not authorised", vm.uiState.value.connection)
    }

    @Test
    fun pitchSettingOrRendererChange_isPublishedToPeers_otherChangesAreNot() {
        val vm = viewModel()
        vm.update { it.copy(autoPlay = !it.autoPlay) }
        assertEquals(0, republished)
        vm.update { it.copy(pitchFit = PitchFit.CLAMP) }
        assertEquals(PitchFit.CLAMP, settings.preferences.value.pitchFit)
        assertEquals(1, republished)
        vm.update { it.copy(pitchFit = PitchFit.CLAMP) }
        assertEquals(1, republished)
        vm.update { it.copy(rendererOverride = RendererKind.ON_OFF.wireName) }
        assertEquals(2, republished)
    }

    @Test
    fun userName_isCheckedThenStoredTrimmed() {
        val vm = viewModel()
        assertEquals("Use 1 to 32 letters, digits, '.', '_' or '-'", vm.setUserName("a b"))
        assertEquals("alice", settings.preferences.value.userName)
        assertNull(vm.setUserName("  carol "))
        assertEquals("carol", settings.preferences.value.userName)
    }

    @Test
    fun refusedPermission_isShown_andExportWritesTheJson() = runTest(main.dispatcher) {
        val vm = viewModel()
        backgroundScope.launch { vm.uiState.collect {} }
        allowed = false
        vm.permissionAnswered(granted = false)
        advanceUntilIdle()
        assertEquals(false, vm.uiState.value.notificationsAllowed)
        assertEquals("Notifications are off: messages still arrive, but nothing announces them.", vm.uiState.value.notice)

        val out = ByteArrayOutputStream()
        vm.export("chats.json") { out }.join()
        advanceUntilIdle()
        assertEquals("{\"messages\":[]}", out.toString(Charsets.UTF_8))
        assertEquals("Exported to chats.json", vm.uiState.value.notice)
    }
}
