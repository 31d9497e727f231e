package org.hapticon.companion

import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavReader
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.RenderMode
import org.hapticon.testing.LittleEndian
import org.hapticon.testing.TestIcons
import org.hapticon.testing.readAllSamples
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import kotlin.math.abs

class RenderCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun readWav(file: File) = file.inputStream().use { WavReader.read(it) }

    private fun iconFile(text: String): File = temp.newFile("icon.json").also { it.writeText(text) }

    private fun assertUsageError(expectedLine: String, result: CliResult) {
        assertEquals(result.toString(), 2, result.exitCode)
        assertEquals(listOf(expectedLine), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun render_presetWithDefaults_writesFloat32HeaderAndTheRendererSamples() {
        val out = File(temp.root, "knock.wav")
        val result = cli("render", "knock", "--out", out.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("wrote $out: knock, 24696 samples, 0.560 s at 44100 Hz, f32, processing model, exact mode\n", result.stdout)

        val bytes = out.readBytes()
        assertEquals(58 + 24_696 * 4, bytes.size)
        assertEquals("RIFF", LittleEndian.fourCc(bytes, 0))
        assertEquals(bytes.size - 8L, LittleEndian.u32(bytes, 4))
        assertEquals("WAVE", LittleEndian.fourCc(bytes, 8))
        assertEquals("fmt ", LittleEndian.fourCc(bytes, 12))
        assertEquals(18L, LittleEndian.u32(bytes, 16))
        assertEquals(3, LittleEndian.u16(bytes, 20)) // IEEE float
        assertEquals(1, LittleEndian.u16(bytes, 22)) // mono
        assertEquals(44_100L, LittleEndian.u32(bytes, 24))
        assertEquals(176_400L, LittleEndian.u32(bytes, 28))
        assertEquals(4, LittleEndian.u16(bytes, 32))
        assertEquals(32, LittleEndian.u16(bytes, 34))
        assertEquals("fact", LittleEndian.fourCc(bytes, 38))
        assertEquals(24_696L, LittleEndian.u32(bytes, 46))
        assertEquals("data", LittleEndian.fourCc(bytes, 50))
        assertEquals(24_696L * 4, LittleEndian.u32(bytes, 54))

        val expected = IconRenderer(HapticIcon.KNOCK, 44_100).stream().readAllSamples()
        assertArrayEquals(expected, readWav(out).samples(), 0f)
    }

    @Test
    fun render_s16ProcessingFastAt8000_matchesPcmRendererExactly() {
        val out = File(temp.root, "hit.wav")
        val result = cli("render", "hit", "--out", out.path, "--format", "s16", "--rate", "8000", "--model", "processing", "--mode", "fast")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("wrote $out: hit, 12320 samples, 1.540 s at 8000 Hz, s16, processing model, fast mode\n", result.stdout)
        val bytes = out.readBytes()
        assertEquals(44 + 12_320 * 2, bytes.size)
        assertEquals(1, LittleEndian.u16(bytes, 20)) // PCM
        assertEquals(16, LittleEndian.u16(bytes, 34))
        val pcm = PcmRenderer(HapticIcon.HIT, 8_000, EnvelopeModel.PROCESSING, RenderMode.FAST).toShortArray()
        for (i in pcm.indices) {
            assertEquals("sample $i", pcm[i].toInt(), (LittleEndian.u16(bytes, 44 + 2 * i).toShort()).toInt())
        }
    }

    @Test
    fun render_fastMode_staysWithinOneMillionthOfExact() {
        val exactFile = File(temp.root, "exact.wav")
        val fastFile = File(temp.root, "fast.wav")
        assertEquals(0, cli("render", "hug", "--out", exactFile.path, "--rate", "48000").exitCode)
        assertEquals(0, cli("render", "hug", "--out", fastFile.path, "--rate", "48000", "--mode", "fast").exitCode)
        val exact = readWav(exactFile).samples()
        val fast = readWav(fastFile).samples()
        assertEquals(144_000, exact.size)
        var maxError = 0.0
        for (i in exact.indices) maxError = maxOf(maxError, abs(exact[i].toDouble() - fast[i]))
        assertTrue("max error $maxError", maxError <= 1e-6)
    }

    @Test
    fun render_iconJsonFile_rendersThatIcon() {
        val file = iconFile(IconJson.encode(TestIcons.STEP_ONSET))
        val out = File(temp.root, "step.wav")
        val result = cli("render", file.path, "--out", out.path, "--rate", "8000", "--model", "processing")
        assertEquals(result.toString(), 0, result.exitCode)
        val audio = readWav(out)
        assertEquals(8_000, audio.sampleRate)
        assertEquals(WavEncoding.FLOAT32, audio.encoding)
        val expected = IconRenderer(TestIcons.STEP_ONSET, 8_000, EnvelopeModel.PROCESSING).stream().readAllSamples()
        assertArrayEquals(expected, audio.samples(), 0f)
    }

    @Test
    fun render_zeroLengthIcon_writesAnEmptyButValidWav() {
        val file = iconFile(IconJson.encode(TestIcons.ZERO_LENGTH))
        val out = File(temp.root, "empty.wav")
        val result = cli("render", file.path, "--out", out.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(58, out.length().toInt())
        assertEquals(0, readWav(out).frames)
    }

    @Test
    fun render_longestIconAsS16_streamsAllSamples() {
        val file = iconFile(IconJson.encode(TestIcons.LONGEST))
        val out = File(temp.root, "longest.wav")
        val result = cli("render", file.path, "--out", out.path, "--rate", "8000", "--format", "s16")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(44 + 240_000 * 2L, out.length())
    }

    @Test
    fun render_unknownPresetAndNoSuchFile_exitsTwo() {
        assertUsageError(
            "hapticon: unknown icon 'tickle': not a preset (stroke, hit, knock, hug) and no such file",
            cli("render", "tickle", "--out", File(temp.root, "x.wav").path),
        )
    }

    @Test
    fun render_presetNameInCapitals_isThePreset() {
        val out = File(temp.root, "k.wav")
        assertEquals(0, cli("render", "KNOCK", "--out", out.path).exitCode)
        assertEquals(24_696, readWav(out).frames)
    }

    @Test
    fun render_fileWithBrokenJson_namesTheOffset() {
        val file = iconFile("{\"schema\": \"hapticon.icon\",")
        val result = cli("render", file.path, "--out", File(temp.root, "x.wav").path)
        assertUsageError("hapticon: icon file $file is not valid JSON: unexpected end of input, expected a member name in double quotes at offset 27", result)
    }

    @Test
    fun render_fileWithBadField_namesTheField() {
        val text = IconJson.encode(HapticIcon.KNOCK).replace("\"attack\":0.005", "\"attack\":\"abc\"")
        val file = iconFile(text)
        val result = cli("render", file.path, "--out", File(temp.root, "x.wav").path)
        assertUsageError("hapticon: icon file $file is not a valid icon: attack: expected a number, got \"abc\"", result)
    }

    @Test
    fun render_noteAboveNyquist_exitsTwoAndWritesNothing() {
        val file = iconFile(IconJson.encode(TestIcons.NOTE_127))
        val out = File(temp.root, "high.wav")
        val result = cli("render", file.path, "--out", out.path, "--rate", "8000")
        assertUsageError(
            "hapticon: cannot render note-127 at 8000 Hz: note: carrier 12543.85 Hz (note 127.0) is at or above the " +
                "Nyquist frequency 4000 Hz of a 8000 Hz render",
            result,
        )
        assertFalse(out.exists())
    }

    @Test
    fun render_rateOutOfRange_namesSampleRate() {
        assertUsageError(
            "hapticon: cannot render hug at 4000 Hz: sampleRate: must be in 8000..192000 Hz, was 4000",
            cli("render", "hug", "--out", File(temp.root, "x.wav").path, "--rate", "4000"),
        )
    }

    @Test
    fun render_badRateNumber_exitsTwo() {
        assertUsageError("hapticon: --rate must be a whole number, got 'fast'", cli("render", "hug", "--out", "x.wav", "--rate", "fast"))
    }

    @Test
    fun render_badFormat_listsTheFormats() {
        assertUsageError("hapticon: --format must be f32 or s16, got 'mp3'", cli("render", "hug", "--out", "x.wav", "--format", "mp3"))
    }

    @Test
    fun render_missingOutOrIcon_exitsTwo() {
        assertUsageError("hapticon: render needs --out", cli("render", "hug"))
        assertUsageError("hapticon: render needs an ICON (a preset name, an icon or pattern JSON file, .ahap or .haptic)", cli("render", "--out", "x.wav"))
    }

    @Test
    fun render_outputDirectoryMissing_exitsTwoNamingIt() {
        val out = File(temp.root, "missing/x.wav")
        assertUsageError(
            "hapticon: cannot write $out: directory ${out.parentFile} does not exist",
            cli("render", "hug", "--out", out.path),
        )
    }

    @Test
    fun render_outputIsADirectory_exitsTwo() {
        assertUsageError("hapticon: cannot write ${temp.root}: it is a directory", cli("render", "hug", "--out", temp.root.path))
    }
}
