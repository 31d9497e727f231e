package org.hapticon.app.sync

import android.content.Context
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.SharedPreferencesChatSettings
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.IconAudioCache
import org.hapticon.app.playback.Media3AudioCoupledOutput
import org.hapticon.app.playback.AdaptiveRenderer
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
) {
    /** What this phone can do now (the vibrator is asked again each time: cheap, and a test may change it). */
    val device: DeviceCapabilities get() = detectDevice()

    /** The renderer the user's override or the automatic choice gives [icon] here. */
    fun localRenderer(icon: HapticIcon): AdaptiveRenderer = player.rendererFor(icon)

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
            val override = { settings.preferences.value.rendererOverride?.let { name -> AdaptiveRenderer.entries.firstOrNull { it.name == name } } }
            val player = AdaptiveHapticPlayer(
                vibrator, device, override,
                audio = Media3AudioCoupledOutput(context),
                audioCache = IconAudioCache(java.io.File(context.cacheDir, "icon-audio")),
            )
            val sync = ChatSync(
                repository = repository,
                outbox = repository,
                settings = settings,
                messengerFactory = ::mqttMessenger,
                player = player,
                rateLimiter = VibrationRateLimiter(Clock.MONOTONIC),
                localCapabilities = { user -> RendererChoice.capabilitiesOf(user, device(), override()) },
                scope = scope,
            )
            return ChatComponent(repository, RoomIconRepository(db.iconDao()), settings, sync, player, device)
        }

        // The client id is the user name (the broker binds it to the login), so no per-device id any more.
        private fun mqttMessenger(user: String, broker: String, password: String?): Messenger? = try {
            MqttMessenger(MqttSettings(BrokerAddress.parse(broker), user, password))
        } catch (e: IllegalArgumentException) {
            android.util.Log.w("ChatComponent", "no messenger for $user at $broker: ${e.message}")
            null
        }
    }
}
