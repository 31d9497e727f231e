package org.hapticon.app.playback

import android.content.Context
import android.os.Looper
import android.os.Vibrator
import androidx.media3.common.C
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.WavReader
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.Transient
import org.hapticon.core.pattern.signal
import org.hapticon.core.pattern.vibrationWaveform
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import java.io.File

/** An [AudioCoupledOutput] that records what it was asked to play. */
private class RecordingAudioOutput(override var isAvailable: Boolean = true) : AudioCoupledOutput {
    val played = ArrayList<File>()
    val usages = ArrayList<VibrationUsage>()
    var stops = 0

    override fun play(wav: File, usage: VibrationUsage) {
        played += wav
        usages += usage
    }

    override fun stop() {
        stops++
    }
}

@RunWith(RobolectricTestRunner::class)
class AudioCoupledHapticsTest {
    @get:Rule val folder = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator: Vibrator = defaultVibrator(context)
    private val audio = RecordingAudioOutput()
    private val audioPhone = DeviceCapabilities(
        hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35,
        hapticPlaybackSupported = true, hapticGeneratorAvailable = true,
    )
    private lateinit var cache: IconAudioCache

    @Before
    fun setUp() {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        cache = IconAudioCache(File(folder.root, "icon-audio"))
    }

    private fun player(output: AudioCoupledOutput = audio, audioCache: IconAudioCache = cache) =
        AdaptiveHapticPlayer(usageVibrator(vibrator), { audioPhone }, { null }, output, audioCache)

    @Test
    fun knock_playsItsPcm16RenderingAt48kHzThroughTheAudioPath() {
        val playback = player().play(HapticIcon.KNOCK, VibrationUsage.TOUCH) as Playback.Playing

        assertEquals(RendererKind.AUDIO_COUPLED, playback.renderer)
        // Knock lasts 2 · 0.27 + 0.02 = 0.56 s: 26 880 samples at 48 kHz.
        assertEquals(560L, playback.durationMillis)
        val wav = audio.played.single().inputStream().use { WavReader.read(it) }
        val samples = wav.samples()
        assertEquals(48_000, wav.sampleRate)
        assertEquals(26_880, samples.size)
        val expected = PcmRenderer(HapticIcon.KNOCK, 48_000).toShortArray()
        // The reader scales PCM16 by 1/32767; scaling back gives the exact integers written.
        for (i in expected.indices) assertEquals("sample $i", expected[i].toInt(), Math.round(samples[i] * 32767f))
        // Nothing on the vibrator: the audio HAL drives the actuator.
        assertNull(lastVibration(vibrator))
    }

    @Test
    fun sameIconTwice_rendersOnceAndPlaysTheCachedFile() {
        val player = player()
        val firstPlayback = player.play(HapticIcon.HIT, VibrationUsage.TOUCH) as Playback.Playing
        val first = audio.played.single()
        val written = first.lastModified()
        first.setLastModified(written - 10_000)

        val secondPlayback = player.play(HapticIcon.HIT, VibrationUsage.TOUCH) as Playback.Playing

        assertEquals(listOf(first, first), audio.played)
        // Measured once: the second press reuses the first press's fidelity.
        assertEquals(PcmRenderer(HapticIcon.HIT, 48_000).fidelity(), firstPlayback.fidelity)
        assertSame(firstPlayback.fidelity, secondPlayback.fidelity)
        assertEquals(1, first.parentFile!!.listFiles()!!.count { it.name.endsWith(".wav") })
    }

    @Test
    fun knockUnderEachModel_rendersOneFilePerModelWithThatModelsSamples() {
        val player = player()
        player.play(HapticIcon.KNOCK, EnvelopeModel.PAPER, VibrationUsage.TOUCH)
        player.play(HapticIcon.KNOCK, EnvelopeModel.PROCESSING, VibrationUsage.TOUCH)
        player.play(HapticIcon.KNOCK, EnvelopeModel.PAPER, VibrationUsage.TOUCH)

        // The model is part of the cache key: two files, and the third press reuses the first.
        val (paperFile, processingFile, again) = audio.played
        assertTrue(paperFile != processingFile)
        assertEquals(paperFile, again)
        for ((file, model) in listOf(paperFile to EnvelopeModel.PAPER, processingFile to EnvelopeModel.PROCESSING)) {
            val samples = file.inputStream().use { WavReader.read(it) }.samples()
            val expected = PcmRenderer(HapticIcon.KNOCK, 48_000, model).toShortArray()
            for (i in expected.indices) assertEquals("$model sample $i", expected[i].toInt(), Math.round(samples[i] * 32767f))
        }
        // Knock's processing envelope peaks at 1, the paper's plateau is 0.5: the paper file's carrier crests at 0.5,
        // the processing file's near its envelope peak (0.968: the 220 Hz crest falls just beside it at 48 kHz).
        val peak = { f: File -> f.inputStream().use { WavReader.read(it) }.samples().maxOf { Math.abs(it) }.toDouble() }
        assertEquals(0.5, peak(paperFile), 0.01)
        assertTrue(peak(processingFile).toString(), peak(processingFile) > 0.95)
    }

    @Test
    fun paperModelWithoutAudio_vibratesThePaperWaveform() {
        val playback = player(RecordingAudioOutput(isAvailable = false)).play(HapticIcon.KNOCK, EnvelopeModel.PAPER, VibrationUsage.TOUCH) as Playback.Playing

        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        val paper = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER)
        assertEquals(RecordedVibration(paper.timings().toList(), paper.amplitudes().toList()), lastVibration(vibrator))
        assertEquals(PAPER_KNOCK, lastVibration(vibrator))
    }

    // Up to full in 20 ms, held 20 ms; the carrier sweeps 100 → 200 Hz, with a tap at 10 ms.
    private val chirp = HapticPattern(
        "chirp",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 1.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.04, 200.0)),
        listOf(Transient(0.01, 0.8, 0.5)),
    )

    @Test
    fun pattern_playsItsOwnSignalAsPcm16At48kHzThroughTheAudioPath() {
        val playback = player().play(chirp, VibrationUsage.TOUCH) as Playback.Playing

        assertEquals(RendererKind.AUDIO_COUPLED, playback.renderer)
        assertEquals(40L, playback.durationMillis)
        val samples = audio.played.single().inputStream().use { WavReader.read(it) }.samples()
        assertEquals(48_000 * 40 / 1000, samples.size)
        // Every sample is the pattern's exact signal at i / 48000 s within PCM16's rounding (the signal passes through a
        // float on its way to the writer), clipped to ±1 where the tap adds to full drive: the sweep and the tap reach
        // the actuator as they are.
        val signal = chirp.signal()
        val exact = DoubleArray(samples.size) { signal.sample(it / 48_000.0) }
        for (i in samples.indices) assertEquals("sample $i", exact[i].coerceIn(-1.0, 1.0), samples[i].toDouble(), 1.0 / 32767)
        // The fidelity measured from the file: its largest error is that clipping (0.0029 at sample 1324).
        val overshoot = exact.maxOf { Math.abs(it) - 1.0 }
        assertTrue(overshoot > 0.0)
        assertEquals(overshoot, playback.fidelity.maxError, 1.0 / 32767)
        assertNull(lastVibration(vibrator))
        // The plan the Icons tab shows says so too.
        assertEquals(RendererKind.AUDIO_COUPLED, player().planFor(chirp).renderer)
    }

    @Test
    fun pattern_audioUnavailable_vibratesItsSteps() {
        val playback = player(RecordingAudioOutput(isAvailable = false)).play(chirp, VibrationUsage.TOUCH) as Playback.Playing
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        val steps = chirp.vibrationWaveform()
        assertEquals(RecordedVibration(steps.timings().toList(), steps.amplitudes().toList()), lastVibration(vibrator))
    }

    @Test
    fun cache_keepsOnlyTheNewestFiles() {
        val small = IconAudioCache(File(folder.root, "small"), maxFiles = 2)
        val files = HapticIcon.PRESETS.map { small.fileFor(it) }

        val kept = File(folder.root, "small").listFiles()!!.filter { it.name.endsWith(".wav") }.toSet()
        assertEquals(2, kept.size)
        assertTrue(files.last() in kept)
        assertFalse(File(folder.root, "small").listFiles()!!.any { it.name.endsWith(".part") })
    }

    @Test
    fun outputUnavailable_fallsBackToTheAmplitudeWaveformOnTheVibrator() {
        val playback = player(RecordingAudioOutput(isAvailable = false)).play(HapticIcon.KNOCK, VibrationUsage.TOUCH) as Playback.Playing

        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
    }

    @Test
    fun cacheNotWritable_vibratesInsteadSoThePressIsNotLost() {
        val blocked = File(folder.root, "blocked").apply { writeText("a file where the directory should be") }
        val playback = player(audioCache = IconAudioCache(File(blocked, "icon-audio"))).play(HapticIcon.KNOCK, VibrationUsage.TOUCH) as Playback.Playing

        assertTrue(audio.played.isEmpty())
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        assertEquals(listOf(175, 111, 0, 175, 111, 0, 175, 111), lastVibration(vibrator)!!.amplitudes)
    }

    @Test
    fun stop_stopsTheAudioAndTheVibrator() {
        val player = player()
        player.play(HapticIcon.HUG, VibrationUsage.TOUCH)
        player.stop()
        assertEquals(1, audio.stops)
    }

    @Test
    fun media3Output_unmutesHapticChannelsAndPlaysTheFileOnTheMainThread() {
        val output = Media3AudioCoupledOutput(context)
        val file = cache.fileFor(HapticIcon.KNOCK)

        output.play(file, VibrationUsage.TOUCH)
        shadowOf(Looper.getMainLooper()).idle()

        // A press: sonification, which Android's VibrationAttributes.Builder(AudioAttributes) makes a TOUCH vibration.
        assertEquals(C.USAGE_ASSISTANCE_SONIFICATION, output.audioAttributes!!.usage)
        assertFalse(output.audioAttributes!!.hapticChannelsMuted)
        assertEquals(file.path, output.currentFile!!.path)

        // A received icon: an instant message's notification (NOTIFICATION for the vibrator: allowed in the background).
        output.play(file, VibrationUsage.COMMUNICATION_REQUEST)
        shadowOf(Looper.getMainLooper()).idle()
        assertEquals(C.USAGE_NOTIFICATION_COMMUNICATION_INSTANT, output.audioAttributes!!.usage)
        assertEquals(C.AUDIO_CONTENT_TYPE_SONIFICATION, output.audioAttributes!!.contentType)
        assertFalse(output.audioAttributes!!.hapticChannelsMuted)
        output.stop()
    }

    @Test
    fun media3Output_onAPhoneWithoutHapticPlayback_isUnavailable() {
        // Robolectric's audio system reports no haptic playback, as most phones do.
        assertFalse(Media3AudioCoupledOutput(context).isAvailable)
        assertSame(RendererKind.AMPLITUDE_WAVEFORM, AdaptiveHapticPlayer(usageVibrator(vibrator), { audioPhone }, { null }, Media3AudioCoupledOutput(context), cache).rendererFor(HapticIcon.KNOCK))
    }
}
