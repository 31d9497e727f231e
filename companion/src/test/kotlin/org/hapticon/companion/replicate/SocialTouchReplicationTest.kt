package org.hapticon.companion.replicate

import org.hapticon.gesture.social.SocialTouchSyntheticPeople
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class SocialTouchReplicationTest {
    /** Two transmitters × 10 takes for Experiment 1, four × 2 for Experiment 2, three CV runs: the table's shape, quickly. */
    private val text: String by lazy {
        val bytes = ByteArrayOutputStream()
        SocialTouchReplication(
            experiment1 = { SocialTouchSyntheticPeople.messages(people = 2, takesPerClass = 10, seed = 3) },
            experiment2 = { SocialTouchSyntheticPeople.messages(people = 4, takesPerClass = 2, seed = 4) },
            runs = 3,
        ).run(PrintStream(bytes, true, "UTF-8"))
        bytes.toString("UTF-8")
    }

    @Test
    fun printsThePapersTables3And6AndTheHumansWithTheirLines() {
        for (line in listOf(
            "  Participant A, LogitBoost (Table 3)              94.3 (3.8)    94.7 (3.5)    :181",
            "  Participant B, LogitBoost (Table 3)              81.7 (6.3)    73.7 (5.8)    :182",
            "  trained on A tested on B and back (Table 4)      32            51            :176",
            "  LogitBoost (Table 6)                             46.9 (11.4)   49.7 (13.8)   :221",
            "  human recipients (Table 6)                       51.8 (16.0)   62.1 (16.5)   :222",
        )) assertTrue(text, text.lines().contains(line))
        assertTrue(text, text.contains("emotions anger fear happiness sadness disgust surprise (:146)"))
        assertTrue(text, text.contains("social messages attention-getting greeting acceptance rejection affection animosity (:152)"))
        assertTrue(text, text.contains("7 classes, chance 1 in 7 = 14 % (:214)"))
        assertTrue(text, text.contains("10 rounds, shrinkage 1, Z max 3, weight threshold 100 %"))
        assertFalse(text, text.contains("n/t"))
    }

    @Test
    fun printsOursInATableOfItsOwn_labelledSimulatedAndNotComparable() {
        val lines = text.lines()
        val ours = lines.indexOfFirst { it.startsWith("Ours: simulated, not comparable") }
        assertTrue(text, ours > lines.indexOfFirst { it.startsWith("  human recipients (Table 6)") })
        val cell = """(\d+\.\d) \((\d+\.\d)\)"""
        val rows = lines.drop(ours).filter { Regex("""^  (simulated p\d, LogitBoost|LogitBoost)\s+$cell\s+$cell$""").matches(it) }
        assertEquals(text, listOf("simulated p1", "simulated p2", "LogitBoost"), rows.map { it.trim().substringBefore(",").substringBefore("  ") })
        for (row in rows) for (m in Regex(cell).findAll(row)) assertTrue(row, m.groupValues[1].toDouble() in 0.0..100.0)
        assertTrue(text, lines.any { Regex("""^  trained on p1 tested on p2 and back\s+\d+\s+\d+$""").matches(it) })
        assertTrue(text, text.contains("Experiment 1 protocol: 2 simulated transmitters x 13 classes, 130 messages each; 3 runs of 10-fold CV"))
        assertTrue(text, text.contains("Experiment 2 protocol: 4 simulated transmitters x 13 classes, 26 messages each"))
        assertTrue(text, lines.any { Regex("""^  human recipients\s+-\s+-$""").matches(it) })
    }
}
