package org.hapticon.companion.gesture

import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli
import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.synthetic.SyntheticGestures
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.Locale

class GestureCommandsTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun csv(recording: Recording, labels: ((Int) -> String)? = null): String = buildString {
        append("time_s,").append(recording.channels.joinToString(",") { it.name })
        if (labels != null) append(",label")
        append('\n')
        for (i in 0 until recording.frameCount) {
            append(String.format(Locale.ROOT, "%.4f", i / recording.sampleRate))
            for (channel in recording.channels) append(',').append(channel[i])
            if (labels != null) append(',').append(labels(i))
            append('\n')
        }
    }

    @Test
    fun labelColumnBecomesSpansAndFileNamesLabelWholeFiles() {
        val text = "time_s,force,label\n0,0,none\n0.01,1,hit-gentle\n0.02,2,hit-gentle\n0.03,nan,none\n0.04,0,KNOCK_energetic\n"
        val labelled = LabelledCsv.parse(text, "rows.csv")
        assertEquals(100.0, labelled.recording.sampleRate, 1e-9)
        assertEquals("[hit-gentle[1, 3), knock-energetic[4, 5)]", labelled.spans.toString())
        assertTrue(labelled.recording.channels[0][3].isNaN())
        val named = LabelledCsv.parse("time_s,force\n0,1\n0.5,2\n", "data/p3-hug-energetic-2.csv")
        assertEquals("[hug-energetic[0, 2)]", named.spans.toString())
        assertEquals(GestureLabel.NONE, LabelledCsv.labelFromName("rest_none.csv"))
    }

    @Test
    fun malformedCsvIsAUsageErrorWithTheLine() {
        fun message(text: String, name: String = "x-none.csv") = assertThrows(UsageException::class.java) { LabelledCsv.parse(text, name) }.message
        assertEquals("x-none.csv:3: time_s must increase, 0.0 follows 0.0", message("time_s,force\n0,1\n0,2\n"))
        assertEquals("x-none.csv:2: 'abc' in force is not a number", message("time_s,force\n0,abc\n"))
        assertEquals("x-none.csv:1: header must start with time_s, was 't'", message("t,force\n0,1\n"))
        assertEquals("x-none.csv: needs at least two rows to know the sample rate", message("time_s,force\n0,1\n"))
        assertEquals("x.csv:2: unknown label 'pat'; expected ${GestureLabel.ALL.joinToString { it.id }}", message("time_s,force,label\n0,1,pat\n", "x.csv"))
        assertTrue(message("time_s,force\n0,1\n1,2\n", "hit-gentle-and-hug-gentle.csv")!!.contains("more than one label id"))
        assertTrue(message("time_s,force\n0,1\n1,2\n", "take.csv")!!.contains("holds no label id"))
    }

    @Test
    fun trainThenClassifyFindsTheGesture() {
        val dir = temp.newFolder("takes")
        for (person in SyntheticGestures.people(2, seed = 3)) {
            for ((i, take) in SyntheticGestures.takesOf(person, 3).withIndex()) {
                // Takes have rest around the gesture, so they carry a label column rather than a label in the name.
                val span = take.labelled.spans.singleOrNull()
                val label = { frame: Int -> if (span != null && frame >= span.from && frame < span.to) span.label.id else "none" }
                File(dir, "p${person.id}-take-$i.csv").writeText(csv(take.labelled.recording, label))
            }
        }
        val model = File(temp.root, "model.json")
        val trained = cli("train", "--in", dir.path, "--out", model.path, "--window", "1", "--trees", "20")
        assertEquals(trained.toString(), 0, trained.exitCode)
        assertTrue(trained.stderr, trained.stderr.startsWith("train: 54 recordings, labels none stroke-gentle stroke-energetic hit-gentle"))
        assertEquals(20, GestureModel.decode(model.readText()).forest.treeCount)

        val person = SyntheticGestures.people(3, seed = 3)[2]
        val stream = SyntheticGestures.concatenate(
            listOf(SyntheticGestures.perform(person, GestureLabel.NONE, 0), SyntheticGestures.perform(person, GestureLabel.parse("hug-energetic"), 0)),
        )
        val rec = File(temp.root, "rec.csv").also { it.writeText(csv(stream.recording)) }
        val classified = cli("classify", "--model", model.path, "--in", rec.path)
        assertEquals(classified.toString(), 0, classified.exitCode)
        val lines = classified.stdout.lines().dropLastWhile { it.isEmpty() }
        assertEquals("time_s,label,probability,event", lines[0])
        val decisions = (stream.recording.frameCount - 100) / 10 + 1
        assertEquals(decisions, lines.size - 1)
        val events = lines.drop(1).filter { it.endsWith(",1") }
        assertEquals(classified.stdout, 1, events.size)
        assertEquals("hug-energetic", events[0].split(',')[1])
        assertEquals("classify: $decisions decisions, 1 events (${GestureModel.decode(model.readText())})", classified.stderrLines.single())
    }

    @Test
    fun badArgumentsAreUsageErrors() {
        val rec = temp.newFile("rec-none.csv").also { it.writeText("time_s,pressure\n0,1\n0.01,2\n") }
        assertEquals("hapticon: train needs --out", cli("train", "--in", rec.path).stderrLines.single())
        assertEquals("hapticon: --window must be seconds in (0, 10.0], got '0'", cli("train", "--in", rec.path, "--out", "m.json", "--window", "0").stderrLines.single())
        assertEquals("hapticon: --trees must be in 1..1000, got 0", cli("train", "--in", rec.path, "--out", "m.json", "--trees", "0").stderrLines.single())
        assertEquals(
            "hapticon: cannot train: no example is as long as a 1.0 s window (100 frames)",
            cli("train", "--in", rec.path, "--out", File(temp.root, "m.json").path).stderrLines.single(),
        )
        assertEquals("hapticon: --people must be in 2..50 (one is held out), got 1", cli("classify-bench", "--people", "1").stderrLines.single())
        val bad = temp.newFile("model.json").also { it.writeText("{}") }
        val result = cli("classify", "--model", bad.path, "--in", rec.path)
        assertEquals(2, result.exitCode)
        assertEquals("hapticon: ${bad.path}: model: 'schema' must be a string", result.stderrLines.single())
    }

    @Test
    fun classifyRefusesRecordingsOfOtherChannels() {
        val take = SyntheticGestures.perform(SyntheticGestures.people(1)[0], GestureLabel.NONE, 0)
        val model = File(temp.root, "m.json")
        val examples = temp.newFolder("ex")
        File(examples, "none.csv").writeText(csv(take.labelled.recording))
        assertEquals(0, cli("train", "--in", examples.path, "--out", model.path, "--trees", "2").exitCode)
        val rec = temp.newFile("rec.csv").also { it.writeText("time_s,pressure\n0,1\n0.01,2\n") }
        assertEquals(
            "hapticon: ${rec.path}: model expects channels [force, accel_x, accel_y, accel_z], got [pressure]",
            cli("classify", "--model", model.path, "--in", rec.path).stderrLines.single(),
        )
    }

    @Test
    fun benchTableAndPlot() {
        val config = RecognitionBenchConfig(people = 2, seed = 1, takesPerLabel = 1, windows = listOf(0.5, 1.0), treeCounts = listOf(3, 5))
        val results = listOf(
            RecognitionResult(0.5, 3, 0.9, 0.05, 250.0, 0.8, 40.0), RecognitionResult(0.5, 5, 0.92, 0.04, Double.NaN, 0.0, 45.0),
            RecognitionResult(1.0, 3, 0.85, 0.1, 350.0, 0.9, 80.0), RecognitionResult(1.0, 5, 0.88, 0.02, 330.0, 0.95, 90.0),
        )
        val table = formatTable(results, config).lines()
        assertEquals("window   trees  accuracy         latency_ms   live_hits  us_per_window", table[1])
        assertEquals("0.5s     5      0.920 ± 0.040    n/a          0.00       45.0", table[3])
        val image = RecognitionPlot.draw(results, config)
        assertEquals(RecognitionPlot.WIDTH, image.width)
        assertEquals(70 + 2 * RecognitionPlot.PANEL_HEIGHT, image.height)
    }
}
