package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.sync.ChatComponent
import org.hapticon.core.HapticIcon
import org.hapticon.core.midiNoteToHz
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.MessageCodec
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * The API 36 envelope calls on Android 16's own framework (Robolectric's SDK 36 jar): the capabilities come from the
 * real `Vibrator.getFrequencyProfile()` / `getEnvelopeEffectInfo()` of vibrators with no, a narrow and a wide
 * frequency profile, the effects are built by the real `WaveformEnvelopeBuilder` / `BasicEnvelopeBuilder` (with their
 * own validation), and the assertions read the segments the vibrator received.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [36])
class EnvelopeEffectApi36Test {
    private lateinit var context: Context
    private lateinit var vibrator: Vibrator

    // Ramp up 100 ms, hold 200 ms, down 100 ms; 100 → 200 Hz.
    private val swell = HapticPattern(
        "swell",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 1.0), AmplitudeKey(0.3, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.4, 200.0)),
    )

    // The swell one octave above 349.2 Hz (note 77): no phone actuator reaches it.
    private val high = HapticPattern("high", swell.amplitude, listOf(FrequencyKey(0.0, 349.2282314330039)))

    private val wide = TestFrequencyProfile(150f, floatArrayOf(50f, 100f, 150f, 200f, 250f, 300f), floatArrayOf(0.5f, 1f, 2f, 1.5f, 1f, 0.5f))
    private val narrow = TestFrequencyProfile(170f, floatArrayOf(120f, 150f, 170f, 200f, 240f), floatArrayOf(0.5f, 1.5f, 2f, 1.5f, 0.5f))
    private val guaranteed = TestEnvelopeLimits(16, 20, 1000)

    @Before
    fun setUp() {
        context = ApplicationProvider.getApplicationContext()
        vibrator = context.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
    }

    private fun phone(profile: TestFrequencyProfile?, limits: TestEnvelopeLimits? = guaranteed): DeviceCapabilities {
        installVibratorInfo(vibrator, profile, limits)
        return DeviceCapabilities.detect(context, vibrator, hapticPlayback = false, hapticGenerator = false)
    }

    private fun play(device: DeviceCapabilities, pattern: HapticPattern, fit: PitchFit = PitchFit.OCTAVES): Playback =
        AdaptiveHapticPlayer(usageVibrator(vibrator), device = { device }, override = { null }, pitchFit = { fit }).play(pattern, VibrationUsage.TOUCH)

    private fun waveform(startAmplitude: Float, endAmplitude: Float, startHz: Float, endHz: Float, millis: Long) =
        EnvelopeSegment.Waveform(startAmplitude, endAmplitude, startHz, endHz, millis)

    @Test
    fun detect_readsTheProfileAndLimitsThePlatformReports() {
        assertEquals(36, Build.VERSION.SDK_INT)
        val device = phone(wide)
        assertEquals(50.0..300.0, device.frequencyRangeHz)
        assertEquals(150.0, device.resonantFrequencyHz!!, 0.0)
        assertTrue(device.envelopeEffectsSupported)
        // getMaxDurationMillis() is the platform's: max size × longest control point.
        assertEquals(EnvelopeEffectInfo(16, 20, 1000, 16_000), device.envelopeInfo)
        assertNull(phone(null).frequencyRangeHz)
        assertEquals(120.0..240.0, phone(narrow).frequencyRangeHz)
    }

    @Test
    fun publishedCapabilities_carryTheShadowedVibratorsEnvelopeLimits() {
        // What ChatSync publishes at connect and on every republish (ChatComponent.create hands it this function).
        val settings = InMemoryChatSettings()
        val narrowLimits = phone(narrow, TestEnvelopeLimits(4, 50, 500))
        val caps = ChatComponent.localCapabilities({ narrowLimits }, settings)("alice")
        // getMaxDurationMillis() is the platform's: 4 × 500 ms.
        assertEquals(EnvelopeEffectInfo(4, 50, 500, 2000), caps.envelopeLimits)
        assertEquals(
            """{"schema":"hapticon.capabilities","version":1,"user":"alice","renderer":"envelope","amplitudeControl":true,"apiLevel":36,""" +
                """"resonantFrequencyHz":170,"envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"octaves",""" +
                """"envelopeMaxControlPoints":4,"envelopeMinControlPointMillis":50,"envelopeMaxControlPointMillis":500,"envelopeMaxDurationMillis":2000}""",
            String(MessageCodec.encode(caps), Charsets.UTF_8),
        )
        // A sender reading it previews with these limits: the one resampling this phone plays with.
        val preview = (PeerPitch.planOf((MessageCodec.decodeCapabilities(MessageCodec.encode(caps)) as Decoded.Accepted).value, swell) as PatternPlan.Envelope)
            .envelope as PatternEnvelope.Waveform
        play(narrowLimits, swell)
        assertEquals(preview.points.map { it.millis }, lastEnvelopeSegments().map { it.millis })
        assertEquals(listOf(100L, 200L, 100L), preview.points.map { it.millis })
        // A vibrator without envelope effects publishes none.
        val plain = ChatComponent.localCapabilities({ phone(narrow, limits = null) }, settings)("alice")
        assertNull(plain.envelopeLimits)
        assertEquals(false, String(MessageCodec.encode(plain), Charsets.UTF_8).contains("envelopeMax"))
    }

    @Test
    fun detect_noEnvelopeEffects_noEnvelopeInfo() {
        val device = phone(wide, limits = null)
        assertEquals(false, device.envelopeEffectsSupported)
        assertNull(device.envelopeInfo)
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, (play(device, swell) as Playback.Playing).renderer)
    }

    @Test
    fun wideProfile_waveformEnvelopeWithThePatternsOwnHz() {
        val playback = play(phone(wide), swell) as Playback.Playing
        assertEquals(RendererKind.ENVELOPE, playback.renderer)
        assertEquals(400L, playback.durationMillis)
        // Each point reaches its amplitude at the pattern's frequency at its end time; the builder starts at 0 and 100 Hz.
        assertEquals(
            listOf(waveform(0f, 1f, 100f, 125f, 100), waveform(1f, 1f, 125f, 175f, 200), waveform(1f, 0f, 175f, 200f, 100)),
            lastEnvelopeSegments(),
        )
    }

    @Test
    fun narrowProfile_octaveShiftMovesTheWholePatternDownOneOctave() {
        play(phone(narrow), high)
        val hz = 174.61412f // 349.2 / 2: note 65, inside 120–240 Hz
        assertEquals(
            listOf(waveform(0f, 1f, hz, hz, 100), waveform(1f, 1f, hz, hz, 200), waveform(1f, 0f, hz, hz, 100)),
            lastEnvelopeSegments(),
        )
    }

    @Test
    fun narrowProfile_clampPinsEveryPointToTheTopOfTheRange() {
        play(phone(narrow), high, PitchFit.CLAMP)
        assertEquals(
            listOf(waveform(0f, 1f, 240f, 240f, 100), waveform(1f, 1f, 240f, 240f, 200), waveform(1f, 0f, 240f, 240f, 100)),
            lastEnvelopeSegments(),
        )
    }

    @Test
    fun noProfile_basicEnvelopeWithSharpnessFromTheFrequency() {
        play(phone(null), swell)
        val x = FrequencyMapping.DEFAULT
        fun s(hz: Double) = x.normalizedOf(hz).toFloat()
        assertEquals(
            listOf(
                EnvelopeSegment.Basic(0f, 1f, s(100.0), s(125.0), 100),
                EnvelopeSegment.Basic(1f, 1f, s(125.0), s(175.0), 200),
                EnvelopeSegment.Basic(1f, 0f, s(175.0), s(200.0), 100),
            ),
            lastEnvelopeSegments(),
        )
    }

    @Test
    fun tightLimits_longRampsCutIntoEqualPartsOnTheSameLine() {
        // At most 100 ms per control point: the 200 ms hold becomes two points, frequency still read at each end.
        play(phone(wide, TestEnvelopeLimits(8, 20, 100)), swell)
        assertEquals(
            listOf(
                waveform(0f, 1f, 100f, 125f, 100), waveform(1f, 1f, 125f, 150f, 100),
                waveform(1f, 1f, 150f, 175f, 100), waveform(1f, 0f, 175f, 200f, 100),
            ),
            lastEnvelopeSegments(),
        )
    }

    @Test
    fun tooFewControlPoints_amplitudeStepsInstead() {
        // 3 points of at most 100 ms: the platform's maximum duration (300 ms) is shorter than the swell.
        val playback = play(phone(wide, TestEnvelopeLimits(3, 20, 100)), swell) as Playback.Playing
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        assertEquals(400L, lastVibration(vibrator)!!.timings.sum())
    }

    @Test
    fun settingsPitchFit_notes0_57_65_127_playExactlyTheseHzOnNarrowAndWideProfiles() {
        // The app's player reads the fit from Settings at every play, as ChatComponent builds it.
        val settings = InMemoryChatSettings()
        fun hzPlayed(profile: TestFrequencyProfile, note: Int, fit: PitchFit): Float {
            settings.update { it.copy(pitchFit = fit) }
            val device = phone(profile)
            val pattern = HapticPattern("note $note", swell.amplitude, listOf(FrequencyKey(0.0, midiNoteToHz(note.toDouble()))))
            ChatComponent.chatPlayer(usageVibrator(vibrator), { device }, settings).play(pattern, VibrationUsage.TOUCH)
            return lastEnvelopeSegments().map { it as EnvelopeSegment.Waveform }.flatMap { listOf(it.startHz, it.endHz) }.distinct().single()
        }
        val notes = listOf(0, 57, 65, 127)
        // Octaves: the fewest that reach the range (C3, A3, F3, G3 in 120–240 Hz; C2, A3, F3, G3 in 50–300 Hz).
        assertEquals(listOf(130.81279f, 220f, 174.61412f, 195.99771f), notes.map { hzPlayed(narrow, it, PitchFit.OCTAVES) })
        assertEquals(listOf(65.406395f, 220f, 174.61412f, 195.99771f), notes.map { hzPlayed(wide, it, PitchFit.OCTAVES) })
        assertEquals(listOf(120f, 220f, 240f, 240f), notes.map { hzPlayed(narrow, it, PitchFit.CLAMP) })
        assertEquals(listOf(50f, 220f, 300f, 300f), notes.map { hzPlayed(wide, it, PitchFit.CLAMP) })
    }

    @Test
    fun icon_envelopePhone_theNoteReachesTheActuator() {
        // Hug (note 50, 146.8 Hz) on a narrow profile: every point at the note, not a fixed sharpness.
        val device = phone(narrow)
        val player = AdaptiveHapticPlayer(usageVibrator(vibrator), device = { device }, override = { null })
        assertEquals(RendererKind.ENVELOPE, (player.play(HapticIcon.HUG, VibrationUsage.TOUCH) as Playback.Playing).renderer)
        // The envelope effect carries its usage too (VibrationAttributes on API 36).
        assertEquals(VibrationUsage.TOUCH, lastUsage(vibrator))
        val segments = lastEnvelopeSegments().map { it as EnvelopeSegment.Waveform }
        assertEquals(setOf(146.83238f), segments.flatMap { listOf(it.startHz, it.endHz) }.toSet())
        assertEquals(3000L, segments.sumOf { it.millis })
        assertEquals(0f, segments.last().endAmplitude, 0f)
        // Without a profile the note becomes sharpness (50 − 36) / 36 on the C2..C5 scale.
        val basic = phone(null)
        AdaptiveHapticPlayer(usageVibrator(vibrator), device = { basic }, override = { null }).play(HapticIcon.HUG, VibrationUsage.TOUCH)
        val sharpness = lastEnvelopeSegments().map { it as EnvelopeSegment.Basic }.flatMap { listOf(it.startSharpness, it.endSharpness) }.toSet()
        assertEquals(setOf((14.0 / 36).toFloat()), sharpness)
    }

    @Test
    fun noProfile_fadeCutIntoThirds_endsOnExactlyZeroIntensity() {
        // 0.7 → 0 over 300 ms in 100 ms parts: 0.7 + (0 − 0.7)·3/3 is 1.1e-16 in doubles, and BasicEnvelopeBuilder
        // refuses an effect whose last intensity is not exactly 0 ("must end at a zero intensity control point").
        val fade = HapticPattern(
            "fade",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 0.7), AmplitudeKey(0.4, 0.7), AmplitudeKey(0.7, 0.0)),
            listOf(FrequencyKey(0.0, 150.0)),
        )
        val playback = play(phone(null, TestEnvelopeLimits(16, 20, 100)), fade) as Playback.Playing
        assertEquals(RendererKind.ENVELOPE, playback.renderer)
        val segments = lastEnvelopeSegments().map { it as EnvelopeSegment.Basic }
        assertEquals(listOf(100L, 100L, 100L, 100L, 100L, 100L, 100L), segments.map { it.millis })
        assertEquals(0f, segments.last().endIntensity, 0f)
        assertEquals(listOf(0.7f, 0.7f, 0.7f, 0.7f, 0.46666667f, 0.23333333f, 0f), segments.map { it.endIntensity })
    }
}
