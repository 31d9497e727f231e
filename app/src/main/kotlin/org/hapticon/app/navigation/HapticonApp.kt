package org.hapticon.app.navigation

import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.consumeWindowInsets
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.Icon
import androidx.compose.material3.NavigationBar
import androidx.compose.material3.NavigationBarItem
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.saveable.rememberSaveableStateHolder
import androidx.compose.ui.Modifier
import org.hapticon.app.di.AppContainer
import org.hapticon.app.feature.chat.rememberChatsNavigation
import androidx.compose.runtime.getValue
import androidx.lifecycle.compose.collectAsStateWithLifecycle
import kotlinx.coroutines.flow.MutableStateFlow

/**
 * The app's frame: the bottom navigation bar and the selected destination. State-based on purpose
 * (two, soon three, flat destinations need no back stack); each destination keeps its saveable UI
 * state while another is shown.
 */
@Composable
fun HapticonApp(
    container: AppContainer,
    selected: TopLevelDestination,
    onSelect: (TopLevelDestination) -> Unit,
) {
    val saveableStates = rememberSaveableStateHolder()
    // During a participant's session the bar is hidden: the participant sees the session and nothing else.
    val studyPreferences by (container.study?.settings?.preferences ?: NO_STUDY).collectAsStateWithLifecycle()
    val inSession = selected == TopLevelDestination.STUDY && studyPreferences?.activeSessionId != null
    // Inside a conversation (any Chats screen but the list) the bar is hidden, as in Signal: the composer sits on the
    // keyboard, and the bar's 80 dp go to the messages.
    val chatsNavigation = rememberChatsNavigation()
    val inChat = selected == TopLevelDestination.CHATS && container.chat != null && !chatsNavigation.atTopLevel
    Scaffold(
        bottomBar = {
            if (!inSession && !inChat) NavigationBar {
                for (destination in TopLevelDestination.entries) {
                    NavigationBarItem(
                        selected = destination == selected,
                        onClick = { onSelect(destination) },
                        // The label names the item for accessibility; the icon is decoration.
                        icon = { Icon(destination.icon, contentDescription = null) },
                        label = { Text(destination.label) },
                    )
                }
            }
        },
    ) { padding ->
        Box(Modifier.fillMaxSize().padding(padding).consumeWindowInsets(padding)) {
            saveableStates.SaveableStateProvider(selected.name) {
                Destination(container, selected, chatsNavigation, onSelect)
            }
        }
    }
}

private val NO_STUDY = MutableStateFlow<org.hapticon.app.study.StudyPreferences?>(null)
