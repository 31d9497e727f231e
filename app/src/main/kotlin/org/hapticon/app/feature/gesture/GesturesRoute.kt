package org.hapticon.app.feature.gesture

import android.net.Uri
import android.os.SystemClock
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.padding
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.PrimaryTabRow
import androidx.compose.material3.Tab
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalContext
import androidx.compose.ui.unit.dp
import androidx.lifecycle.viewmodel.compose.viewModel
import androidx.lifecycle.viewmodel.initializer
import androidx.lifecycle.viewmodel.viewModelFactory
import org.hapticon.app.data.ChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.gesture.GestureComponent
import org.hapticon.app.playback.HapticPlayer
import java.io.FileNotFoundException

/** The Gestures destination's parts, in tab order. */
enum class GestureTab(val label: String) { RECORD("Record"), TEACH("Teach"), RECOGNISE("Recognise"), SOCIAL("Social touch") }

/**
 * The Gestures destination: record and make an icon, teach a personal model, recognise live and send, recognise social
 * touch. Without chat ([icons] and [messages] null) an icon cannot be saved nor a recognised gesture sent; [user] is
 * the sender's name, [onSent] wakes the chat's sync.
 */
@Composable
fun GesturesRoute(
    gestures: GestureComponent?,
    icons: RoomIconRepository?,
    messages: ChatRepository?,
    player: HapticPlayer,
    user: () -> String?,
    onSent: () -> Unit,
) {
    if (gestures == null) {
        Text("Gestures are not available in this build", Modifier.padding(16.dp))
        return
    }
    val recorder: RecorderViewModel = viewModel(factory = viewModelFactory { initializer { RecorderViewModel(gestures, icons, player) } })
    val teach: TeachViewModel = viewModel(factory = viewModelFactory { initializer { TeachViewModel(gestures) } })
    val recognition: RecognitionViewModel = viewModel(
        factory = viewModelFactory { initializer { RecognitionViewModel(gestures, messages, user, onSent) } },
    )
    val social: SocialTouchViewModel = viewModel(
        factory = viewModelFactory {
            initializer {
                SocialTouchViewModel(
                    gestures.socialTouch, messages, user, onSent,
                    // The pad's frames carry MotionEvent times: uptime.
                    clockSeconds = { SystemClock.uptimeMillis() / 1000.0 },
                )
            }
        },
    )
    var tab by rememberSaveable { mutableStateOf(GestureTab.RECORD) }
    val context = LocalContext.current
    val opener = { uri: Uri -> { context.contentResolver.openInputStream(uri) ?: throw FileNotFoundException("cannot open $uri") } }
    val importRecording = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { recorder.importFile(opener(it), it.lastPathSegment ?: "file") }
    }
    val importModel = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { teach.importModel(opener(it), it.lastPathSegment ?: "file") }
    }
    val importSocialModel = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { social.importModel(opener(it), it.lastPathSegment ?: "file") }
    }
    val classifyContacts = rememberLauncherForActivityResult(ActivityResultContracts.OpenDocument()) { uri ->
        uri?.let { social.classifyFile(opener(it), it.lastPathSegment ?: "file") }
    }
    Column(Modifier.fillMaxSize()) {
        GestureTabs(tab) { tab = it }
        when (tab) {
            GestureTab.RECORD -> RecorderRoute(recorder, gestures.touch, onImport = { importRecording.launch(arrayOf("text/*", "audio/*", "application/octet-stream")) })
            GestureTab.TEACH -> TeachRoute(teach, gestures.touch, onImportModel = { importModel.launch(arrayOf("application/json", "text/*", "application/octet-stream")) })
            GestureTab.RECOGNISE -> RecognitionRoute(recognition, gestures.touch)
            GestureTab.SOCIAL -> SocialTouchRoute(
                social,
                onImportModel = { importSocialModel.launch(arrayOf("application/json", "text/*", "application/octet-stream")) },
                onClassifyFile = { classifyContacts.launch(arrayOf("text/*", "application/octet-stream")) },
            )
        }
    }
}

@OptIn(ExperimentalMaterial3Api::class)
@Composable
private fun GestureTabs(selected: GestureTab, onSelect: (GestureTab) -> Unit) {
    PrimaryTabRow(selectedTabIndex = selected.ordinal) {
        for (tab in GestureTab.entries) Tab(selected = tab == selected, onClick = { onSelect(tab) }, text = { Text(tab.label) })
    }
}
