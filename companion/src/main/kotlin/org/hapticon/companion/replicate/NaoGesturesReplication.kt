package org.hapticon.companion.replicate

import org.hapticon.gesture.recognition.NaoEvaluation
import org.hapticon.gesture.recognition.NaoPreset
import org.hapticon.gesture.recognition.NaoRecording
import java.io.PrintStream
import java.util.Locale

/**
 * 004: the NAO fabric-sensor paper's touch-gesture pipeline ([NaoPreset]) scored the paper's way (a random 70/30
 * split of windows) and ours (leave one person out). The paper's data set is not shipped, so this runs on simulated
 * people ([sessions]); the numbers show how much the random split flatters, not the paper's sensor.
 */
class NaoGesturesReplication(private val sessions: () -> List<NaoRecording>) : Replication {
    override val id: String = "004"
    override val names: List<String> = listOf("nao")
    override val title: String = "NAO fabric sensor: touch gestures × intensity, random split vs leave-one-person-out"

    override fun run(out: PrintStream) {
        val recordings = sessions()
        val windows = NaoPreset.windows(recordings)
        out.println()
        out.println("pipeline: ${NaoPreset.CHANNELS} channels at ${NaoPreset.SAMPLE_RATE.toInt()} Hz, ${NaoPreset.WINDOW_FRAMES}-sample windows, " +
            "${NaoPreset.HOP_FRAMES}-sample hop, label at >= ${NaoPreset.LABEL_OVERLAP} overlap, ${NaoPreset.FEATURES_PER_CHANNEL} features/channel, ${NaoPreset.FOREST}")
        out.println("data: ${recordings.size} simulated people (gesture NaoSyntheticPeople), ${windows.size} windows; the paper's recordings are not shipped")
        out.println("checked: the paper's abstract (5 gestures x gentle/energetic, 4 resistances, random forest, 74.1 % = 8.1 x chance 1/11);")
        out.println("         its Methods were not reached: the 31st feature per channel (number of peaks) is our reading (docs/replication.md)")
        val split = NaoEvaluation.randomSplit(windows)
        val lopo = NaoEvaluation.leaveOnePersonOut(windows)
        out.println()
        out.println("                              paper   ours 70/30   ours LOPO")
        line(out, "combined (11 classes)", 0.741, split.combined, lopo.combined)
        line(out, "gesture", 0.743, split.gesture, lopo.gesture)
        line(out, "intensity", 0.893, split.intensity, lopo.intensity)
        line(out, "tickle-gentle recall", 0.64, split.share("tickle-gentle", "tickle-gentle"), lopo.share("tickle-gentle", "tickle-gentle"))
        line(out, "tickle-gentle -> poke-gentle", 0.11, split.share("tickle-gentle", "poke-gentle"), lopo.share("tickle-gentle", "poke-gentle"))
        out.println(String.format(Locale.ROOT, "  windows scored: 70/30 %d, LOPO %d", split.total, lopo.total))
    }

    private fun line(out: PrintStream, what: String, paper: Double, split: Double, lopo: Double) {
        out.println(String.format(Locale.ROOT, "  %-28s %6.1f %%   %8.1f %%   %7.1f %%", what, 100 * paper, 100 * split, 100 * lopo))
    }

}
