package org.hapticon.companion.gesture

import org.hapticon.companion.cli
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.Locale

class SocialTouchCommandsTest {
    @get:Rule
    val temp = TemporaryFolder()

    /** A message at 100 Hz: rest, then [frames] frames of [intensity] over [area], then rest. */
    private fun message(file: File, intensity: Double, frames: Int, area: Double) = file.writeText(buildString {
        append("time_s,intensity,x,y,area\n")
        for (k in 0 until frames + 20) {
            val on = k in 10 until 10 + frames
            append(String.format(Locale.ROOT, "%.2f,%s,0.5,0.5,%s\n", k / 100.0, if (on) intensity else 0.0, if (on) area else 0.0))
        }
    })

    /** Trains on [dir] into [name]; the one line on stderr: 24 messages of two people, both evaluations 100 %. */
    private fun trainPerfectly(dir: File, name: String, labels: String): File {
        val model = File(temp.root, name)
        val train = cli("train", "--classifier", "logitboost", "--in", dir.path, "--out", model.path)
        assertEquals(train.toString(), 0, train.exitCode)
        assertEquals(
            listOf("train: 24 messages from 2 people, labels $labels, LogitBoost 10 rounds; 10x10-fold CV 100.0 %, leave-one-transmitter-out 100.0 %; wrote $model"),
            train.stderrLines,
        )
        return model
    }

    @Test
    fun trainLogitboost_thenClassify_recognisesAMessage() {
        val dir = temp.newFolder("messages")
        for (person in listOf("p1", "p2")) for (n in 1..6) {
            message(File(dir, "$person-pat-$n.csv"), 1.0 + 0.05 * n, 5 + n % 3, 1.0)
            message(File(dir, "$person-squeeze-$n.csv"), 5.0 + 0.1 * n, 50 + n, 6.0)
        }
        val model = trainPerfectly(dir, "social.json", "pat squeeze")
        val probe = temp.newFile("probe.csv").also { message(it, 5.5, 55, 5.0) }
        val classify = cli("classify", "--model", model.path, "--in", probe.path)
        assertEquals(classify.toString(), 0, classify.exitCode)
        assertEquals("label,probability", classify.stdout.lines()[0])
        assertEquals("squeeze", classify.stdout.lines()[1].substringBefore(','))
    }

    /** A skin recording on a 3-element strip at 40 Hz: rest, [frames] frames of [intensity] on element [at], pushing the joint by [push], rest. */
    private fun skin(file: File, intensity: Double, frames: Int, at: Int, push: Double) = file.writeText(buildString {
        append("time_s,joint,e:0:0,e:1:0,e:2:0\n")
        for (k in 0 until frames + 8) {
            val on = k in 4 until 4 + frames
            val e = DoubleArray(3) { if (on && it == at) intensity else 0.0 }
            append(String.format(Locale.ROOT, "%.3f,%s,%s,%s,%s\n", k / 40.0, if (on) push else 0.0, e[0], e[1], e[2]))
        }
    })

    @Test
    fun trainLogitboost_onSkinRecordings_usesTheJointAndLocationFeatures() {
        // Same intensity and length: a push at x 0 versus a pull at x 2, told apart by the joint and location features.
        val dir = temp.newFolder("skin")
        for (person in listOf("p1", "p2")) for (n in 1..6) {
            skin(File(dir, "$person-rejection-$n.csv"), 0.5 + 0.01 * n, 10, at = 0, push = 0.4)
            skin(File(dir, "$person-greeting-$n.csv"), 0.5 + 0.01 * n, 10, at = 2, push = -0.4)
        }
        val model = trainPerfectly(dir, "skin.json", "greeting rejection")
        val probe = temp.newFile("probe-skin.csv").also { skin(it, 0.45, 12, at = 2, push = -0.3) }
        val classify = cli("classify", "--model", model.path, "--in", probe.path)
        assertEquals("greeting", classify.stdout.lines()[1].substringBefore(','))
        val broken = temp.newFile("broken.csv").also { it.writeText("time_s,joint,e:0:0,e:1\n0,0,0,0\n") }
        val bad = cli("classify", "--model", model.path, "--in", broken.path)
        assertEquals(listOf("hapticon: ${broken.path}:1: column 4 must be e:X:Y (an element and its centroid), got \"e:1\""), bad.stderrLines)
    }

    @Test
    fun trainLogitboost_badNameOrHeader_exitsTwo() {
        val dir = temp.newFolder("bad")
        message(File(dir, "anger.csv"), 1.0, 5, 1.0)
        val result = cli("train", "--classifier", "logitboost", "--in", dir.path, "--out", File(temp.root, "m.json").path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: ${File(dir, "anger.csv").path}: name must be PERSON-LABEL[-N].csv, e.g. p1-anger-3.csv"), result.stderrLines)
        val header = temp.newFolder("header")
        File(header, "p1-anger-1.csv").writeText("time,i\n0,1\n")
        val bad = cli("train", "--classifier", "logitboost", "--in", header.path, "--out", File(temp.root, "m.json").path)
        assertEquals(listOf("hapticon: ${File(header, "p1-anger-1.csv").path}:1: expected the header time_s,intensity,x,y,area"), bad.stderrLines)
        assertEquals(2, cli("train", "--classifier", "svm", "--in", dir.path, "--out", "x.json").exitCode)
    }
}
