package org.hapticon.app.data

import android.content.Context
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

/** The user's chat settings. */
data class ChatPreferences(
    /** The user name; null until the first-run screen set it. */
    val userName: String? = null,
    val brokerUrl: String = DEFAULT_BROKER_URL,
    /** Play an arriving message's icon at once (rate-limited). Off by default: vibrating unasked surprises people. */
    val autoPlay: Boolean = false,
    /** A renderer the user forces instead of the best available one ([org.hapticon.app.playback.Renderer] name), or null. */
    val rendererOverride: String? = null,
    /**
     * The broker password of [userName] (the MQTT user name is the Hapticon user name: the broker's ACL
     * ties topics to it), or null for a broker run with `--allow-anonymous`.
     */
    val brokerPassword: String? = null,
) {
    /** Omits the password, so that it never reaches a log. */
    override fun toString(): String =
        "ChatPreferences(userName=$userName, brokerUrl=$brokerUrl, autoPlay=$autoPlay, rendererOverride=$rendererOverride, " +
            "brokerPassword=${if (brokerPassword == null) "none" else "***"})"

    companion object {
        /** The emulator's alias for the host machine, where a development broker runs. */
        const val DEFAULT_BROKER_URL = "tcp://10.0.2.2:1883"
    }
}

/** Reads and writes [ChatPreferences]. */
interface ChatSettingsRepository {
    val preferences: StateFlow<ChatPreferences>
    fun update(transform: (ChatPreferences) -> ChatPreferences)
}

/**
 * Settings kept in SharedPreferences (small, synchronous reads at start-up are fine). The broker password
 * lives in a file of its own, `chat_credentials`, private to the app like the rest, so that settings can be
 * exported or shown without it. It is not encrypted at rest: Jetpack Security's EncryptedSharedPreferences is
 * deprecated, and a Keystore-wrapped key is left for later (docs/security.md).
 */
class SharedPreferencesChatSettings(context: Context) : ChatSettingsRepository {
    private val prefs = context.getSharedPreferences("chat", Context.MODE_PRIVATE)
    private val credentials = context.getSharedPreferences("chat_credentials", Context.MODE_PRIVATE)
    private val state = MutableStateFlow(read())
    override val preferences: StateFlow<ChatPreferences> = state.asStateFlow()

    override fun update(transform: (ChatPreferences) -> ChatPreferences) {
        val next = transform(state.value)
        prefs.edit()
            .putString(USER, next.userName)
            .putString(BROKER, next.brokerUrl)
            .putBoolean(AUTO_PLAY, next.autoPlay)
            .putString(RENDERER, next.rendererOverride)
            .apply()
        credentials.edit().putString(PASSWORD, next.brokerPassword).apply()
        state.value = next
    }

    private fun read() = ChatPreferences(
        userName = prefs.getString(USER, null),
        brokerUrl = prefs.getString(BROKER, null) ?: ChatPreferences.DEFAULT_BROKER_URL,
        autoPlay = prefs.getBoolean(AUTO_PLAY, false),
        rendererOverride = prefs.getString(RENDERER, null),
        brokerPassword = credentials.getString(PASSWORD, null),
    )

    private companion object {
        const val USER = "user"
        const val BROKER = "broker"
        const val AUTO_PLAY = "auto_play"
        const val RENDERER = "renderer"
        const val PASSWORD = "broker_password"
    }
}

/** In-memory settings, for tests. */
class InMemoryChatSettings(initial: ChatPreferences = ChatPreferences()) : ChatSettingsRepository {
    private val state = MutableStateFlow(initial)
    override val preferences: StateFlow<ChatPreferences> = state.asStateFlow()
    override fun update(transform: (ChatPreferences) -> ChatPreferences) {
        state.value = transform(state.value)
    }
}
