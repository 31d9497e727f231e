package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import android.os.VibrationEffect
import android.os.Vibrator
import android.os.VibratorManager
import org.hapticon.core.platform.VibrationUsage
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

/**
 * [VibrationOutput] on the phone's vibrator; every effect passes the safety limits before it reaches it. What a sensor
 * renders under the user's finger (a compliance grain, the partner's grip) is `USAGE_PHYSICAL_EMULATION`: "vibrations
 * which emulate physical hardware reactions" (AOSP `VibrationAttributes`). Android lets that usage play from the
 * background and in Battery Saver ("the trigger process might still be in the background when the user interaction
 * wakes the device", `VibrationSettings.BACKGROUND_PROCESS_USAGE_ALLOWLIST`), and it follows the user's hardware
 * feedback intensity, not the touch feedback switch.
 */
class VibratorVibrationOutput(private val vibrator: UsageVibrator) : VibrationOutput {
    override val capabilities: PlaybackCapabilities
        get() = PlaybackCapabilities(vibrator.hasVibrator(), vibrator.hasAmplitudeControl(), Build.VERSION.SDK_INT)

    override fun play(waveform: VibrationWaveform) {
        if (!vibrator.hasVibrator()) return
        vibrator.vibrate(waveform.toVibrationEffect(), USAGE)
    }

    override fun playLevel(amplitude: Int, durationMillis: Long) {
        SafetyLimits.requireVibrationAmplitude(amplitude)
        SafetyLimits.requireVibrationSeconds(durationMillis / 1000.0)
        require(amplitude >= 1) { "a level needs an amplitude >= 1, was $amplitude" }
        if (!vibrator.hasVibrator()) return
        vibrator.vibrate(VibrationEffect.createOneShot(durationMillis, amplitude), USAGE)
    }

    override fun stop() = vibrator.cancel()

    companion object {
        /** The usage of every vibration this output makes. */
        val USAGE: VibrationUsage = VibrationUsage.PHYSICAL_EMULATION

        /** An output on the phone's default vibrator. */
        fun create(context: Context): VibratorVibrationOutput = VibratorVibrationOutput(UsageVibrator.create(context))
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
