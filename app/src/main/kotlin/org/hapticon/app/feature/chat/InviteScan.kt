package org.hapticon.app.feature.chat

import android.content.ActivityNotFoundException
import android.content.Context
import android.graphics.Bitmap
import android.graphics.BitmapFactory
import android.net.Uri
import androidx.activity.compose.rememberLauncherForActivityResult
import androidx.activity.result.contract.ActivityResultContracts
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.runtime.rememberCoroutineScope
import androidx.compose.runtime.rememberUpdatedState
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.saveable.rememberSaveable
import androidx.compose.runtime.setValue
import androidx.compose.ui.platform.LocalContext
import androidx.core.content.FileProvider
import com.google.zxing.BarcodeFormat
import com.google.zxing.BinaryBitmap
import com.google.zxing.DecodeHintType
import com.google.zxing.NotFoundException
import com.google.zxing.ReaderException
import com.google.zxing.RGBLuminanceSource
import com.google.zxing.common.GlobalHistogramBinarizer
import com.google.zxing.common.HybridBinarizer
import com.google.zxing.qrcode.QRCodeReader
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.launch
import kotlinx.coroutines.withContext
import java.io.File
import java.io.IOException

/**
 * Scanning an invite's QR code from inside the app: Android's camera app takes the photo
 * (`MediaStore.ACTION_IMAGE_CAPTURE` into a file of ours, so Hapticon needs no camera permission of its own:
 * the camera app holds it) and ZXing decodes it here, the same library that draws the code. Chosen over a
 * live viewfinder: CameraX is published only on Google's Maven repository, which the offline build does not
 * reach; Google's code scanner needs Play services, which study phones may not have; and zxing-android-embedded
 * drives the deprecated android.hardware.Camera and has had no release since 2021.
 */
object InviteScan {
    /** Longest side a photo is decoded at: a QR code a third of the frame wide still has ~5 px per module. */
    const val MAX_DECODE_SIDE: Int = 1600

    /** The file the camera app writes into, shared with it through the app's FileProvider (cache `scans/`). */
    fun photoUri(context: Context): Uri {
        val file = File(File(context.cacheDir, "scans").apply { mkdirs() }, "invite.jpg")
        return FileProvider.getUriForFile(context, "${context.packageName}.exports", file)
    }

    /** The text of the QR code in [bitmap], or null when ZXing finds none. */
    fun decode(bitmap: Bitmap): String? {
        val pixels = IntArray(bitmap.width * bitmap.height)
        bitmap.getPixels(pixels, 0, bitmap.width, 0, 0, bitmap.width, bitmap.height)
        val source = RGBLuminanceSource(bitmap.width, bitmap.height, pixels)
        val hints = mapOf(DecodeHintType.TRY_HARDER to true, DecodeHintType.POSSIBLE_FORMATS to listOf(BarcodeFormat.QR_CODE))
        // Hybrid first (uneven light across a photographed screen), the global histogram for what it misses.
        for (binary in listOf(BinaryBitmap(HybridBinarizer(source)), BinaryBitmap(GlobalHistogramBinarizer(source)))) {
            try {
                return QRCodeReader().decode(binary, hints).text
            } catch (e: NotFoundException) {
                continue
            } catch (e: ReaderException) {
                continue
            }
        }
        return null
    }

    /** Reads the photo at [uri], scaled down to [MAX_DECODE_SIDE], and decodes it; null when none is there. Blocking. */
    fun decode(context: Context, uri: Uri): String? {
        val resolver = context.contentResolver
        // Only the size first: with inJustDecodeBounds, decodeStream fills the options and always returns null.
        val bounds = BitmapFactory.Options().apply { inJustDecodeBounds = true }
        (resolver.openInputStream(uri) ?: return null).use { BitmapFactory.decodeStream(it, null, bounds) }
        if (bounds.outWidth <= 0 || bounds.outHeight <= 0) return null
        var sample = 1
        while (maxOf(bounds.outWidth, bounds.outHeight) / sample > MAX_DECODE_SIDE) sample *= 2
        val bitmap = resolver.openInputStream(uri)?.use {
            BitmapFactory.decodeStream(it, null, BitmapFactory.Options().apply { inSampleSize = sample })
        } ?: return null
        return try {
            decode(bitmap)
        } finally {
            bitmap.recycle()
        }
    }

    const val NOT_FOUND: String = "No QR code found in the photo. Hold the phone so the code fills about half the picture, and try again."
}

/**
 * Returns what starts a scan: the camera app opens, and the decoded text goes to [onScanned] (an invite link to
 * check and apply), or a one-line reason to [onFailed]. Nothing happens when the user backs out of the camera.
 */
@Composable
fun rememberInviteScanner(onScanned: (String) -> Unit, onFailed: (String) -> Unit): () -> Unit {
    val context = LocalContext.current
    val scope = rememberCoroutineScope()
    val scanned by rememberUpdatedState(onScanned)
    val failed by rememberUpdatedState(onFailed)
    // The photo's file: made off the main thread when a scan starts, kept across the camera app's round trip.
    var photo by rememberSaveable { mutableStateOf<String?>(null) }
    val camera = rememberLauncherForActivityResult(ActivityResultContracts.TakePicture()) { taken ->
        val uri = photo?.let(Uri::parse)
        if (!taken || uri == null) return@rememberLauncherForActivityResult
        scope.launch {
            val text = try {
                withContext(Dispatchers.IO) { InviteScan.decode(context, uri) }
            } catch (e: IOException) {
                failed("The photo could not be read: ${e.message}")
                return@launch
            }
            if (text == null) failed(InviteScan.NOT_FOUND) else scanned(text)
        }
    }
    return remember(camera) {
        {
            scope.launch {
                val uri = withContext(Dispatchers.IO) { InviteScan.photoUri(context) }
                photo = uri.toString()
                try {
                    camera.launch(uri)
                } catch (e: ActivityNotFoundException) {
                    failed("This phone has no camera app to take the photo. Open the invite link instead.")
                }
            }
        }
    }
}
