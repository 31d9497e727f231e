package org.hapticon.app.feature.chat

import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.material3.Icon
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Surface
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.vector.ImageVector
import androidx.compose.ui.platform.testTag
import androidx.compose.ui.semantics.LiveRegionMode
import androidx.compose.ui.semantics.liveRegion
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.combine
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.ConnectionState

/**
 * Whether messages can move now, as the chat list and a conversation say it in one line under their top bar.
 * Both screens read Room, so everything stays readable and writable meanwhile; what is written waits in the outbox.
 */
sealed interface ChatConnection {
    /** Connected, or the first attempt still under way: nothing to say. */
    data object Online : ChatConnection

    /** Android has no default network: the phone is offline. */
    data object Offline : ChatConnection

    /** The phone is online but the broker at [broker] did not answer; the client tries again by itself. */
    data class Unreachable(val broker: String) : ChatConnection

    /** The broker refused this account for good ([reason]: a bad password, not authorised): only Settings can fix it. */
    data class Refused(val reason: String) : ChatConnection

    companion object {
        /**
         * What to say for the sync's [state], Android's network ([online]; null while unknown) and the account's
         * [brokerUrl]. Offline comes first: with the network gone the MQTT client still reads Connected until its
         * keep-alive fails. A first attempt still under way says nothing (no flicker at every start); once an attempt
         * failed ([ConnectionState.Connecting.lastFailure]) the broker is unreachable.
         */
        fun of(state: ConnectionState, online: Boolean?, brokerUrl: String): ChatConnection = when {
            online == false -> Offline
            state is ConnectionState.Failed -> Refused(state.reason)
            state is ConnectionState.Connecting && state.lastFailure != null -> Unreachable(brokerName(brokerUrl))
            else -> Online
        }

        /** [ChatConnection.of] as it changes. */
        fun flow(state: Flow<ConnectionState>, online: Flow<Boolean?>, brokerUrl: Flow<String>): Flow<ChatConnection> =
            combine(state, online, brokerUrl, ::of)

        /** "192.168.1.20:1883" for `tcp://192.168.1.20:1883`: what a participant typed or scanned, without the scheme. */
        private fun brokerName(url: String): String =
            runCatching { BrokerAddress.parse(url) }.map { "${it.host}:${it.port}" }.getOrDefault(url)
    }
}

/** The line for this connection, or null when there is nothing to say. */
fun ChatConnection.line(): String? = when (this) {
    ChatConnection.Online -> null
    ChatConnection.Offline -> "Offline. Messages wait on this phone until it is back online."
    is ChatConnection.Unreachable -> "Can't reach the broker at $broker. Messages wait on this phone; trying again."
    is ChatConnection.Refused -> "The broker refused this account ($reason). Fix it in Settings."
}

/** The line of a conversation with a peer the broker has never seen: said so instead of a single tick forever. */
fun neverConnectedLine(peer: String): String = "$peer has never connected to this broker. Messages reach them once they do."

/** The test tag of the line under the top bar. */
const val CONNECTION_LINE_TAG: String = "connection-line"

/**
 * One line under a chat screen's top bar: [text] beside an icon, on the surface's high container colour so it reads
 * as part of the frame, not as a message. A polite live region: TalkBack says it when it appears or changes, after
 * whatever it is saying.
 */
@Composable
fun ConnectionLine(text: String, icon: ImageVector = HapticonIcons.CloudOff) {
    Surface(
        color = MaterialTheme.colorScheme.surfaceContainerHigh,
        contentColor = MaterialTheme.colorScheme.onSurface,
        modifier = Modifier.fillMaxWidth().testTag(CONNECTION_LINE_TAG).semantics { liveRegion = LiveRegionMode.Polite },
    ) {
        Row(Modifier.padding(horizontal = 16.dp, vertical = 8.dp), verticalAlignment = Alignment.CenterVertically) {
            Icon(icon, contentDescription = null, tint = MaterialTheme.colorScheme.onSurfaceVariant, modifier = Modifier.size(20.dp))
            Text(text, style = MaterialTheme.typography.bodyMedium, modifier = Modifier.padding(start = 12.dp))
        }
    }
}
