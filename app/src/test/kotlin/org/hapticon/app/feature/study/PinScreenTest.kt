package org.hapticon.app.feature.study

import androidx.compose.runtime.getValue
import androidx.compose.ui.test.assertIsEnabled
import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performTextInput
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import org.hapticon.app.designsystem.HapticonTheme
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The PIN screen: setting the PIN on first use, then a wrong PIN refused and the right one accepted. */
@RunWith(RobolectricTestRunner::class)
class PinScreenTest {
    @get:Rule val rule = createComposeRule()

    private val attempts = ArrayList<String>()

    @Test
    fun firstUse_setPin_thenWrongPinShowsError_rightPinUnlocks() {
        var state by mutableStateOf<Pair<LockState, String?>>(LockState.SET_PIN to null)
        val pin = "2580"
        rule.setContent {
            HapticonTheme {
                PinScreen(
                    state.first, state.second,
                    onSetPin = { a, b ->
                        attempts += "set $a/$b"
                        state = if (a == b) LockState.LOCKED to null else LockState.SET_PIN to "the two PINs differ"
                    },
                    onUnlock = { p ->
                        attempts += "unlock $p"
                        state = if (p == pin) LockState.UNLOCKED to null else LockState.LOCKED to "wrong PIN"
                    },
                )
            }
        }

        rule.onNodeWithText("Set a researcher PIN").assertExists()
        rule.onNodeWithText("Set PIN").assertIsNotEnabled()
        rule.onNodeWithContentDescription("PIN").performTextInput("25a80")
        rule.onNodeWithContentDescription("Repeat PIN").performTextInput("2581")
        rule.onNodeWithText("Set PIN").assertIsEnabled().performClick()
        rule.onNodeWithText("the two PINs differ").assertExists()

        rule.onNodeWithContentDescription("PIN").performTextInput(pin)
        rule.onNodeWithContentDescription("Repeat PIN").performTextInput(pin)
        rule.onNodeWithText("Set PIN").performClick()
        rule.onNodeWithText("Researcher mode").assertExists()
        rule.onNodeWithContentDescription("Repeat PIN").assertDoesNotExist()

        rule.onNodeWithContentDescription("PIN").performTextInput("1111")
        rule.onNodeWithText("Unlock").performClick()
        rule.onNodeWithText("wrong PIN").assertExists()
        rule.onNodeWithContentDescription("PIN").performTextInput(pin)
        rule.onNodeWithText("Unlock").performClick()

        // Letters are dropped as typed, and each attempt clears the field.
        assertEquals(listOf("set 2580/2581", "set 2580/2580", "unlock 1111", "unlock 2580"), attempts)
        assertEquals(LockState.UNLOCKED, state.first)
    }
}
