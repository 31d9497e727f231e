package org.hapticon.companion

import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavReader
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import javax.imageio.ImageIO

class DemoCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun demo_withApk_writesWavsPlotsAndComparisonAndReportsTheApk() {
        val dir = File(temp.root, "demo/nested")
        val apk = temp.newFile("app.apk").also { it.writeBytes(ByteArray(1234)) }
        val result = cli("demo", "--out", dir.path, "--apk", apk.path)
        assertEquals(result.toString(), 0, result.exitCode)

        val sensorFiles = listOf("fsr-press.bin", "fsr-press.jsonl", "fsr-press.csv", "grains.csv", "handshake-self.csv", "handshake-partner.csv", "handshake.csv")
        val expectedFiles = listOf("stroke", "hit", "knock", "hug").flatMap { listOf("$it.wav", "$it.png") } + "envelope-models.png" + sensorFiles + "received-knock.wav" + "study" + "gesture"
        assertEquals(expectedFiles.sorted(), dir.list()!!.sorted())
        val lines = result.stdout.lines().dropLast(1)
        assertEquals(25, lines.size)
        assertEquals("wrote ${File(dir, "stroke.wav")}: stroke, 476280 samples, 10.800 s at 44100 Hz, f32, processing model, exact mode", lines[0])
        assertEquals("wrote ${File(dir, "envelope-models.png")}: 1200×1224 PNG", lines[8])
        assertEquals("wrote ${File(dir, "fsr-press.bin")}: framed stream from hapticon-demo-fsr, device info + 2000 FSR samples at 1000 Hz, 28036 bytes", lines[9])
        assertEquals(true, Regex("messaging: embedded MQTT broker on tcp://127\\.0\\.0\\.1:\\d+, users alice and bob with passwords, the shipped ACL").matches(lines[15]))
        assertEquals(
            "messaging: alice sent bob \"hello from alice\" with icon knock: attack 0.005 s, sustain 0.01 s, release 0.005 s, " +
                "level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s; bob received it intact",
            lines[16],
        )
        assertEquals("wrote ${File(dir, "received-knock.wav")}: knock, 24696 samples, 0.560 s at 44100 Hz, f32, processing model, exact mode", lines[17])
        assertEquals("messaging: bob's delivered receipt reached alice", lines[18])
        assertEquals(
            "wrote ${File(dir, "study/results.csv")}: 144 responses of 12 simulated participants (the originating study's protocol)",
            lines[19],
        )
        assertEquals("APK: $apk (1234 bytes, 0.0 MB)", lines[24])

        val hug = File(dir, "hug.wav").inputStream().use { WavReader.read(it) }
        assertEquals(WavEncoding.FLOAT32, hug.encoding)
        assertEquals(44_100, hug.sampleRate)
        assertEquals(132_300, hug.frames)
        assertEquals(600, ImageIO.read(File(dir, "knock.png")).height)
    }

    @Test
    fun demo_studyAndGesture_runTheWholePipelines() {
        val dir = temp.newFolder("demo")
        assertEquals(0, cli("demo", "--out", dir.path).exitCode)

        // 12 participants × 3 tasks × 4 icons, one row each, every log verified.
        val rows = org.hapticon.study.export.ResponseCsv.read(File(dir, "study/results.csv").readText())
        assertEquals(144, rows.size)
        assertEquals(12, rows.map { it.participant }.distinct().size)
        assertEquals(12, File(dir, "study/logs.txt").readLines().count { it.contains("chain intact") })
        // Task 1 is first for everyone; tasks 2 and 3 swap places for half of the participants.
        val secondTasks = rows.filter { it.taskPosition == 2 }.groupBy { it.participant }.values.map { it.first().task }
        assertEquals(mapOf("text" to 6, "stickers" to 6), secondTasks.groupingBy { it }.eachCount())
        val analysis = File(dir, "study/analysis")
        assertEquals(true, File(analysis, "pairwise.csv").readLines().size > 1)
        assertEquals(true, File(analysis, "summary.md").readText().contains("|"))

        val fitted = org.hapticon.core.io.IconJson.decode(File(dir, "gesture/knock-fit.json").readText())
        assertEquals(3, fitted.count)
        assertEquals(57.0, fitted.note, 0.0)
        assertEquals(0.27, fitted.period, 0.005)
    }

    @Test
    fun demo_missingApk_exitsTwoBeforeWritingAnything() {
        val dir = File(temp.root, "demo")
        val result = cli("demo", "--out", dir.path, "--apk", File(temp.root, "none.apk").path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --apk: no such file: ${File(temp.root, "none.apk")}"), result.stderrLines)
        assertEquals(false, dir.exists())
    }

    @Test
    fun demo_outIsAFile_exitsTwo() {
        val file = temp.newFile("taken")
        val result = cli("demo", "--out", file.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: cannot write into $file: it is not a directory"), result.stderrLines)
    }
}
