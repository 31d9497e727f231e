package org.hapticon.app.sensors

import java.io.Closeable
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.app.playback.PlaybackCapabilities
import org.hapticon.app.playback.VibrationOutput
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.FlexDivider
import org.hapticon.sensor.glove.ForceFeedbackSink
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.GloveListener
import org.hapticon.sensor.glove.GloveSource
import org.hapticon.sensor.glove.PartnerHand

/** A glove whose samples the test pushes with [push] (on the test's thread, as if it were the sensor's). */
class TestGloveSource(connected: Boolean = true, override val divider: FlexDivider = FlexDivider()) : GloveSource {
    val connectedFlow = MutableStateFlow(connected)
    private val listeners = CopyOnWriteArrayList<GloveListener>()

    override val connected: Flow<Boolean> = connectedFlow

    /** Whether the glove takes force feedback; [forceFeedbackSent] records what it got. */
    val acceptsForceFeedbackFlow = MutableStateFlow(false)
    val forceFeedbackSent = CopyOnWriteArrayList<List<Int>>()

    override val acceptsForceFeedback: Flow<Boolean> = acceptsForceFeedbackFlow

    override val forceFeedback: ForceFeedbackSink = ForceFeedbackSink { values ->
        acceptsForceFeedbackFlow.value && forceFeedbackSent.add(values.toList())
    }

    override fun addListener(listener: GloveListener): Closeable {
        listeners += listener
        return Closeable { listeners -= listener }
    }

    fun push(thumbVolts: Double, middleVolts: Double, nanos: Long = 0) {
        for (l in listeners) l.onGloveSample(thumbVolts, middleVolts, nanos)
    }

    /** The divider output of a flex sensor at [degrees] with [calibration]. */
    fun voltsAt(degrees: Double, calibration: FlexCalibration): Double = divider.voltsFor(calibration.resistanceAt(degrees))
}

/** [CalibrationStore] in memory. */
class TestCalibrationStore(user: String = CalibrationStore.DEFAULT_USER) : CalibrationStore {
    private val users = MutableStateFlow(user)
    private val saves = MutableStateFlow(0L)
    val saved = mutableMapOf<Pair<String, GloveFinger>, SavedCalibration>()

    override val currentUser: StateFlow<String> = users.asStateFlow()
    override val revision: StateFlow<Long> = saves.asStateFlow()

    override fun setCurrentUser(user: String) {
        users.value = user.trim().ifEmpty { CalibrationStore.DEFAULT_USER }
    }

    override fun load(user: String, finger: GloveFinger): SavedCalibration? = synchronized(saved) { saved[user to finger] }

    override fun save(user: String, finger: GloveFinger, calibration: SavedCalibration) {
        synchronized(saved) { saved[user to finger] = calibration }
        saves.value = saves.value + 1
    }
}

/** A partner holding still at [thumbDegrees]/[middleDegrees]. */
class TestPartnerHand(@Volatile var thumbDegrees: Double, @Volatile var middleDegrees: Double) : PartnerHand {
    override val label = "Test partner"

    override fun readAngles(nowNanos: Long, out: DoubleArray) {
        out[0] = thumbDegrees
        out[1] = middleDegrees
    }
}

/** Passes everything to [delegate] (the Robolectric vibrator) and notes each call, with [record] reading what arrived. */
class RecordingVibrationOutput<R>(private val delegate: VibrationOutput, private val record: () -> R) : VibrationOutput {
    val played = CopyOnWriteArrayList<R>()
    @Volatile var stops = 0

    override val capabilities: PlaybackCapabilities get() = delegate.capabilities

    override fun play(waveform: VibrationWaveform) {
        delegate.play(waveform)
        played += record()
    }

    override fun playLevel(amplitude: Int, durationMillis: Long) {
        delegate.playLevel(amplitude, durationMillis)
        played += record()
    }

    override fun stop() {
        delegate.stop()
        stops++
    }
}

/** A nanosecond clock the test moves. */
class TestClock(@Volatile var nanos: Long = 1_000_000_000L) : () -> Long {
    override fun invoke(): Long = nanos

    fun advanceMillis(millis: Long) {
        nanos += millis * 1_000_000
    }
}

/** A [HandshakeLink] in memory: [peersFlow] to offer, [sent] records the wearer's angles per peer. */
class TestHandshakeLink(peers: List<String> = listOf("bob")) : HandshakeLink {
    val peersFlow = MutableStateFlow(peers)
    val sent = CopyOnWriteArrayList<Triple<String, Double, Double>>()
    private val hands = mutableMapOf<String, NetworkPartnerHand>()

    override val handshakePeers: Flow<List<String>> = peersFlow

    override fun partner(peer: String): NetworkPartnerHand = synchronized(hands) { hands.getOrPut(peer) { NetworkPartnerHand(peer) } }

    override fun sendOwnHand(peer: String, thumbDegrees: Double, middleDegrees: Double) {
        sent += Triple(peer, thumbDegrees, middleDegrees)
    }
}
