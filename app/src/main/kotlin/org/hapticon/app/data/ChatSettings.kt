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
) {
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

/** Settings kept in SharedPreferences (small, synchronous reads at start-up are fine). */
class SharedPreferencesChatSettings(context: Context) : ChatSettingsRepository {
    private val prefs = context.getSharedPreferences("chat", Context.MODE_PRIVATE)
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
        state.value = next
    }

    private fun read() = ChatPreferences(
        userName = prefs.getString(USER, null),
        brokerUrl = prefs.getString(BROKER, null) ?: ChatPreferences.DEFAULT_BROKER_URL,
        autoPlay = prefs.getBoolean(AUTO_PLAY, false),
        rendererOverride = prefs.getString(RENDERER, null),
    )

    private companion object {
        const val USER = "user"
        const val BROKER = "broker"
        const val AUTO_PLAY = "auto_play"
        const val RENDERER = "renderer"
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
