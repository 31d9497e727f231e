package org.hapticon.app.feature.chat

import android.graphics.Bitmap
import androidx.compose.ui.graphics.asAndroidBitmap
import androidx.compose.ui.test.captureToImage
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onAllNodesWithTag
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * Delivered and read must differ by more than colour (WCAG 1.4.1 Use of Color): a participant who cannot tell the
 * tint apart, or reads a grey-scale screen, still sees which. Measured on the drawn pixels of the two marks, by their
 * shape alone: the share of each 16 dp mark that is drawn at all, whatever its colour.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class StateMarkShapeTest {
    @get:Rule
    val compose = createComposeRule()

    private fun own(n: Int, state: MessageState) = StoredMessage(
        "0b7e7c1e-3f7b-4a57-9d3e-%012d".format(n), "bob", "alice", 1_767_225_600_000L + n, "m$n", null, null, true, state, null,
    )

    /** The share of [bitmap]'s pixels that differ from its corner pixel (the background behind the mark). */
    private fun inked(bitmap: Bitmap): Double {
        val background = bitmap.getPixel(0, 0)
        val pixels = IntArray(bitmap.width * bitmap.height).also { bitmap.getPixels(it, 0, bitmap.width, 0, 0, bitmap.width, bitmap.height) }
        return pixels.count { it != background }.toDouble() / pixels.size
    }

    @Test
    fun readMark_isAFilledDisc_deliveredMark_isBareTicks() {
        compose.setContent {
            HapticonTheme(dynamicColor = false) {
                ConversationScreen(
                    ConversationUiState.Success("bob", listOf(own(1, MessageState.DELIVERED), own(2, MessageState.READ)), HapticIcon.PRESETS, null, null, null, null),
                    ConversationActions(),
                )
            }
        }
        // Top to bottom: the delivered message, then the read one.
        val nodes = compose.onAllNodesWithTag(STATE_MARK_TAG, useUnmergedTree = true)
        val order = nodes.fetchSemanticsNodes().withIndex().sortedBy { it.value.boundsInRoot.top }.map { it.index }
        assertEquals(2, order.size)
        val (delivered, read) = order.map { inked(nodes[it].captureToImage().asAndroidBitmap()) }
        assertTrue("delivered ticks cover $delivered of their mark", delivered < 0.45)
        assertTrue("the read disc covers $read of its mark", read > 0.6)
    }
}
