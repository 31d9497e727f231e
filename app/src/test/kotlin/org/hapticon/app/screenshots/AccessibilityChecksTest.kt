package org.hapticon.app.screenshots

import androidx.compose.foundation.background
import androidx.compose.foundation.clickable
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.size
import androidx.compose.ui.Alignment
import androidx.compose.material3.Button
import androidx.compose.material3.Text
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.graphics.asAndroidBitmap
import androidx.compose.ui.test.captureToImage
import androidx.compose.ui.test.onRoot
import androidx.compose.ui.unit.dp
import androidx.compose.ui.unit.sp
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.offset
import androidx.compose.foundation.rememberScrollState
import androidx.compose.foundation.verticalScroll
import androidx.compose.ui.draw.clipToBounds
import androidx.compose.ui.platform.LocalDensity
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/** The ATF bridge finds what it is there to find, and passes what is fine. */
class AccessibilityChecksTest : ScreenshotTest() {
    private fun failuresOf(touchTargetDp: Int = 48, content: @androidx.compose.runtime.Composable () -> Unit): List<String> {
        // Centred: ATF excuses small targets against the screen's edge (they may be cut off, not small).
        compose.setContent { Box(Modifier.fillMaxSize().background(Color.White), Alignment.Center) { content() } }
        val bitmap = compose.onRoot().captureToImage().asAndroidBitmap()
        return AccessibilityChecks.run(compose.onRoot(useUnmergedTree = true).fetchSemanticsNode(), bitmap, touchTargetDp)
    }

    @Test
    fun run_smallUnnamedTarget_failsSizeAndName() {
        // Compose widens the 24 dp box's touch area to 48 dp: measured right, it fails a 56 dp rule.
        val failures = failuresOf(touchTargetDp = 56) { Box(Modifier.size(24.dp).background(Color.Black).clickable {}) }
        assertTrue(failures.toString(), failures.any { it.startsWith("TouchTargetSizeCheck: ERROR") && "KEY_WIDTH=48" in it })
        assertTrue(failures.toString(), failures.any { it.startsWith("SpeakableTextPresentCheck") })
    }

    @Test
    fun run_controlCutByAScrolledListsEdge_notMeasured() {
        // 48 dp tall, 30 dp of it scrolled (or clipped) away: 18 dp show. In a list scrolled past it ATF does not
        // measure it (it may be partly scrolled off, isAgainstScrollableEdge); cut by a plain clip it is too small.
        val scrolled = failuresOf {
            val px = with(LocalDensity.current) { 30.dp.roundToPx() }
            Column(Modifier.size(200.dp, 100.dp).verticalScroll(rememberScrollState(px))) {
                Button(onClick = {}, Modifier.size(200.dp, 48.dp)) { Text("Feel stroke") }
                Box(Modifier.height(300.dp))
            }
        }
        assertEquals(emptyList<String>(), scrolled.filter { it.startsWith("TouchTargetSizeCheck") })
    }

    @Test
    fun run_controlCutByAPlainClip_failsSize() {
        val clipped = failuresOf {
            Box(Modifier.size(200.dp, 18.dp).clipToBounds()) {
                Button(onClick = {}, Modifier.offset(y = (-30).dp).size(200.dp, 48.dp)) { Text("Feel stroke") }
            }
        }
        assertTrue(clipped.toString(), clipped.any { it.startsWith("TouchTargetSizeCheck: ERROR") })
    }

    @Test
    fun run_paleTextOnWhite_failsContrast() {
        val failures = failuresOf { Text("Barely there", color = Color(0xFFCCCCCC), fontSize = 14.sp) }
        assertTrue(failures.toString(), failures.any { it.startsWith("TextContrastCheck: WARNING #11") })
    }

    @Test
    fun run_materialButtonAndBlackText_passes() {
        // A 40 dp Material button: its touch area is 48 dp, so it passes.
        val failures = failuresOf {
            Column {
                Text("Readable", color = Color.Black)
                Button(onClick = {}) { Text("Play") }
            }
        }
        assertEquals(emptyList<String>(), failures)
    }

    @Test
    fun run_disabledButton_exemptFromContrast() {
        // Material draws a disabled label at 38 % opacity; WCAG 1.4.3 exempts inactive components.
        assertEquals(emptyList<String>(), failuresOf { Button(onClick = {}, enabled = false) { Text("Next") } })
    }
}
