package org.hapticon.app.data

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

/** Chat settings held in memory, starting from [initial]: the tests' [ChatSettingsRepository]. */
class InMemoryChatSettings(initial: ChatPreferences = ChatPreferences()) : ChatSettingsRepository {
    private val state = MutableStateFlow(initial)
    override val preferences: StateFlow<ChatPreferences> = state.asStateFlow()
    override fun update(transform: (ChatPreferences) -> ChatPreferences) {
        state.value = transform(state.value)
    }
}
