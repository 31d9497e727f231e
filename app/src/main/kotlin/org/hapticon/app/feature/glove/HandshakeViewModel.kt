package org.hapticon.app.feature.glove

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.flatMapLatest
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.launchIn
import kotlinx.coroutines.flow.onEach
import kotlinx.coroutines.flow.stateIn
import org.hapticon.app.playback.ContinuousVibration
import org.hapticon.app.playback.VibrationOutput
import org.hapticon.app.sensors.CalibrationStore
import org.hapticon.app.sensors.HandshakeLink
import org.hapticon.app.sensors.NetworkPartnerHand
import org.hapticon.app.sensors.NoHandshakeLink
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.GloveListener
import org.hapticon.sensor.glove.GloveSource
import org.hapticon.sensor.glove.HandRegion
import org.hapticon.sensor.glove.HandPoseSink
import org.hapticon.sensor.glove.HandshakeLoop
import org.hapticon.sensor.glove.NoPartner
import org.hapticon.sensor.glove.PartnerHand

/**
 * The handshake screen's wiring around sensor-bridge's [HandshakeLoop] (which holds the tele-handshake itself:
 * angles, the 30.9° start, the regional pressures, force feedback and the pose stream). This view model only
 * connects it to Android and the screen: the current user's stored calibration, the partner chosen (the
 * simulated one while the toggle is on, or a chat peer's hand arriving through the broker
 * ([setNetworkPartner]), which also receives the wearer's pose), the phone's vibrator (the loop's amplitude
 * through a [ContinuousVibration]: rate-limited to 20 updates/s, each update a 250 ms one-shot so it dies out by
 * itself, capped by the safety limits) and a snapshot for the UI every [refreshMillis]. Samples run on the
 * sensor's reading thread under [lock], as do the UI's snapshots.
 */
@OptIn(ExperimentalCoroutinesApi::class)
class HandshakeViewModel(
    private val glove: GloveSource,
    private val store: CalibrationStore,
    vibration: VibrationOutput,
    private val simulatedPartner: PartnerHand,
    private val clock: () -> Long = System::nanoTime,
    private val refreshMillis: Long = 33,
    private val link: HandshakeLink = NoHandshakeLink,
) : ViewModel() {
    private val lock = Any()
    private val continuous = ContinuousVibration(vibration)
    private val loop = HandshakeLoop(glove.divider, glove.forceFeedback)

    @Volatile private var vibrate = true
    @Volatile private var networkPartner: NetworkPartnerHand? = null

    private val simulated = MutableStateFlow(false)
    private val vibrationOn = MutableStateFlow(true)
    private val forceFeedbackEnabled = MutableStateFlow(true)
    private val networkPeer = MutableStateFlow<String?>(null)
    private val calibrationSource = MutableStateFlow(CalibrationSource(false, false))

    private val listener = GloveListener { thumbVolts, middleVolts, _ -> onSample(thumbVolts, middleVolts, clock()) }
    private val registration = glove.addListener(listener)

    private val ticks: Flow<Unit> = glove.connected.flatMapLatest { if (it) ticker(refreshMillis) else flowOf(Unit) }

    val uiState: StateFlow<HandshakeUiState> =
        combine(
            combine(glove.connected, glove.acceptsForceFeedback, ::Pair),
            simulated,
            combine(vibrationOn, forceFeedbackEnabled, ::Pair),
            combine(store.currentUser, calibrationSource, link.handshakePeers, networkPeer, ::PartnerChoice),
            ticks,
        ) { (connected, feedbackAvailable), sim, (vib, feedbackOn), choice, _ ->
            snapshot(connected, feedbackAvailable, sim, vib, feedbackOn, choice)
        }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), HandshakeUiState.Loading)

    init {
        // The wearer's calibration: reloaded whenever the user changes or a calibration is saved.
        combine(store.currentUser, store.revision, ::Pair).onEach { (user, _) ->
            val thumb = store.load(user, GloveFinger.THUMB)
            val middle = store.load(user, GloveFinger.MIDDLE)
            loop.thumbCalibration = thumb?.calibration ?: FlexCalibration.THUMB_DEFAULT
            loop.middleCalibration = middle?.calibration ?: FlexCalibration.MIDDLE_DEFAULT
            calibrationSource.value = CalibrationSource(thumb != null, middle != null)
        }.launchIn(viewModelScope)
        // Nothing streams: nothing may keep vibrating.
        glove.connected.onEach { if (!it) synchronized(lock) { continuous.stop() } }.launchIn(viewModelScope)
    }

    /** Plays against the simulated partner, or against nobody (an open hand). */
    fun setSimulatedPartner(enabled: Boolean) {
        if (enabled) stopNetwork()
        simulated.value = enabled
        setPartner(if (enabled) simulatedPartner else NoPartner)
    }

    /**
     * Shakes hands with [peer] over the chat's broker: their hand as it arrives, the wearer's sent to them
     * at most every [HandshakeLoop.POSE_INTERVAL_NANOS]; null ends it (an open hand).
     */
    fun setNetworkPartner(peer: String?) {
        if (peer == null) {
            stopNetwork()
            setPartner(NoPartner)
            return
        }
        simulated.value = false
        val hand = link.partner(peer)
        networkPartner = hand
        loop.poseSink = HandPoseSink { thumb, middle -> link.sendOwnHand(peer, thumb, middle) }
        networkPeer.value = peer
        setPartner(hand)
    }

    private fun stopNetwork() {
        networkPartner = null
        loop.poseSink = null
        networkPeer.value = null
    }

    /** Plays against [hand]; the messaging task's network partner comes in here. */
    fun setPartner(hand: PartnerHand) {
        loop.partner = hand
    }

    /** Whether the pressure drives the phone's vibrator. */
    fun setVibration(enabled: Boolean) {
        vibrationOn.value = enabled
        vibrate = enabled
        if (!enabled) synchronized(lock) { continuous.stop() }
    }

    /** Whether a LucidGloves glove on the line gets force-feedback commands; off releases it at once. */
    fun setForceFeedback(enabled: Boolean) {
        forceFeedbackEnabled.value = enabled
        loop.forceFeedbackOn = enabled
        if (!enabled) synchronized(lock) { loop.releaseForceFeedback(clock()) }
    }

    override fun onCleared() {
        registration.close()
        synchronized(lock) {
            continuous.stop()
            // Leaving the screen must not leave the wearer's fingers held.
            loop.releaseForceFeedback(clock())
        }
    }

    private fun onSample(thumbVolts: Double, middleVolts: Double, now: Long) {
        synchronized(lock) {
            val phone = loop.onSample(thumbVolts, middleVolts, now)
            continuous.update(if (vibrate) phone else 0, now)
        }
    }

    private fun snapshot(
        connected: Boolean,
        feedbackAvailable: Boolean,
        sim: Boolean,
        vib: Boolean,
        feedbackOn: Boolean,
        choice: PartnerChoice,
    ): HandshakeUiState.Ready =
        synchronized(lock) {
            val (user, source) = choice.user to choice.source
            HandshakeUiState.Ready(
                connected = connected,
                peers = choice.peers,
                networkPeer = choice.networkPeer,
                networkPartnerLive = networkPartner?.isLive(clock()) ?: false,
                forceFeedbackAvailable = feedbackAvailable,
                forceFeedbackEnabled = feedbackOn,
                forceFeedbackCommands = loop.forceFeedbackCommands,
                servoValues = loop.servoValues().toList(),
                simulatedPartner = sim,
                vibrationEnabled = vib,
                user = user,
                thumbCalibrated = source.thumb,
                middleCalibrated = source.middle,
                selfThumbDegrees = loop.selfThumbDegrees,
                selfMiddleDegrees = loop.selfMiddleDegrees,
                thumbFault = loop.thumbFault,
                middleFault = loop.middleFault,
                partnerThumbDegrees = loop.partnerThumbDegrees,
                partnerMiddleDegrees = loop.partnerMiddleDegrees,
                active = loop.active,
                regions = HandRegion.entries.map { RegionUi(it, loop.pressureVolts(it), loop.amplitude(it)) },
                phoneAmplitude = continuous.currentAmplitude,
                samples = loop.samples,
            )
        }

    private data class CalibrationSource(val thumb: Boolean, val middle: Boolean)

    private data class PartnerChoice(
        val user: String,
        val source: CalibrationSource,
        val peers: List<String>,
        val networkPeer: String?,
    )

    private companion object {
        fun ticker(periodMillis: Long): Flow<Unit> = flow {
            while (true) {
                emit(Unit)
                delay(periodMillis)
            }
        }
    }
}

/** One hand region's interaction pressure (V) and its vibration amplitude (0..255). */
data class RegionUi(val region: HandRegion, val pressureVolts: Double, val amplitude: Int) {
    /** Where the pressure lies in the region's range, 0..1 (0 outside a handshake). */
    val level: Float
        get() = if (pressureVolts <= 0.0) 0f else ((pressureVolts - region.minPressureVolts) / region.pressureRangeVolts).coerceIn(0.0, 1.0).toFloat()
}

/** What the handshake screen shows. */
sealed interface HandshakeUiState {
    data object Loading : HandshakeUiState

    data class Ready(
        val connected: Boolean,
        /** Chat peers one can shake hands with over the network. */
        val peers: List<String>,
        /** The peer shaking hands over the network, or null. */
        val networkPeer: String?,
        /** Whether that peer's hand is arriving (a sample within the last half second). */
        val networkPartnerLive: Boolean,
        /** Whether the glove on the line takes force-feedback commands (LucidGloves). */
        val forceFeedbackAvailable: Boolean,
        val forceFeedbackEnabled: Boolean,
        /** Force-feedback commands sent to the glove so far. */
        val forceFeedbackCommands: Long,
        /** The servo values last sent, thumb … pinky (0 … 1000). */
        val servoValues: List<Int>,
        val simulatedPartner: Boolean,
        val vibrationEnabled: Boolean,
        val user: String,
        val thumbCalibrated: Boolean,
        val middleCalibrated: Boolean,
        val selfThumbDegrees: Double,
        val selfMiddleDegrees: Double,
        val thumbFault: Boolean,
        val middleFault: Boolean,
        val partnerThumbDegrees: Double,
        val partnerMiddleDegrees: Double,
        val active: Boolean,
        val regions: List<RegionUi>,
        /** What the phone's vibrator plays now, 0 when still. */
        val phoneAmplitude: Int,
        val samples: Long,
    ) : HandshakeUiState
}
