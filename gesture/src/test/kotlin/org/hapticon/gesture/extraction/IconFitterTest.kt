package org.hapticon.gesture.extraction

import org.hapticon.core.HapticIcon
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.io.RecordingCsv
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test
import java.util.Random
import kotlin.math.PI
import kotlin.math.sin

class IconFitterTest {
    private val fullScale = FitOptions(levelReference = LevelReference.FullScale)
    private val peak = FitOptions(levelReference = LevelReference.GesturePeak)

    @Test fun recoversThePresetsFromCleanRenders() {
        for (preset in listOf(HapticIcon.HIT, HapticIcon.KNOCK, HapticIcon.STROKE, HapticIcon.HUG)) {
            val gesture = NoisyIconRenders.render(preset, Double.POSITIVE_INFINITY, Random(1))
            val fit = IconFitter.fit(gesture.toRecording(), options = fullScale)
            val icon = fit.icon
            assertEquals(preset.name, preset.note, icon.note, 0.0)
            assertEquals(preset.name, preset.count, icon.count)
            assertEquals(preset.name, preset.period, icon.period, 0.0005)
            // The envelope filter rounds the corners of millisecond ramps (2 ms covers knock's 5 ms attack);
            // stroke's overlapping repetitions leave the foot of its attack to the first one alone (0.5 %).
            assertEquals(preset.name, preset.attack, icon.attack, 0.002 + 0.005 * preset.attack)
            assertEquals(preset.name, preset.sustain, icon.sustain, 0.002 + 0.005 * preset.sustain)
            assertEquals(preset.name, preset.release, icon.release, 0.002 + 0.005 * preset.release)
            assertEquals(preset.name, preset.level, icon.level, 0.01)
            assertEquals(preset.name, SignalKind.VIBRATION, fit.report.kind)
            assertEquals(preset.name, preset.count, fit.report.onsets.size)
            assertEquals(preset.name, NoisyIconRenders.PAD_SECONDS, fit.report.onsets.first(), 0.002 + 0.005 * preset.attack)
            assertTrue(preset.name, fit.report.rSquared > 0.99)
            // No noise: only the filtered feet of the ramps count as noise.
            assertTrue(preset.name, fit.report.snrDb!! > 50.0)
            assertEquals(preset.name, emptyList<String>(), fit.report.warnings)
        }
    }

    /** The documented tolerances at 30 dB (docs/gesture-extraction.md), over 10 seeded random icons. */
    @Test fun meetsTheDocumentedToleranceAt30dB() {
        val row = FitBenchmark.run(trials = 10, seed = 7, snrs = listOf(30.0), methods = listOf(EnvelopeMethod.LOWPASS)).single()
        assertEquals(0, row.failures)
        assertEquals(1.0, row.noteExact, 0.0)
        assertEquals(1.0, row.countExact, 0.0)
        assertTrue("worst attack error ${row.attackWorst}", row.attackWorst < 0.002)
        assertTrue("mean attack error ${row.attackError}", row.attackError < 0.0005)
        assertTrue("mean sustain error ${row.sustainError}", row.sustainError < 0.0005)
        assertTrue("mean release error ${row.releaseError}", row.releaseError < 0.0005)
        assertTrue("mean level error ${row.levelError}", row.levelError < 0.001)
        assertTrue("mean period error ${row.periodError}", row.periodError < 0.001)
        assertEquals(30.0, row.estimatedSnrDb!!, 1.0)
    }

    @Test fun fit_defaultReference_isTheInputsFullScaleSoLevelsKeepTheGesturesStrength() {
        // Stroke (level 0.3) and knock (0.5) recorded as normalised WAV-like signals at 40 dB SNR.
        for (preset in listOf(HapticIcon.STROKE, HapticIcon.KNOCK)) {
            val fit = IconFitter.fit(NoisyIconRenders.render(preset, 40.0, Random(3)).toRecording())
            assertEquals(preset.name, preset.level, fit.icon.level, 0.02)
            assertEquals(preset.name, "the input's full scale 1.000", fit.report.levelReference)
            assertEquals(preset.name, 1.0, fit.report.levelReferenceValue, 0.0)
            assertTrue(preset.name, fit.report.parameter("level").how.endsWith("relative to the input's full scale 1.000"))
        }
    }

    @Test fun fit_gesturePeakReference_makesEveryIconFullStrength() {
        val gesture = NoisyIconRenders.render(HapticIcon.STROKE, 40.0, Random(3))
        val fit = IconFitter.fit(gesture.toRecording(), options = peak)
        // A flat sustain with noise reads about 2 envelope-noise σ below its own 99th percentile.
        assertEquals(0.98, fit.icon.level, 0.02)
        assertEquals(HapticIcon.STROKE.level, fit.report.envelopePeak, 0.01)
        assertEquals("level", fit.report.parameters[2].name)
        assertEquals(listOf("attack", "sustain", "level", "release", "note", "period", "count"), fit.report.parameters.map { it.name })
    }

    @Test fun fit_valueReference_dividesTheLevelByIt() {
        val recording = NoisyIconRenders.render(HapticIcon.KNOCK, 40.0, Random(5)).toRecording()
        val fit = IconFitter.fit(recording, options = FitOptions(levelReference = LevelReference.Value(0.625)))
        assertEquals(0.8, fit.icon.level, 0.02)
        assertEquals("the given reference 0.6250", fit.report.levelReference)
    }

    @Test fun fit_channelInPhysicalUnitsWithoutFullScale_asksForAReference() {
        val x = DoubleArray(2000) { i -> if (i in 500 until 700) 2.0 else 0.1 }
        val error = assertThrows(IllegalArgumentException::class.java) { IconFitter.fit(Recording(500.0, listOf(Channel("force", "N", x)))) }
        assertEquals(
            "channel force is in N with no known full scale: give a reference (--reference VALUE, e.g. the sensor's calibrated maximum, or --reference strongest)",
            error.message,
        )
    }

    @Test fun fitBatch_strongestGestureIsLevelOneAndTheOthersKeepTheirRatio() {
        val strong = NoisyIconRenders.render(HapticIcon.KNOCK, 40.0, Random(1)).toRecording()
        val weak = NoisyIconRenders.render(HapticIcon.KNOCK.copy(level = 0.25), 40.0, Random(2)).toRecording()
        val (strongFit, weakFit) = IconFitter.fitBatch(listOf(strong, weak))
        assertEquals(1.0, strongFit.icon.level, 0.03)
        assertEquals(0.5, weakFit.icon.level, 0.03)
        assertEquals(strongFit.report.levelReferenceValue, weakFit.report.levelReferenceValue, 0.0)
        assertEquals(0.5, weakFit.report.levelReferenceValue, 0.02)
        assertTrue(weakFit.report.levelReference, weakFit.report.levelReference.startsWith("the strongest gesture of the batch of 2 "))
        assertThrows(IllegalArgumentException::class.java) { IconFitter.fitBatch(emptyList()) }
    }

    @Test fun allZerosConstantAndTooShortAreNoGesture() {
        assertEquals("no gesture found: channel v is all zeros", noGesture(DoubleArray(1000)))
        assertEquals("no gesture found: channel v is constant at 0.3000", noGesture(DoubleArray(1000) { 0.3 }))
        assertEquals("no gesture found: the recording has 1 sample(s), too short to hold one (need at least 16)", noGesture(doubleArrayOf(0.5)))
        assertEquals("no gesture found: the recording has 0 sample(s), too short to hold one (need at least 16)", noGesture(DoubleArray(0)))
    }

    @Test fun aNonFiniteSampleIsAClearError() {
        val x = DoubleArray(1000) { sin(it * 0.3) }.also { it[500] = Double.NaN }
        val e = assertThrows(IllegalArgumentException::class.java) { IconFitter.fit(recording(x, 1000.0)) }
        assertEquals("channel v has a non-finite sample (NaN) at index 500 (0.5000 s)", e.message)
        val missing = assertThrows(IllegalArgumentException::class.java) { IconFitter.fit(recording(x, 1000.0), "force") }
        assertEquals("no channel 'force'; the recording has v", missing.message)
    }

    @Test fun aNanCellInACsvIsRejectedWithItsLine() {
        val csv = "time_s,v\n" + (0 until 100).joinToString("") { "${it / 1000.0},${if (it == 40) "NaN" else "0.5"}\n" }
        val e = assertThrows(IllegalArgumentException::class.java) { IconFitter.fit(RecordingCsv.read(csv, "tap.csv")) }
        assertEquals("tap.csv:42: v is NaN; gaps are rejected (fill them, or read with GapPolicy.INTERPOLATE)", e.message)
    }

    @Test fun aSaturatedRecordingIsFittedWithWarnings() {
        // Three 200 ms bursts of a 250 Hz sine at 4× full scale, clipped to ±1: nearly a square wave.
        val rate = 44_100.0
        val x = DoubleArray(44_100 * 2) { i ->
            val t = i / rate
            val inBurst = (0 until 3).any { k -> t >= 0.2 + 0.5 * k && t < 0.4 + 0.5 * k }
            if (inBurst) (4.0 * sin(2 * PI * 250.0 * t)).coerceIn(-1.0, 1.0) else 0.0
        }
        val fit = IconFitter.fit(recording(x, rate), options = fullScale)
        assertEquals(59.0, fit.icon.note, 0.0) // 250 Hz: 59.21
        assertEquals(3, fit.icon.count)
        assertEquals(0.5, fit.icon.period, 0.001)
        assertEquals(1.0, fit.icon.level, 0.0)
        assertTrue(fit.report.parameter("level").clamped)
        assertTrue(fit.report.warnings.toString(), fit.report.warnings.any { it.startsWith("saturated: ") })
        assertTrue(fit.report.warnings.toString(), fit.report.warnings.any { it.startsWith("level ") && it.endsWith(" clamped to 1.000") })
    }

    @Test fun anHourAtOneKilohertzWithThreePressesIsFitted() {
        // 3.6 M samples of an FSR resting at 0.5 N, with three 4 N presses (100/300/100 ms) 2 s apart at 30 min.
        val rate = 1000.0
        val x = DoubleArray(3_600_000) { 0.5 }
        val press = HapticIcon("press", 0.1, 0.3, 1.0, 0.1, 60.0)
        for (k in 0 until 3) {
            val start = 1_800_000 + 2000 * k
            for (j in 0 until 500) x[start + j] += 4.0 * trapezoid(j / rate, press)
        }
        // A 20 N load cell: its calibrated maximum is the full scale, so the 4 N press fits level 0.2.
        val fit = IconFitter.fit(Recording(rate, listOf(Channel("force", "N", x, fullScale = 20.0))))
        assertEquals(0.2, fit.icon.level, 0.005)
        assertEquals("the input's full scale 20.00 N", fit.report.levelReference)
        assertEquals(SignalKind.FORCE, fit.report.kind)
        assertEquals(3, fit.icon.count)
        assertEquals(2.0, fit.icon.period, 0.002)
        assertEquals(1800.0, fit.report.onsets.first(), 0.01)
        assertEquals(0.1, fit.icon.attack, 0.01)
        assertEquals(0.3, fit.icon.sustain, 0.01)
        assertEquals(0.1, fit.icon.release, 0.01)
        assertEquals(4.0, fit.report.envelopePeak, 0.05)
        val contact = fit.icon.attack + fit.icon.sustain + fit.icon.release
        assertEquals(ForceNote.note(fit.report.envelopePeak / 20.0, contact).toDouble(), fit.icon.note, 0.0)
        assertEquals(51.0, fit.icon.note, 0.0) // firmness 0.2, contact 0.5 s: 51.17
    }

    @Test fun moreThan64TapsAndOverlongHoldsAreClampedWithWarnings() {
        val rate = 1000.0
        val taps = DoubleArray(10_000) { i -> if (i % 100 in 10 until 40) 3.0 else 0.0 }
        val many = IconFitter.fit(Recording(rate, listOf(Channel("force", "N", taps))), options = peak)
        assertEquals(HapticIcon.MAX_COUNT, many.icon.count)
        assertEquals(100.0, many.report.parameter("count").measured, 0.0)
        assertTrue(many.report.warnings.toString(), many.report.warnings.contains("count 100 clamped to 64"))

        val hold = DoubleArray(50_000) { i -> if (i in 1000 until 46_000) 5.0 else 0.0 }
        val held = IconFitter.fit(Recording(rate, listOf(Channel("force", "N", hold))), options = peak)
        assertEquals(HapticIcon.MAX_DURATION_SECONDS, held.icon.duration, 1e-9)
        assertEquals(45.0, held.report.parameter("sustain").measured, 0.05)
        assertTrue(held.report.warnings.toString(), held.report.warnings.any { it.contains("clamped to the 30.0 s duration cap") })
    }

    @Test fun aForceChannelWithAnUnknownUnitGetsAMidFirmnessNote() {
        val rate = 500.0
        val x = DoubleArray(2000) { i -> if (i in 500 until 700) 2.0 else 0.1 }
        val fit = IconFitter.fit(Recording(rate, listOf(Channel("bend", "deg", x))), options = FitOptions(levelReference = LevelReference.Value(90.0)))
        assertEquals(SignalKind.FORCE, fit.report.kind)
        val contact = fit.icon.attack + fit.icon.sustain + fit.icon.release
        assertEquals(ForceNote.note(0.5, contact).toDouble(), fit.icon.note, 0.0)
        assertEquals(listOf("force scale of unit 'deg' unknown: firmness taken as 0.5 for the note"), fit.report.warnings)
    }

    private fun noGesture(x: DoubleArray): String? =
        assertThrows(NoGestureException::class.java) { IconFitter.fit(Recording(1000.0, listOf(Channel("v", "", x)))) }.message

    private fun recording(x: DoubleArray, rate: Double) = Recording(rate, listOf(Channel("v", "", x)))

    private fun trapezoid(t: Double, icon: HapticIcon): Double = when {
        t < icon.attack -> t / icon.attack
        t < icon.attack + icon.sustain -> 1.0
        t < icon.envelopeDuration -> (icon.envelopeDuration - t) / icon.release
        else -> 0.0
    }
}
