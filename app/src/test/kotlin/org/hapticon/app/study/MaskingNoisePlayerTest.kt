package org.hapticon.app.study

import android.content.Context
import android.media.AudioDeviceInfo
import android.media.AudioManager
import android.os.Looper
import androidx.media3.common.Player
import androidx.test.core.app.ApplicationProvider
import java.io.File
import org.hapticon.core.io.WavReader
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.shadows.AudioDeviceInfoBuilder

/** The masking noise files, the ExoPlayer that loops them, and the headphone check. */
@RunWith(RobolectricTestRunner::class)
class MaskingNoisePlayerTest {
    @get:Rule val folder = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()

    private fun idle() = shadowOf(Looper.getMainLooper()).idle()

    @Test
    fun noiseFile_isTenSecondsOfPcm16At48kHz_renderedOnce() {
        val files = NoiseFiles(File(folder.root, "noise"))
        val pink = files.fileFor(NoiseColor.PINK)

        assertEquals("pink-20240501-48000.wav", pink.name)
        assertEquals(44L + 2 * 480_000, pink.length())
        val wav = pink.inputStream().use { WavReader.read(it) }
        assertEquals(48_000, wav.sampleRate)
        assertEquals(-12.0, NoiseGenerator.rmsDbfs(wav.samples()), 0.01)
        pink.setLastModified(1_000L)
        assertEquals(pink, files.fileFor(NoiseColor.PINK))
        assertEquals("not rendered again", 1_000L, pink.lastModified())
        assertEquals("white-20240501-48000.wav", files.fileFor(NoiseColor.WHITE).name)
    }

    @Test
    fun start_loopsTheColorsFileAtTheLevelsVolume_andStopStopsIt() {
        val files = NoiseFiles(File(folder.root, "noise"))
        val player = Media3MaskingNoisePlayer(context, files)

        player.start(MaskingSetting(NoiseColor.PINK, -30.0))
        idle()

        assertEquals(files.fileFor(NoiseColor.PINK).path, player.currentFile!!.path)
        assertEquals(Player.REPEAT_MODE_ONE, player.repeatMode)
        assertEquals(0.125893f, player.volume, 1e-6f)
        assertTrue(player.isPlayRequested)

        player.stop()
        idle()
        assertFalse(player.isPlayRequested)

        player.start(MaskingSetting(NoiseColor.WHITE, 0.0))
        idle()
        assertEquals("white-20240501-48000.wav", player.currentFile!!.name)
        assertEquals("the level is capped at the rendered file's", 1f, player.volume, 0f)
        player.release()
        idle()
    }

    @Test
    fun startWithNoiseOff_playsNothing() {
        val player = Media3MaskingNoisePlayer(context, NoiseFiles(File(folder.root, "noise")))
        player.start(MaskingSetting(NoiseColor.OFF))
        idle()
        assertNull(player.currentFile)
        assertFalse(File(folder.root, "noise").exists())
    }

    @Test
    fun headphones_onlyHeadphoneTypesCount() {
        val audio = context.getSystemService(AudioManager::class.java)
        val detector = AudioManagerHeadphoneDetector(context)
        shadowOf(audio).setOutputDevices(listOf(AudioDeviceInfoBuilder.newBuilder().setType(AudioDeviceInfo.TYPE_BUILTIN_SPEAKER).build()))
        assertFalse(detector.headphonesConnected())
        shadowOf(audio).setOutputDevices(
            listOf(
                AudioDeviceInfoBuilder.newBuilder().setType(AudioDeviceInfo.TYPE_BUILTIN_SPEAKER).build(),
                AudioDeviceInfoBuilder.newBuilder().setType(AudioDeviceInfo.TYPE_BLUETOOTH_A2DP).build(),
            ),
        )
        assertTrue(detector.headphonesConnected())
    }
}
