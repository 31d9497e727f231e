package org.hapticon.app.feature.glove

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import java.util.EnumMap
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.stateIn
import org.hapticon.app.sensors.CalibrationStore
import org.hapticon.app.sensors.SavedCalibration
import org.hapticon.sensor.glove.CalibrationState
import org.hapticon.sensor.glove.DividerReading
import org.hapticon.sensor.glove.FlexCalibrationFlow
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.GloveListener
import org.hapticon.sensor.glove.GloveSource
import org.hapticon.sensor.glove.SensorFault

/**
 * Calibrates the glove's flex sensors, one finger at a time, with sensor-bridge's
 * [FlexCalibrationFlow]: hold 0°, 30°, 50°, 70°, 90°, each until the reading settles, twice round (the
 * tele-handshake paper took each pose twice and averaged), then fit ln R = α·θ + ln β. A fitted result is saved for the current user in [store] at once.
 *
 * Readings arrive on the sensor's reading thread and drive the flow there; the UI sees the flow's
 * state at most every [publishIntervalNanos] (≈ 30 fps), and at once whenever the pose or the
 * outcome changes.
 */
class CalibrationViewModel(
    private val glove: GloveSource,
    private val store: CalibrationStore,
    private val clock: () -> Long = System::nanoTime,
    private val wallClockMillis: () -> Long = System::currentTimeMillis,
    private val publishIntervalNanos: Long = 33_000_000L,
) : ViewModel() {
    private val lock = Any()
    private val flows = EnumMap<GloveFinger, FlexCalibrationFlow>(GloveFinger::class.java).apply {
        for (finger in GloveFinger.entries) put(finger, FlexCalibrationFlow(finger))
    }

    @Volatile private var selected = GloveFinger.THUMB
    private var lastPublish = Long.MIN_VALUE / 2
    private var latest: DividerReading? = null

    private val finger = MutableStateFlow(GloveFinger.THUMB)
    private val flowStates = MutableStateFlow(currentStates())
    private val live = MutableStateFlow(LiveReading(null, null))
    private val userInput = MutableStateFlow(store.currentUser.value)

    private val listener = GloveListener { thumbVolts, middleVolts, _ -> onSample(thumbVolts, middleVolts) }
    private val registration = glove.addListener(listener)

    private val saved = combine(store.currentUser, store.revision) { user, _ ->
        GloveFinger.entries.associateWith { store.load(user, it) }
    }

    val uiState: StateFlow<CalibrationUiState> =
        combine(combine(userInput, store.currentUser, ::Pair), glove.connected, finger, combine(flowStates, live, ::Pair), saved) {
                (input, user), connected, f, (states, reading), savedFits ->
            val flow = flows.getValue(f)
            CalibrationUiState.Ready(
                userInput = input,
                user = user,
                connected = connected,
                finger = f,
                poses = flow.posesDegrees,
                takesPerPose = flow.takesPerPose,
                windowSamples = flow.criterion.windowSamples,
                maxSpreadPercent = flow.criterion.maxRelativeSpread * 100,
                state = states.getValue(f),
                live = reading,
                saved = savedFits,
            )
        }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), CalibrationUiState.Loading)

    /** Edits the participant name; calibrations are kept per name. */
    fun setUser(name: String) {
        userInput.value = name
        store.setCurrentUser(name)
    }

    fun selectFinger(finger: GloveFinger) {
        selected = finger
        this.finger.value = finger
    }

    /** The person holds the pose asked for: start collecting readings. */
    fun beginPose() = act { it.beginPose() }

    /** Drops the current finger's captured poses and starts at 0° again. */
    fun restart() = act { it.restart() }

    override fun onCleared() {
        registration.close()
    }

    private inline fun act(step: (FlexCalibrationFlow) -> Unit) {
        synchronized(lock) {
            step(flows.getValue(selected))
            flowStates.value = currentStates()
        }
    }

    private fun onSample(thumbVolts: Double, middleVolts: Double) {
        val now = clock()
        synchronized(lock) {
            val f = selected
            val reading = glove.divider.resistanceOf(if (f == GloveFinger.THUMB) thumbVolts else middleVolts)
            latest = reading
            val flow = flows.getValue(f)
            val before = flow.state
            val after = flow.offer(reading)
            val milestone = after.javaClass != before.javaClass || poseOf(after) != poseOf(before)
            if (after is CalibrationState.Calibrated && before !is CalibrationState.Calibrated) {
                store.save(store.currentUser.value, f, SavedCalibration.of(after.fit, wallClockMillis()))
            }
            if (milestone || now - lastPublish >= publishIntervalNanos) {
                lastPublish = now
                flowStates.value = currentStates()
                live.value = when (reading) {
                    is DividerReading.Resistance -> LiveReading(reading.kiloohms, null)
                    is DividerReading.Fault -> LiveReading(null, reading.fault)
                }
            }
        }
    }

    private fun currentStates(): Map<GloveFinger, CalibrationState> = flows.mapValues { it.value.state }

    private fun poseOf(state: CalibrationState): Int = when (state) {
        is CalibrationState.WaitingForPose -> state.take * 1000 + state.poseIndex
        is CalibrationState.Settling -> state.take * 1000 + state.poseIndex
        else -> -1
    }
}

/** The selected finger's sensor right now: a resistance in kΩ, or a fault. */
data class LiveReading(val kiloohms: Double?, val fault: SensorFault?)

/** What the calibration screen shows. */
sealed interface CalibrationUiState {
    data object Loading : CalibrationUiState

    data class Ready(
        /** The participant field as typed. */
        val userInput: String,
        /** Whose calibrations are saved and shown. */
        val user: String,
        val connected: Boolean,
        val finger: GloveFinger,
        val poses: List<Double>,
        /** Rounds through [poses]: each pose is taken this many times and averaged. */
        val takesPerPose: Int,
        val windowSamples: Int,
        val maxSpreadPercent: Double,
        /** The selected finger's calibration flow. */
        val state: CalibrationState,
        val live: LiveReading,
        /** What is saved for [user], per finger. */
        val saved: Map<GloveFinger, SavedCalibration?>,
    ) : CalibrationUiState
}
