package org.hapticon.app.screenshots

import androidx.compose.foundation.layout.padding
import androidx.compose.runtime.Composable
import androidx.compose.ui.Modifier
import androidx.compose.ui.unit.dp
import org.hapticon.app.feature.study.LikertScaleControl
import org.hapticon.app.feature.study.LockState
import org.hapticon.app.feature.study.PinScreen
import org.hapticon.app.feature.study.SessionActions
import org.hapticon.app.feature.study.SessionScreen
import org.hapticon.app.feature.study.SessionUiState
import org.hapticon.core.HapticIcon
import org.hapticon.study.LikertScale
import org.hapticon.study.Stimulus
import org.hapticon.study.StudyStep
import org.hapticon.study.StudyTask
import org.junit.Test

/** The participant's session (each kind of step, the Likert item) and the researcher's PIN gate. */
class StudyScreenshotTest : ScreenshotTest() {
    private val scale = LikertScale(7, listOf("Not at all", "Very much"))
    private val textTask = StudyTask(
        id = "text",
        title = "Messages with icons",
        instructions = "Your partner sends you messages with a haptic icon. Press the icon to feel it, then rate how " +
            "well it fits the message.",
        stimuli = listOf(
            Stimulus("s1", HapticIcon.STROKE, text = "Thinking of you"),
            Stimulus("s2", HapticIcon.KNOCK, text = "Are you there?"),
        ),
        question = "How well does the icon fit the message?",
    )
    private val stickerTask = StudyTask(
        id = "sticker",
        title = "Stickers with icons",
        instructions = "Rate how well each icon fits its sticker.",
        stimuli = listOf(Stimulus("k1", HapticIcon.HUG, sticker = "sticker_hug")),
        question = "How well does the icon fit the sticker?",
    )

    private fun active(step: StudyStep, selected: Int? = null, pressed: Boolean = false, playing: Boolean = false) =
        SessionUiState.Active("P07", step, scale, answered = 1, trials = 3, selected, pressed, playing)

    @Composable
    private fun session(state: SessionUiState) =
        SessionScreen(state, SessionActions(), pinError = null)

    @Test
    fun session_taskIntro() = screen("study-task-intro", Variant.MAIN) {
        session(active(StudyStep.TaskIntro(textTask, 1)))
    }

    @Test
    fun session_trialBeforeTheIconIsFelt() = screen("study-trial", Variant.MAIN) {
        session(active(StudyStep.Trial(textTask, 1, 2, textTask.stimuli[1], textTask.question)))
    }

    @Test
    fun session_trialRatedWhileIconPlays() = screen("study-trial-rated") {
        session(active(StudyStep.Trial(textTask, 1, 2, textTask.stimuli[1], textTask.question), selected = 5, pressed = true, playing = true))
    }

    @Test
    fun session_stickerTrial() = screen("study-trial-sticker") {
        session(active(StudyStep.Trial(stickerTask, 2, 1, stickerTask.stimuli[0], stickerTask.question), selected = 6, pressed = true))
    }

    @Test
    fun session_taskEnd() = screen("study-task-end") {
        session(active(StudyStep.TaskEnd(textTask, 1)))
    }

    @Test
    fun session_done() = screen("study-done") {
        session(active(StudyStep.Done))
    }

    @Test
    fun session_failed() = screen("study-failed") {
        session(SessionUiState.Failed("The session log is damaged (line 12). Ask the researcher."))
    }

    @Test
    fun likert_fivePointsWithAllLabels() = screen("study-likert") {
        LikertScaleControl(
            LikertScale(5, listOf("Strongly disagree", "Disagree", "Neutral", "Agree", "Strongly agree")),
            selected = 4, onSelect = {}, modifier = Modifier.padding(16.dp),
        )
    }

    @Test
    fun pin_firstUse_setsAPin() = screen("study-pin-set") {
        PinScreen(LockState.SET_PIN, error = null, onSetPin = { _, _ -> }, onUnlock = {})
    }

    @Test
    fun pin_locked_wrongPin() = screen("study-pin-locked") {
        PinScreen(LockState.LOCKED, error = "Wrong PIN", onSetPin = { _, _ -> }, onUnlock = {})
    }
}
