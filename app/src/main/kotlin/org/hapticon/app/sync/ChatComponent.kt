package org.hapticon.app.sync

import android.content.Context
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.app.data.AppKeys
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.ChatSettingsRepository
import org.hapticon.app.data.ClientCredentials
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.SharedPreferencesChatSettings
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.AndroidVibrationGate
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.IconAudioCache
import org.hapticon.app.playback.Media3AudioCoupledOutput
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.UsageVibrator
import org.hapticon.app.playback.defaultVibrator
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.Clock
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings

/** Everything the chat feature needs, built once in the [org.hapticon.app.di.AppContainer]. */
class ChatComponent(
    val repository: ChatRepository,
    val icons: RoomIconRepository,
    val settings: ChatSettingsRepository,
    val sync: ChatSync,
    val player: AdaptiveHapticPlayer,
    private val detectDevice: () -> DeviceCapabilities,
    /** Tests a broker before first launch saves it; null when it answered, else the reason. */
    val probe: BrokerProbe = { _, _, _ -> null },
    /** Posts arriving messages as notifications; null where there is none (some tests). */
    val notifier: MessageNotifier? = null,
    /** Accepts a peer's changed end-to-end key for the current user; false when none is waiting. */
    val trustKey: (peer: String) -> Boolean = { false },
    /** The user's haptic patterns, offered in the composer after the icons; null in containers built without them. */
    val patterns: org.hapticon.app.data.RoomPatternRepository? = null,
    /** The user's client certificate for mutual TLS; null in containers built without one. */
    val certificates: org.hapticon.app.data.ClientCertificateRepository? = null,
    /** Whether a peer has published end-to-end keys ([peerKeys]); reads key files, so never on the main thread. */
    private val keysOf: (peer: String) -> PeerKeys = { PeerKeys.NOT_NEEDED },
    /** Whether the phone has a network ([NetworkWatcher.online]); null while unknown. */
    val online: kotlinx.coroutines.flow.StateFlow<Boolean?> = MutableStateFlow(null),
) {
    /**
     * Whether messages to [peer] can be sealed: [PeerKeys.NONE_PUBLISHED] when [peer] never published end-to-end keys
     * (unknown on this broker, or an old client without encryption), which a "New chat" should say. Reads files.
     */
    suspend fun peerKeys(peer: String): PeerKeys = kotlinx.coroutines.withContext(Dispatchers.IO) { keysOf(peer) }

    /** An invite link opened from outside, waiting for the Chats screen to apply it. */
    val pendingInvite: MutableStateFlow<String?> = MutableStateFlow(null)

    /** A conversation to open (a tapped message notification), waiting for the Chats screen. */
    val pendingConversation: MutableStateFlow<String?> = MutableStateFlow(null)

    /** Text shared to Hapticon from another app, waiting for the Chats screen to put it in a conversation's composer. */
    val pendingShare: MutableStateFlow<SharedText?> = MutableStateFlow(null)

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
            val keys = AppKeys(java.io.File(context.filesDir, "e2e"))
            val certificates = org.hapticon.app.data.ClientCertificateStore(java.io.File(context.filesDir, "client-certificate"))
            val devices = java.io.File(context.filesDir, "mqtt-devices")
            val vibrator = defaultVibrator(context)
            // Audio support does not change while the app runs; asking for it costs an effect-library query.
            val audio = DeviceCapabilities.detect(context, vibrator)
            val device = {
                DeviceCapabilities.detect(context, vibrator, audio.hapticPlaybackSupported, audio.hapticGeneratorAvailable)
            }
            val player = chatPlayer(
                UsageVibrator(vibrator, AndroidVibrationGate(context, vibrator)), device, settings,
                audio = Media3AudioCoupledOutput(context),
                audioCache = IconAudioCache(java.io.File(context.cacheDir, "icon-audio")),
            )
            val notifier = MessageNotifier(context) { settings.preferences.value.userName }
            val power = context.getSystemService(android.os.PowerManager::class.java)
            val sync = ChatSync(
                repository = repository,
                outbox = repository,
                settings = settings,
                messengerFactory = { user, broker, password ->
                    val sealed = settings.preferences.value.endToEnd
                    // The user's explicit choice in Settings; logged at every session so it is never silent.
                    if (!sealed) android.util.Log.w("ChatComponent", "end-to-end encryption is OFF for $user (chosen in Settings): the broker's operator can read and forge this account's messages")
                    mqttMessenger(user, broker, password, keys.takeIf { sealed }, devices, certificates.credentials())
                },
                player = player,
                rateLimiter = VibrationRateLimiter(Clock.MONOTONIC),
                localCapabilities = localCapabilities(device, settings),
                scope = scope,
                arrivalConditions = notifier::arrivalConditions,
                screenOn = { power?.isInteractive ?: true },
            )
            sync.onIncoming = { message, alert -> notifier.show(message, alert) }
            // Lives as long as the process, like the sync it nudges.
            val network = NetworkWatcher(context, sync).also { it.start() }
            val probe: BrokerProbe = { user, broker, password -> probeBroker(settings, sync, user, broker, password) }
            val trustKey = { peer: String ->
                val user = settings.preferences.value.userName
                (user != null && keys.trust(user, peer)).also { trusted -> if (trusted) sync.keyTrusted(peer) }
            }
            val patterns = org.hapticon.app.data.RoomPatternRepository(db.patternDao())
            val keysOf = { peer: String -> peerKeysOf(peer, settings.preferences.value, sync.connection.value, keys) }
            return ChatComponent(
                repository, RoomIconRepository(db.iconDao()), settings, sync, player, device, probe, notifier, trustKey, patterns, certificates, keysOf,
                online = network.online,
            )
        }

        /**
         * What this phone publishes as its capabilities, at connect and on every republish ([ChatSync]): read afresh
         * from [device] (the vibrator's renderer, frequency profile and envelope limits) and [settings] (the renderer
         * override and the pitch fit) each time.
         */
        internal fun localCapabilities(device: () -> DeviceCapabilities, settings: ChatSettingsRepository): (user: String) -> Capabilities =
            { user -> RendererChoice.capabilitiesOf(user, device(), rendererOverride(settings), settings.preferences.value.pitchFit) }

        /** The renderer the user forces in [settings], or null for the automatic choice. */
        internal fun rendererOverride(settings: ChatSettingsRepository): RendererKind? =
            settings.preferences.value.rendererOverride?.let { name -> RendererKind.entries.firstOrNull { it.name == name } }

        /**
         * The app's player: plays on [vibrator] as [device] allows, with the renderer override and the pitch fit
         * ([org.hapticon.app.data.ChatPreferences.pitchFit]) read from [settings] at every play, so a change in
         * Settings applies to the next icon or pattern.
         */
        internal fun chatPlayer(
            vibrator: UsageVibrator,
            device: () -> DeviceCapabilities,
            settings: ChatSettingsRepository,
            audio: org.hapticon.app.playback.AudioCoupledOutput? = null,
            audioCache: IconAudioCache? = null,
        ): AdaptiveHapticPlayer = AdaptiveHapticPlayer(
            vibrator, device, { rendererOverride(settings) },
            audio = audio, audioCache = audioCache,
            pitchFit = { settings.preferences.value.pitchFit },
        )

        /**
         * How the messenger of [user] connects to [broker] as [device], with the keep-alive the keep-alive alarm is timed for
         * ([KeepAlive.MQTT_KEEP_ALIVE_SECONDS]): with [credentials] on an `ssl://` broker, the client
         * certificate logs in and the study CA in its chain is what the broker's certificate must chain to
         * (docs/security.md, "Client certificates"); a `tcp://` broker cannot carry one, so there the password
         * alone logs in. Throws [IllegalArgumentException] for an invalid address, or a certificate of another user.
         */
        internal fun mqttSettings(user: String, broker: String, password: String?, device: DeviceId, credentials: ClientCredentials?): MqttSettings {
            val address = BrokerAddress.parse(broker)
            val tls = credentials?.takeIf { address.tls }
            return MqttSettings(
                address, user, password, device, keepAliveSeconds = KeepAlive.MQTT_KEEP_ALIVE_SECONDS,
                clientCertificate = tls?.certificate, trustedCertificates = tls?.trusted.orEmpty(),
            )
        }

        /**
         * The messenger of [user] at [broker]; with [keys], sealed end to end; with [credentials], logged in by
         * client certificate ([mqttSettings]). Its broker session is this phone's own for [user] (client id
         * `USER:DEVICE`, the device id kept in [devices]/USER, a secret: docs/security.md), so the user's other
         * devices keep theirs. Null, logged, when the address is not valid, the device id cannot be kept, or the
         * end-to-end keys do not open (the Keystore key is gone): rather no chat than a plaintext one.
         */
        internal fun mqttMessenger(
            user: String, broker: String, password: String?, keys: AppKeys?, devices: java.io.File, credentials: ClientCredentials? = null,
        ): Messenger? = try {
            val device = DeviceId.loadOrCreate(java.io.File(devices, user))
            MqttMessenger(mqttSettings(user, broker, password, device, credentials), keys?.endToEnd(user))
        } catch (e: java.io.IOException) {
            android.util.Log.w("ChatComponent", "no messenger for $user: this phone's device id cannot be kept (${e.message})")
            null
        } catch (e: IllegalArgumentException) {
            android.util.Log.w("ChatComponent", "no messenger for $user at $broker: ${e.message}")
            null
        } catch (e: java.security.GeneralSecurityException) {
            android.util.Log.w("ChatComponent", "no messenger for $user: end-to-end keys do not open (${e.message})")
            null
        }

        /**
         * Tests [broker] for [user] through the real session, without saving anything first: the session runs as
         * the candidate ([ChatSync.trySession]) while the settings keep the previous account, so no screen shows an
         * account that is not yet there (first launch stays on its form, with what was typed). The answer is the
         * first Connected or Failed state of that session within [timeoutMillis]; Connected saves the account (the
         * session goes on as it is), anything else leaves the settings as they were. A separate probe client would
         * be unsafe: the broker binds the client id to the user name, so a second connection as [user] would take
         * over (and with a clean session erase) the user's queued messages; through the real session whatever
         * arrives is stored.
         */
        internal suspend fun probeBroker(
            settings: ChatSettingsRepository,
            sync: ChatSync,
            user: String,
            broker: BrokerAddress,
            password: String?,
            timeoutMillis: Long = PROBE_TIMEOUT_MILLIS,
        ): String? {
            val target = ChatSync.SessionTarget(user, broker.toString(), password)
            return sync.trySession(target) {
                val state = kotlinx.coroutines.withTimeoutOrNull(timeoutMillis) { sync.settledStateOf(target) }
                if (state == org.hapticon.messaging.ConnectionState.Connected) {
                    // A first account (none before) owes the user the offer of Stay reachable, saved in the same
                    // write: no screen ever sees the account without it (the chat list would flash by).
                    settings.update {
                        it.copy(
                            userName = user, brokerUrl = broker.toString(), brokerPassword = password,
                            reachableOfferPending = it.reachableOfferPending || it.userName == null,
                        )
                    }
                    return@trySession null
                }
                val lastFailure = (sync.connection.value as? org.hapticon.messaging.ConnectionState.Connecting)?.lastFailure
                when (state) {
                    is org.hapticon.messaging.ConnectionState.Failed -> "The broker at $broker refused the connection: ${state.reason}"
                    else -> "No answer from $broker within ${timeoutMillis / 1000} s. Is the broker running on the study computer, " +
                        "and is this phone on the same network?" + (lastFailure?.let { " ($it)" } ?: "")
                }
            }
        }

        private const val PROBE_TIMEOUT_MILLIS = 5_000L

        /**
         * What is known of [peer]'s end-to-end keys for the account of [prefs]: with encryption off nothing is needed; a
         * pinned key means published; without one, a session that is [connection] Connected has read every retained key
         * (`hapticon/v1/keys/+`), so [peer] published none; before that it is not known yet.
         */
        internal fun peerKeysOf(peer: String, prefs: org.hapticon.app.data.ChatPreferences, connection: org.hapticon.messaging.ConnectionState, keys: AppKeys): PeerKeys {
            if (!prefs.endToEnd) return PeerKeys.NOT_NEEDED
            if (!org.hapticon.messaging.Topics.isValidUserName(peer)) return PeerKeys.NONE_PUBLISHED // nobody can publish under it
            val user = prefs.userName ?: return PeerKeys.NOT_KNOWN_YET
            val known = try {
                keys.endToEnd(user).hasKeyOf(peer)
            } catch (e: java.security.GeneralSecurityException) {
                return PeerKeys.NOT_KNOWN_YET // no keys of our own (the Keystore key is gone): the session does not run either
            } catch (e: IllegalStateException) {
                return PeerKeys.NOT_KNOWN_YET // a damaged pin file: the messenger refuses to guess too
            }
            return when {
                known -> PeerKeys.PUBLISHED
                connection == org.hapticon.messaging.ConnectionState.Connected -> PeerKeys.NONE_PUBLISHED
                else -> PeerKeys.NOT_KNOWN_YET
            }
        }

    }
}
