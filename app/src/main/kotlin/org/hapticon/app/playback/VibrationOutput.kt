package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import android.os.VibrationEffect
import android.os.Vibrator
import android.os.VibratorManager
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.grains.GrainSink
import org.hapticon.sensor.safety.SafetyLimits

/**
 * Sensor-driven vibration on the phone: short bursts (compliance grains) and a held level that is
 * renewed continuously (handshake pressure). Callable from any thread (the sensor's reading thread).
 * It is sensor-bridge's [GrainSink]: the grain engine's bursts end here, on the phone's vibrator.
 */
interface VibrationOutput : GrainSink {
    /** What the phone's vibrator can do. */
    val capabilities: PlaybackCapabilities

    /** Plays [waveform] at once, replacing whatever this output was playing. */
    override fun play(waveform: VibrationWaveform)

    /**
     * Vibrates at [amplitude] (1..255) for [durationMillis], replacing whatever was playing.
     * @throws org.hapticon.sensor.safety.SafetyLimitException if either is beyond the safety limits.
     */
    fun playLevel(amplitude: Int, durationMillis: Long)

    /** Stops any vibration this output started. */
    fun stop()
}

/** [VibrationOutput] on a [Vibrator]; every effect passes the safety limits before it reaches it. */
class VibratorVibrationOutput(private val vibrator: Vibrator) : VibrationOutput {
    override val capabilities: PlaybackCapabilities
        get() = PlaybackCapabilities(vibrator.hasVibrator(), vibrator.hasAmplitudeControl(), Build.VERSION.SDK_INT)

    override fun play(waveform: VibrationWaveform) {
        if (!vibrator.hasVibrator()) return
        vibrator.vibrate(waveform.toVibrationEffect())
    }

    override fun playLevel(amplitude: Int, durationMillis: Long) {
        SafetyLimits.requireVibrationAmplitude(amplitude)
        SafetyLimits.requireVibrationSeconds(durationMillis / 1000.0)
        require(amplitude >= 1) { "a level needs an amplitude >= 1, was $amplitude" }
        if (!vibrator.hasVibrator()) return
        vibrator.vibrate(VibrationEffect.createOneShot(durationMillis, amplitude))
    }

    override fun stop() = vibrator.cancel()

    companion object {
        /** An output on the phone's default vibrator. */
        fun create(context: Context): VibratorVibrationOutput = VibratorVibrationOutput(defaultVibrator(context))
    }
}

/** The phone's default vibrator. */
fun defaultVibrator(context: Context): Vibrator =
    if (Build.VERSION.SDK_INT >= Build.VERSION_CODES.S) {
        context.getSystemService(VibratorManager::class.java).defaultVibrator
    } else {
        @Suppress("DEPRECATION")
        context.getSystemService(Vibrator::class.java)
    }
