package org.hapticon.app.feature.iconeditor

import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class IconEditorTest {
    @get:Rule
    val compose = createComposeRule()

    private val valid = mapOf(
        IconField.NAME to "buzz", IconField.ATTACK to "0.1", IconField.SUSTAIN to "0.2", IconField.LEVEL to "0.8",
        IconField.RELEASE to "0.1", IconField.NOTE to "60", IconField.PERIOD to "0", IconField.COUNT to "1",
    )

    @Test
    fun validate_validFields_makesIcon() {
        val state = IconEditorViewModel.validate(valid)
        assertEquals(HapticIcon("buzz", 0.1, 0.2, 0.8, 0.1, 60.0, 0.0, 1), state.icon)
        assertEquals(emptyMap<IconField, String>(), state.errors)
    }

    @Test
    fun validate_notANumber_errorUnderThatField() {
        val state = IconEditorViewModel.validate(valid + (IconField.SUSTAIN to "abc"))
        assertNull(state.icon)
        assertEquals(mapOf(IconField.SUSTAIN to "Enter a number"), state.errors)
    }

    @Test
    fun validate_levelAboveOne_iconValidationNamesLevel() {
        val state = IconEditorViewModel.validate(valid + (IconField.LEVEL to "1.5"))
        assertNull(state.icon)
        assertEquals(setOf(IconField.LEVEL), state.errors.keys)
    }

    @Test
    fun screen_invalidLevel_showsMessageAndDisablesSave() {
        val state = IconEditorViewModel.validate(valid + (IconField.LEVEL to "1.5"))
        compose.setContent { IconEditorScreen(state, IconEditorActions()) }

        compose.onNodeWithText(state.errors.getValue(IconField.LEVEL)).assertExists()
        compose.onNodeWithText("Save").assertIsNotEnabled()
    }
}
