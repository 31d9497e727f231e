package org.hapticon.app.feature.chat

import androidx.compose.foundation.Canvas
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.imePadding
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.foundation.text.selection.SelectionContainer
import androidx.compose.foundation.verticalScroll
import androidx.compose.material3.Button
import androidx.compose.material3.CircularProgressIndicator
import androidx.compose.material3.ExperimentalMaterial3Api
import androidx.compose.material3.Icon
import androidx.compose.material3.IconButton
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.OutlinedTextField
import androidx.compose.material3.Scaffold
import androidx.compose.material3.Surface
import androidx.compose.material3.Text
import androidx.compose.material3.TopAppBar
import androidx.compose.runtime.Composable
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.geometry.Offset
import androidx.compose.ui.geometry.Size
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.text.font.FontFamily
import androidx.compose.ui.text.style.TextAlign
import androidx.compose.ui.unit.dp
import com.google.zxing.BarcodeFormat
import com.google.zxing.EncodeHintType
import com.google.zxing.common.BitMatrix
import com.google.zxing.qrcode.QRCodeWriter
import com.google.zxing.qrcode.decoder.ErrorCorrectionLevel
import org.hapticon.app.designsystem.HapticonIcons
import org.hapticon.messaging.InviteLink

/**
 * First launch, written for a study participant: what the app does and that the invite from the study team
 * fills everything in (scan its QR code, [onScanInvite], or open its link); then the connection is tested before
 * anything is saved. A failure gives its reason and keeps what was typed (the screen stays: the test saves
 * nothing, [org.hapticon.app.sync.ChatComponent.probeBroker]). [prefilledBroker] is what an opened or scanned
 * invite filled in (empty otherwise: no address suits every phone).
 */
@Composable
fun FirstLaunchScreen(
    prefilledBroker: String,
    check: AccountCheck,
    onScanInvite: () -> Unit = {},
    onSave: (String, String, String) -> Unit,
) {
    var name by rememberSaveable { mutableStateOf("") }
    var password by rememberSaveable { mutableStateOf("") }
    var broker by rememberSaveable(prefilledBroker) { mutableStateOf(prefilledBroker) }
    val testing = check is AccountCheck.Testing
    Column(
        Modifier.fillMaxSize().imePadding().verticalScroll(rememberScrollState()).padding(24.dp),
        verticalArrangement = Arrangement.spacedBy(16.dp),
    ) {
        Icon(HapticonIcons.Vibration, contentDescription = null, tint = MaterialTheme.colorScheme.primary, modifier = Modifier.size(48.dp))
        Text("Welcome to Hapticon", style = MaterialTheme.typography.headlineMedium)
        Text(
            "Send messages you can feel: each can carry a stroke, a hit, a knock or a hug, played on your phone's vibration motor. " +
                "Messages go through your study's own server, so no company sees them. " +
                "If the study team gave you an invite, scan its code: it fills in the server for you.",
            style = MaterialTheme.typography.bodyLarge,
        )
        OutlinedButton(onClick = onScanInvite, enabled = !testing, modifier = Modifier.fillMaxWidth()) {
            Icon(HapticonIcons.QrCodeScanner, contentDescription = null)
            Text("Scan invite code", Modifier.padding(start = 8.dp))
        }
        OutlinedTextField(
            name, { name = it }, label = { Text("Your user name") }, singleLine = true, enabled = !testing,
            supportingText = { Text("Others start a chat with you by this name") },
            modifier = Modifier.fillMaxWidth().semantics { contentDescription = "Your user name" },
        )
        OutlinedTextField(
            broker, { broker = it }, label = { Text("Server address") }, singleLine = true, enabled = !testing,
            placeholder = { Text("192.168.1.20:1883") },
            supportingText = { Text("From your invite or the study team") },
            modifier = Modifier.fillMaxWidth().semantics { contentDescription = "Server address" },
        )
        OutlinedTextField(
            password, { password = it }, label = { Text("Password") }, singleLine = true, enabled = !testing,
            visualTransformation = androidx.compose.ui.text.input.PasswordVisualTransformation(),
            keyboardOptions = androidx.compose.foundation.text.KeyboardOptions(keyboardType = androidx.compose.ui.text.input.KeyboardType.Password),
            supportingText = { Text("From the study team; leave it empty if you were given none") },
            modifier = Modifier.fillMaxWidth().semantics { contentDescription = "Password" },
        )
        when (check) {
            is AccountCheck.Failed -> Text(check.reason, color = MaterialTheme.colorScheme.error, style = MaterialTheme.typography.bodyMedium)
            is AccountCheck.Testing -> Row(verticalAlignment = Alignment.CenterVertically) {
                CircularProgressIndicator(Modifier.size(20.dp), strokeWidth = 2.dp)
                Text("Connecting to ${check.broker}…", Modifier.padding(start = 12.dp))
            }
            AccountCheck.Idle, AccountCheck.Saved -> Unit
        }
        Button(onClick = { onSave(name, broker, password) }, enabled = !testing, modifier = Modifier.fillMaxWidth()) { Text("Test connection and start") }
        Text(
            "Running a study yourself? The Hapticon command on your computer starts the server and prints each participant's invite.",
            style = MaterialTheme.typography.bodyMedium, color = MaterialTheme.colorScheme.onSurfaceVariant,
        )
    }
}

/**
 * The invite: a QR code and the link it holds, which another phone opens to add this user and fill in
 * the broker. Shared as text through the system share sheet.
 */
@OptIn(ExperimentalMaterial3Api::class)
@Composable
fun InviteScreen(link: InviteLink?, onBack: () -> Unit, onShare: (String) -> Unit, onScan: () -> Unit = {}) {
    Scaffold(
        topBar = {
            TopAppBar(
                title = { Text("Invite") },
                navigationIcon = { IconButton(onClick = onBack) { Icon(HapticonIcons.ArrowBack, contentDescription = "Back to chats") } },
            )
        },
    ) { padding ->
        Column(
            Modifier.fillMaxSize().padding(padding).verticalScroll(rememberScrollState()).padding(24.dp),
            horizontalAlignment = Alignment.CenterHorizontally,
            verticalArrangement = Arrangement.spacedBy(16.dp),
        ) {
            if (link == null) {
                Text("Set a broker in Settings first: the invite carries it.", style = MaterialTheme.typography.bodyLarge)
                return@Column
            }
            Text(
                "Let someone scan this with their camera, or share the link. Opening it adds ${link.user} as a contact " +
                    "and, on a new phone, fills in the broker ${link.broker}.",
                style = MaterialTheme.typography.bodyLarge, textAlign = TextAlign.Center,
            )
            val matrix = remember(link) { qrMatrix(link.toString()) }
            // A QR code needs dark on light whatever the theme; the white margin is the code's quiet zone.
            Surface(shape = RoundedCornerShape(16.dp), color = Color.White) {
                QrCode(matrix, Modifier.padding(16.dp).size(240.dp).semantics { contentDescription = "QR code of the invite link" })
            }
            SelectionContainer {
                Text(link.toString(), style = MaterialTheme.typography.bodySmall, fontFamily = FontFamily.Monospace, textAlign = TextAlign.Center)
            }
            OutlinedButton(onClick = { onShare(link.toString()) }) {
                Icon(HapticonIcons.Share, contentDescription = null)
                Text("Share link", Modifier.padding(start = 8.dp))
            }
            OutlinedButton(onClick = onScan) {
                Icon(HapticonIcons.QrCodeScanner, contentDescription = null)
                Text("Scan someone's code", Modifier.padding(start = 8.dp))
            }
        }
    }
}

/** The QR code of [text] (ZXing, error correction M: survives a smudge, stays small), without its own margin. */
fun qrMatrix(text: String): BitMatrix = QRCodeWriter().encode(
    text, BarcodeFormat.QR_CODE, 0, 0,
    mapOf(EncodeHintType.ERROR_CORRECTION to ErrorCorrectionLevel.M, EncodeHintType.MARGIN to 0),
)

@Composable
private fun QrCode(matrix: BitMatrix, modifier: Modifier) {
    Canvas(modifier.background(Color.White)) {
        val cell = size.minDimension / matrix.width
        for (y in 0 until matrix.height) for (x in 0 until matrix.width) {
            if (matrix[x, y]) drawRect(Color.Black, Offset(x * cell, y * cell), Size(cell + 0.5f, cell + 0.5f))
        }
    }
}
