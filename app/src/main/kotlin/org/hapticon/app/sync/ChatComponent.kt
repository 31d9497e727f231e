package org.hapticon.app.sync

import android.content.Context
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.SharedPreferencesChatSettings
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.IconAudioCache
import org.hapticon.app.playback.Media3AudioCoupledOutput
import org.hapticon.messaging.RendererKind
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.defaultVibrator
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.Clock
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.mqtt.BrokerAddress
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings

/** Everything the chat feature needs, built once in the [org.hapticon.app.AppContainer]. */
class ChatComponent(
    val repository: ChatRepository,
    val icons: RoomIconRepository,
    val settings: ChatSettingsRepository,
    val sync: ChatSync,
    val player: AdaptiveHapticPlayer,
    private val detectDevice: () -> DeviceCapabilities,
    /** Tests a broker before first launch saves it; null when it answered, else the reason. */
    val probe: org.hapticon.app.feature.chat.BrokerProbe = { _, _ -> null },
    /** Posts arriving messages as notifications; null where there is none (some tests). */
    val notifier: MessageNotifier? = null,
) {
    /** An invite link opened from outside, waiting for the Chats screen to apply it. */
    val pendingInvite: MutableStateFlow<String?> = MutableStateFlow(null)

    /** A conversation to open (a tapped message notification), waiting for the Chats screen. */
    val pendingConversation: MutableStateFlow<String?> = MutableStateFlow(null)

    /** What this phone can do now (the vibrator is asked again each time: cheap, and a test may change it). */
    val device: DeviceCapabilities get() = detectDevice()

    /** The renderer the user's override or the automatic choice gives [icon] here. */
    fun localRenderer(icon: HapticIcon): RendererKind = player.rendererFor(icon)

    companion object {
        fun create(
            context: Context,
            scope: CoroutineScope = CoroutineScope(SupervisorJob() + Dispatchers.Default),
            db: HapticonDatabase = HapticonDatabase.create(context),
        ): ChatComponent {
            val repository = OfflineFirstChatRepository(db)
            val settings = SharedPreferencesChatSettings(context)
            val vibrator = defaultVibrator(context)
            // Audio support does not change while the app runs; asking for it costs an effect-library query.
            val audio = DeviceCapabilities.detect(context, vibrator)
            val device = {
                DeviceCapabilities.detect(context, vibrator, audio.hapticPlaybackSupported, audio.hapticGeneratorAvailable)
            }
            val override = { settings.preferences.value.rendererOverride?.let { name -> RendererKind.entries.firstOrNull { it.name == name } } }
            val player = AdaptiveHapticPlayer(
                vibrator, device, override,
                audio = Media3AudioCoupledOutput(context),
                audioCache = IconAudioCache(java.io.File(context.cacheDir, "icon-audio")),
            )
            val deviceId = deviceId(context)
            val sync = ChatSync(
                repository = repository,
                outbox = repository,
                settings = settings,
                messengerFactory = { user, broker -> mqttMessenger(user, broker, deviceId) },
                player = player,
                rateLimiter = VibrationRateLimiter(Clock.MONOTONIC),
                localCapabilities = { user -> RendererChoice.capabilitiesOf(user, device(), override()) },
                scope = scope,
                quietNow = { doNotDisturb(context) },
            )
            val notifier = MessageNotifier(context) { settings.preferences.value.userName }
            sync.onIncoming = { message, _ -> notifier.show(message) }
            val probe: org.hapticon.app.feature.chat.BrokerProbe = { user, broker -> probeBroker(user, broker, deviceId) }
            return ChatComponent(repository, RoomIconRepository(db.iconDao()), settings, sync, player, device, probe, notifier)
        }

        private fun mqttMessenger(user: String, broker: String, deviceId: String): Messenger? = try {
            MqttMessenger(MqttSettings(BrokerAddress.parse(broker), user, deviceId))
        } catch (e: IllegalArgumentException) {
            android.util.Log.w("ChatComponent", "no messenger for $user at $broker: ${e.message}")
            null
        }

        /**
         * Connects to [broker] as [user] with a separate probe client (its own client id, so the real
         * session is not taken over) and disconnects; null when connected within [PROBE_TIMEOUT_MILLIS].
         */
        private suspend fun probeBroker(user: String, broker: BrokerAddress, deviceId: String): String? {
            val messenger = try {
                MqttMessenger(MqttSettings(broker, user, "$deviceId-probe".take(32)))
            } catch (e: IllegalArgumentException) {
                return e.message
            }
            return try {
                val connected = kotlinx.coroutines.withTimeoutOrNull(PROBE_TIMEOUT_MILLIS) {
                    messenger.connect(org.hapticon.messaging.InboxListener { })
                    true
                }
                when {
                    connected == true -> null
                    messenger.state.value is org.hapticon.messaging.ConnectionState.Failed ->
                        "The broker at $broker refused the connection: ${(messenger.state.value as org.hapticon.messaging.ConnectionState.Failed).reason}"
                    else -> "No answer from $broker within ${PROBE_TIMEOUT_MILLIS / 1000} s. Is `hapticon broker` running, " +
                        "and is this phone on the same network?" + ((messenger.state.value as? org.hapticon.messaging.ConnectionState.Connecting)?.lastFailure?.let { " ($it)" } ?: "")
                }
            } catch (e: Exception) {
                if (e is kotlinx.coroutines.CancellationException) throw e
                "Could not reach $broker: ${e.message}"
            } finally {
                runCatching { messenger.disconnect() }
            }
        }

        private const val PROBE_TIMEOUT_MILLIS = 5_000L

        /** Do-not-disturb is on when the interruption filter lets less than everything through. */
        private fun doNotDisturb(context: Context): Boolean {
            val manager = context.getSystemService(android.app.NotificationManager::class.java) ?: return false
            return manager.currentInterruptionFilter > android.app.NotificationManager.INTERRUPTION_FILTER_ALL
        }

        /** A stable id for this installation (the MQTT session is per user and device). */
        private fun deviceId(context: Context): String {
            val prefs = context.getSharedPreferences("device", Context.MODE_PRIVATE)
            return prefs.getString("id", null) ?: ("android-" + java.util.UUID.randomUUID().toString().take(8)).also {
                prefs.edit().putString("id", it).apply()
            }
        }
    }
}
