package org.hapticon.app.screenshots

import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Surface
import androidx.compose.runtime.Composable
import androidx.compose.runtime.CompositionLocalProvider
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.asAndroidBitmap
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.test.captureToImage
import androidx.compose.ui.test.hasAnyDescendant
import androidx.compose.ui.test.isDialog
import androidx.compose.ui.test.isRoot
import androidx.compose.ui.test.junit4.ComposeContentTestRule
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onRoot
import androidx.compose.ui.unit.Density
import com.github.takahirom.roborazzi.RoborazziOptions
import com.github.takahirom.roborazzi.RoborazziTaskType
import com.github.takahirom.roborazzi.ExperimentalRoborazziApi
import com.github.takahirom.roborazzi.captureRoboImage
import com.github.takahirom.roborazzi.captureScreenRoboImage
import com.github.takahirom.roborazzi.roborazziSystemPropertyTaskType
import java.io.File
import org.hapticon.app.designsystem.HapticonTheme
import org.junit.Rule
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * One rendering of a screen: light or dark theme, at the default or the largest font scale.
 *
 * 2.0 is the largest font scale Android 14+ offers (Settings › Display › Font size), the one that clips
 * first; the file suffix names the variant in docs/images/screens/.
 */
enum class Variant(val suffix: String, val dark: Boolean, val fontScale: Float) {
    Light("", dark = false, fontScale = 1f),
    Dark("-dark", dark = true, fontScale = 1f),
    LargestFont("-font200", dark = false, fontScale = 2f),
    ;

    companion object {
        /** Main screens: light, dark and the largest font scale. */
        val MAIN: List<Variant> = listOf(Light, Dark, LargestFont)

        /** Secondary states: light and dark. */
        val THEMES: List<Variant> = listOf(Light, Dark)
    }
}

/**
 * Base for screenshot tests: a phone-sized Robolectric device (411×891 dp at xxhdpi, as a Pixel 7) with
 * native graphics, so Compose draws real pixels (see /work/shared/screenshots.md and docs/screenshots.md).
 *
 * [screen] renders a composable in the app's own theme (dynamic colour off, so pictures show our palette
 * and not the emulated wallpaper's) for each [Variant], then for each one:
 * - records it to `docs/images/screens/NAME[suffix].png` when `roborazzi.test.record=true`, and otherwise
 *   compares it with that recorded image: any changed pixel fails the test (Roborazzi's default
 *   comparator; the diff lands in `out/app/roborazzi/`). Recorded images change only by `./build screenshots`.
 * - runs the Accessibility Test Framework's checks ([AccessibilityChecks]) on what was drawn.
 */
@OptIn(ExperimentalRoborazziApi::class)
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
abstract class ScreenshotTest {
    @get:Rule
    val compose: ComposeContentTestRule = createComposeRule()

    /**
     * Renders [content] once per variant and records/compares `NAME[suffix].png`; [prepare] runs once after
     * the content is set (to drive a route with its ViewModel); [accessibility] runs the ATF checks on every
     * variant (turn off only for a picture that is not a screen, with a reason).
     *
     * [dialog]: the content shows a dialog, which Compose puts in a window of its own (a second root that
     * `onRoot()` does not reach); the picture is then the whole screen with every window, as a phone shows it
     * (the screen behind under the dialog's scrim, Roborazzi's `captureScreenRoboImage`), and the checks run
     * on the dialog's window, the one that has TalkBack's focus.
     */
    fun screen(
        name: String,
        variants: List<Variant> = Variant.THEMES,
        accessibility: Boolean = true,
        dialog: Boolean = false,
        prepare: () -> Unit = {},
        content: @Composable () -> Unit,
    ) {
        require(Regex("[a-z0-9-]+").matches(name)) { "screenshot names are lower-case-with-dashes: $name" }
        var variant by mutableStateOf(variants.first())
        compose.setContent {
            ScreenFrame(variant) { content() }
        }
        prepare()  // drive a stateful screen (clicks, readings) to the state to picture
        val failures = mutableListOf<String>()
        for (v in variants) {
            variant = v
            compose.waitForIdle()
            val file = File(screensDirectory(), "$name${v.suffix}.png")
            if (dialog) captureScreenRoboImage(file, roborazziOptions()) else compose.onRoot().captureRoboImage(file, roborazziOptions())
            if (accessibility) {
                // A dialog's root is the one isDialog() finds inside; the screen's own root has none.
                val root = if (dialog) compose.onNode(isRoot() and hasAnyDescendant(isDialog()), useUnmergedTree = true) else compose.onRoot(useUnmergedTree = true)
                val bitmap = root.captureToImage().asAndroidBitmap()
                failures += AccessibilityChecks.run(root.fetchSemanticsNode(), bitmap).map { "${file.name}: $it" }
            }
        }
        if (failures.isNotEmpty()) {
            throw AssertionError("accessibility checks failed:\n" + failures.joinToString("\n"))
        }
    }

    companion object {
        /**
         * Where the recorded screens live. The offline build passes the absolute path; Gradle runs unit tests
         * in the module directory, so the relative fallback points at the same folder.
         */
        fun screensDirectory(): File =
            File(System.getProperty("hapticon.screens.dir") ?: "../docs/images/screens")

        /** Record when asked (`roborazzi.test.record=true`), compare and fail on a difference otherwise. */
        fun roborazziOptions(): RoborazziOptions {
            val fromProperties = roborazziSystemPropertyTaskType()
            val task = if (fromProperties.isEnabled()) fromProperties else RoborazziTaskType.Verify
            return RoborazziOptions(taskType = task)
        }
    }
}

/** The app's theme without dynamic colour, a full-screen surface, and the variant's font scale. */
@Composable
private fun ScreenFrame(variant: Variant, content: @Composable () -> Unit) {
    val density = LocalDensity.current
    CompositionLocalProvider(LocalDensity provides Density(density.density, variant.fontScale)) {
        HapticonTheme(darkTheme = variant.dark, dynamicColor = false) {
            Surface(Modifier.fillMaxSize(), color = MaterialTheme.colorScheme.background) { content() }
        }
    }
}
