package org.hapticon.app.playback

import android.os.Vibrator
import org.robolectric.shadows.ShadowVibrator

/**
 * A vibrator's frequency profile as the HAL reports it: the resonant frequency and output acceleration per frequency
 * (Android's hidden `VibratorInfo.FrequencyProfile`; `Vibrator.getFrequencyProfile()` reports its min..max).
 */
data class TestFrequencyProfile(val resonantHz: Float, val frequenciesHz: FloatArray, val accelerationsGs: FloatArray)

/** `VibratorEnvelopeEffectInfo` as the HAL reports it (max control points, min and max control point duration). */
data class TestEnvelopeLimits(val maxSize: Int, val minControlPointMillis: Int, val maxControlPointMillis: Int)

/**
 * Makes the API 36 [vibrator] (the platform's `SystemVibrator` under Robolectric) report [profile] and [limits]:
 * Robolectric 4.17 has no shadow for the frequency profile or envelope effects, so the real `Vibrator` methods run
 * on the `VibratorInfo` planted here, exactly as on a phone (`SystemVibrator.getInfo()` returns its cached
 * `mVibratorInfo`). The capabilities are those `VibratorInfo.areEnvelopeEffectsSupported()` asks for
 * (`CAP_COMPOSE_PWLE_EFFECTS_V2 | CAP_FREQUENCY_CONTROL`, AOSP `VibratorInfo.java`) plus amplitude control; a null
 * [profile] is an empty one, which `getFrequencyProfile()` reports as null.
 */
fun installVibratorInfo(vibrator: Vibrator, profile: TestFrequencyProfile?, limits: TestEnvelopeLimits?) {
    val frequencyProfileClass = Class.forName("android.os.VibratorInfo\$FrequencyProfile")
    val frequencyProfile = if (profile == null) {
        frequencyProfileClass.getConstructor(Float::class.java, FloatArray::class.java, FloatArray::class.java)
            .newInstance(Float.NaN, FloatArray(0), FloatArray(0))
    } else {
        frequencyProfileClass.getConstructor(Float::class.java, FloatArray::class.java, FloatArray::class.java)
            .newInstance(profile.resonantHz, profile.frequenciesHz, profile.accelerationsGs)
    }
    val builderClass = Class.forName("android.os.VibratorInfo\$Builder")
    val builder = builderClass.getConstructor(Int::class.java).newInstance(0)
    val capabilities = CAP_AMPLITUDE_CONTROL or (if (limits != null) CAP_FREQUENCY_CONTROL or CAP_COMPOSE_PWLE_EFFECTS_V2 else 0L)
    builderClass.getMethod("setCapabilities", Long::class.java).invoke(builder, capabilities)
    builderClass.getMethod("setFrequencyProfile", frequencyProfileClass).invoke(builder, frequencyProfile)
    if (limits != null) {
        builderClass.getMethod("setMaxEnvelopeEffectSize", Int::class.java).invoke(builder, limits.maxSize)
        builderClass.getMethod("setMinEnvelopeEffectControlPointDurationMillis", Int::class.java).invoke(builder, limits.minControlPointMillis)
        builderClass.getMethod("setMaxEnvelopeEffectControlPointDurationMillis", Int::class.java).invoke(builder, limits.maxControlPointMillis)
    }
    val info = builderClass.getMethod("build").invoke(builder)
    var type: Class<*>? = vibrator.javaClass
    while (type != null && type.name != "android.os.SystemVibrator") type = type.superclass
    val field = checkNotNull(type) { "${vibrator.javaClass} is not a SystemVibrator" }.getDeclaredField("mVibratorInfo")
    field.isAccessible = true
    field.set(vibrator, info)
    // Vibrator caches what it derived from the previous info; a phone whose HAL changed is a new phone.
    for (cached in listOf("mVibratorFrequencyProfile", "mVibratorEnvelopeEffectInfo")) {
        Vibrator::class.java.getDeclaredField(cached).apply { isAccessible = true }.set(vibrator, null)
    }
}

/** One segment of the last envelope effect a vibrator received, in the units its builder took. */
sealed interface EnvelopeSegment {
    val millis: Long

    /** `android.os.vibrator.PwleSegment` (`WaveformEnvelopeBuilder`): amplitude and frequency in Hz, start → end. */
    data class Waveform(val startAmplitude: Float, val endAmplitude: Float, val startHz: Float, val endHz: Float, override val millis: Long) : EnvelopeSegment

    /** `android.os.vibrator.BasicPwleSegment` (`BasicEnvelopeBuilder`): intensity and sharpness, start → end. */
    data class Basic(val startIntensity: Float, val endIntensity: Float, val startSharpness: Float, val endSharpness: Float, override val millis: Long) : EnvelopeSegment
}

/**
 * The segments of the last effect a vibrator was asked to play (the shadow keeps one record for all of them). Robolectric's `ShadowSystemVibrator` keeps the
 * `VibrationEffect.Composed`'s segments in ShadowVibrator's protected `vibrationEffectSegments`; the segment classes
 * are hidden from the public android.jar, so their getters are called reflectively.
 */
fun lastEnvelopeSegments(): List<EnvelopeSegment> {
    val field = ShadowVibrator::class.java.getDeclaredField("vibrationEffectSegments").apply { isAccessible = true }
    return (field.get(null) as List<*>).map { segment ->
        fun float(name: String) = segment!!.javaClass.getMethod(name).invoke(segment) as Float
        val millis = segment!!.javaClass.getMethod("getDuration").invoke(segment) as Long
        when (segment.javaClass.name) {
            "android.os.vibrator.PwleSegment" ->
                EnvelopeSegment.Waveform(float("getStartAmplitude"), float("getEndAmplitude"), float("getStartFrequencyHz"), float("getEndFrequencyHz"), millis)
            "android.os.vibrator.BasicPwleSegment" ->
                EnvelopeSegment.Basic(float("getStartIntensity"), float("getEndIntensity"), float("getStartSharpness"), float("getEndSharpness"), millis)
            else -> error("not an envelope segment: $segment")
        }
    }
}

// android.hardware.vibrator.IVibrator (hidden): the capability bits VibratorInfo tests.
private const val CAP_AMPLITUDE_CONTROL = 4L
private const val CAP_FREQUENCY_CONTROL = 512L
private const val CAP_COMPOSE_PWLE_EFFECTS_V2 = 4096L
