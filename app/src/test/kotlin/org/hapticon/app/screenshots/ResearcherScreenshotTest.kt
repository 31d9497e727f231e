package org.hapticon.app.screenshots

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import java.io.File
import org.hapticon.app.feature.study.LockState
import org.hapticon.app.feature.study.ResearcherScreen
import org.hapticon.app.feature.study.ResearcherUiState
import org.hapticon.app.feature.study.ResearcherActions
import org.hapticon.app.feature.study.UploadState
import org.hapticon.app.study.ExportResult
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.SessionCheck
import org.hapticon.app.study.SessionSummary
import org.hapticon.app.study.StoredProtocol
import org.hapticon.study.log.ChainVerification
import androidx.compose.ui.test.hasScrollToNodeAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.performScrollToNode
import org.junit.Test

/**
 * The researcher's screen behind the PIN: the originating study's protocol with pink masking noise on, the
 * sessions run so far, the warning before a masked session without headphones, an export with its log checks
 * and a failed upload. The screen takes its state as given; its ViewModel only receives presses.
 */
class ResearcherScreenshotTest : ScreenshotTest() {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val exports = File(context.cacheDir, "exports")

    private val masked = StoredProtocol.DEFAULT.copy(masking = MaskingSetting(NoiseColor.PINK, -30.0))
    private val sessions = listOf(
        SessionSummary(1, masked.protocol.id, "P000-A", 0, answers = 24, trials = 24, finished = true),
        SessionSummary(2, masked.protocol.id, "P001-B", 1, answers = 24, trials = 24, finished = true),
        SessionSummary(3, masked.protocol.id, "P002-A", 2, answers = 9, trials = 24, finished = false),
    )
    private val unlocked = ResearcherUiState.Success(
        lock = LockState.UNLOCKED,
        protocols = listOf(masked),
        selected = masked,
        sessions = sessions,
        activeSessionId = 3,
        nextParticipant = "P003-B",
    )

    @Test
    fun researcher_maskedProtocolWithSessions() = screen("study-researcher", Variant.MAIN) {
        ResearcherScreen(unlocked, ResearcherActions())
    }

    /** Masking noise is on and no headphones are connected: the start waits for the researcher's answer. */
    @Test
    fun researcher_maskingWithoutHeadphones_warns() = screen("study-researcher-headphones", dialog = true) {
        ResearcherScreen(unlocked.copy(headphoneWarning = true), ResearcherActions())
    }

    @Test
    fun researcher_exportedThenUploadFailed() = screen(
        "study-researcher-export",
        // Scrolled to the end, where the failed upload's reason and Retry upload are, with the export above them.
        prepare = { compose.onNode(hasScrollToNodeAction()).performScrollToNode(hasText("Nothing is lost", substring = true)) },
    ) {
        val export = ExportResult(
            File(exports, "hapticon-2026-11-25.csv"), File(exports, "hapticon-2026-11-25.json"), csv = "", rows = 57,
            checks = listOf(SessionCheck("P000-A", ChainVerification.Intact), SessionCheck("P001-B", ChainVerification.Intact)),
        )
        ResearcherScreen(
            unlocked.copy(
                export = export, collectorUrl = "https://lab.example.org:8443",
                upload = UploadState.Failed("The collector did not answer within 10 s"),
            ),
            ResearcherActions(),
        )
    }
}
