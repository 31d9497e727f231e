package org.hapticon.app.feature.sensors

import androidx.lifecycle.ViewModel
import androidx.lifecycle.viewModelScope
import java.util.Locale
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.Job
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.SharingStarted
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.combine
import kotlinx.coroutines.flow.flatMapLatest
import kotlinx.coroutines.flow.flow
import kotlinx.coroutines.flow.flowOf
import kotlinx.coroutines.flow.stateIn
import kotlinx.coroutines.launch
import org.hapticon.sensor.glove.GloveChannels
import org.hapticon.sensor.glove.SessionGloveSource
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.grains.GrainConfig
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.grains.GrainStatus
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.live.StreamSnapshot
import org.hapticon.sensor.live.UsbDevices
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.SensorProtocols
import org.hapticon.sensor.protocol.framed.ChannelUnit

/**
 * The Sensors screen: plugged-in boards, connecting with a protocol and baud rate, the live stream
 * (values, plots, counters) and the FSR grain mode's controls.
 *
 * While a stream runs, the UI state is refreshed every [refreshMillis] (default 33 ms, ≤ 30 fps) from
 * the session's snapshot, however fast the board sends; between refreshes nothing reaches the UI.
 */
@OptIn(ExperimentalCoroutinesApi::class)
class SensorsViewModel(
    private val usb: UsbDevices,
    private val session: SensorSession,
    private val grains: GrainEngine,
    private val glove: SessionGloveSource,
    private val refreshMillis: Long = DEFAULT_REFRESH_MILLIS,
    /** The protocols offered, in order; the first is chosen until the user picks another. */
    private val protocols: SensorProtocols = SensorProtocols.DEFAULT,
) : ViewModel() {
    private val selection = MutableStateFlow(Selection(protocol = protocols.entries.first()))
    private val grainControls = MutableStateFlow(GrainControls())
    private var connectJob: Job? = null

    private val ticks: Flow<Unit> = session.state.flatMapLatest { state ->
        if (state is SessionState.Streaming) ticker(refreshMillis) else flowOf(Unit)
    }

    private val controls: Flow<Controls> =
        combine(grainControls, grains.status, glove.channels, session.listenerError) { g, status, channels, error ->
            Controls(g, status, channels, error)
        }

    val uiState: StateFlow<SensorsUiState> =
        if (!usb.hasUsbHost) {
            MutableStateFlow(SensorsUiState.NoUsbHost)
        } else {
            combine(usb.devices, selection, session.state, controls, ticks) { devices, sel, connection, ctl, _ ->
                buildState(devices, sel, connection, ctl, session.snapshot())
            }.stateIn(viewModelScope, SharingStarted.WhileSubscribed(5_000), SensorsUiState.Loading)
        }

    fun selectDevice(id: String) = selection.update { it.copy(deviceId = id) }

    fun selectProtocol(protocol: SensorProtocol) = selection.update { it.copy(protocol = protocol) }

    fun selectBaudRate(baudRate: Int) = selection.update { it.copy(baudRate = baudRate) }

    /** Connects to the selected board (asking for USB permission if needed). */
    fun connect() {
        val devices = usb.currentDevices()
        val device = devices.firstOrNull { it.id == selection.value.deviceId } ?: devices.firstOrNull() ?: return
        val sel = selection.value
        connectJob?.cancel()
        connectJob = viewModelScope.launch { session.connect(device, sel.protocol, sel.baudRate) }
    }

    /** Stops the stream; what was received stays on screen. */
    fun disconnect() {
        connectJob?.cancel()
        session.disconnect()
    }

    fun setGrainsEnabled(enabled: Boolean) = updateGrains { it.copy(enabled = enabled) }

    fun setGrainChannel(channel: Int) = updateGrains { it.copy(channel = channel) }

    /** [input] null: from the channel's unit (framed), else FSR ADC counts. */
    fun setForceInput(input: ForceInput?) = updateGrains { it.copy(input = input) }

    fun setGrainCount(count: Int) =
        updateGrains { it.copy(count = count.coerceIn(GrainSettings.STUDY_MIN_GRAIN_COUNT, GrainSettings.STUDY_MAX_GRAIN_COUNT)) }

    fun setDistribution(distribution: BinDistribution) = updateGrains { it.copy(distribution = distribution) }

    /** Burst strength, clamped to the vibrator's 1..255. */
    fun setGrainAmplitude(amplitude: Int) = updateGrains { it.copy(amplitude = amplitude.coerceIn(1, 255)) }

    fun setFallbackSampleRate(hz: Int) = updateGrains { it.copy(fallbackSampleRateHz = hz) }

    fun setGloveChannels(channels: GloveChannels) = glove.setChannels(channels)

    override fun onCleared() {
        grains.configure(null)
        session.disconnect()
    }

    private inline fun MutableStateFlow<Selection>.update(change: (Selection) -> Selection) {
        value = change(value)
    }

    private fun updateGrains(change: (GrainControls) -> GrainControls) {
        val next = change(grainControls.value)
        grainControls.value = next
        grains.configure(next.toConfig())
    }

    private fun buildState(
        devices: List<SensorDevice>,
        sel: Selection,
        connection: SessionState,
        ctl: Controls,
        snapshot: StreamSnapshot,
    ): SensorsUiState.Ready {
        val selectedId = sel.deviceId?.takeIf { id -> devices.any { it.id == id } } ?: devices.firstOrNull()?.id
        val info = snapshot.info
        val busy = connection is SessionState.RequestingPermission || connection is SessionState.Opening ||
            connection is SessionState.Streaming
        return SensorsUiState.Ready(
            devices = devices,
            selectedDeviceId = selectedId,
            protocol = sel.protocol,
            protocols = protocols.entries,
            baudRate = sel.baudRate,
            connection = connection,
            canConnect = selectedId != null && !busy,
            canDisconnect = busy,
            stream = if (info == null && snapshot.counters.bytes == 0L) null else streamUi(info, snapshot, ctl.listenerError),
            grains = grainUi(ctl.grains, ctl.grainStatus, info),
            glove = gloveUi(ctl.gloveChannels, info),
        )
    }

    private fun streamUi(info: StreamInfo?, snapshot: StreamSnapshot, listenerError: String?): StreamUi {
        val names = info?.channelNames.orEmpty()
        val channels = snapshot.latest.mapIndexed { c, value ->
            ChannelUi(
                index = c,
                name = names.getOrElse(c) { "ch$c" },
                valueText = formatValue(value, info?.channelUnits?.getOrNull(c)),
                plotted = c < session.history.maxChannels,
            )
        }
        return StreamUi(
            deviceDescription = info?.deviceDescription,
            channels = channels,
            counters = snapshot.counters,
            measuredRateHz = snapshot.measuredRateHz,
            samples = snapshot.samples,
            plot = session.history,
            outputError = listenerError,
        )
    }

    private fun grainUi(g: GrainControls, status: GrainStatus, info: StreamInfo?): GrainUi = GrainUi(
        enabled = g.enabled,
        channel = g.channel,
        channelNames = info?.channelNames.orEmpty(),
        input = g.input,
        count = g.count,
        distribution = g.distribution,
        amplitude = g.amplitude,
        fallbackSampleRateHz = g.fallbackSampleRateHz,
        deviceSampleRateHz = info?.sampleRateHz,
        // Sampled on each refresh (a volatile read): the engine pushes no status per grain, so the grain path stays lock-free.
        grainsPlayed = grains.grainsPlayed,
        error = status.error,
    )

    private fun gloveUi(channels: GloveChannels, info: StreamInfo?): GloveUi {
        val protocol = info?.protocol ?: selection.value.protocol
        return GloveUi(
            thumbChannel = channels.thumbFor(protocol),
            middleChannel = channels.middleFor(protocol),
            adcBits = info?.let { channels.adcBitsFor(it) } ?: channels.adcBits ?: protocol.assumedAdcBits,
            adcBitsFromDevice = info?.adcBits,
            channelNames = info?.channelNames.orEmpty(),
        )
    }

    private data class Selection(
        val deviceId: String? = null,
        val protocol: SensorProtocol,
        val baudRate: Int = 115_200,
    )

    private data class Controls(
        val grains: GrainControls,
        val grainStatus: GrainStatus,
        val gloveChannels: GloveChannels,
        val listenerError: String?,
    )

    private data class GrainControls(
        val enabled: Boolean = false,
        val channel: Int = 0,
        val input: ForceInput? = null,
        val count: Int = GrainSettings.DEFAULT_GRAIN_COUNT,
        val distribution: BinDistribution = BinDistribution.LINEAR,
        val amplitude: Int = 255,
        val fallbackSampleRateHz: Int = 100,
    ) {
        fun toConfig(): GrainConfig? = if (!enabled) null else GrainConfig(
            channel = channel,
            input = input,
            settings = GrainSettings(grainCount = count, distribution = distribution),
            amplitude = amplitude,
            fallbackSampleRateHz = fallbackSampleRateHz.toDouble(),
        )
    }

    companion object {
        /** ≈ 30 fps. */
        const val DEFAULT_REFRESH_MILLIS: Long = 33

        private fun ticker(periodMillis: Long): Flow<Unit> = flow {
            while (true) {
                emit(Unit)
                delay(periodMillis)
            }
        }

        /** A channel value with its unit: counts as integers, framed units converted for reading. */
        fun formatValue(value: Double, unit: ChannelUnit?): String = when (unit) {
            ChannelUnit.CENTIDEGREE -> "%.2f°".format(Locale.ROOT, value / 100)
            ChannelUnit.MILLIVOLT -> "${plain(value)} mV"
            ChannelUnit.GRAM -> "${plain(value)} g"
            ChannelUnit.MILLINEWTON -> "${plain(value)} mN"
            else -> plain(value)
        }

        private fun plain(value: Double): String =
            if (value == Math.rint(value) && kotlin.math.abs(value) < 1e15) value.toLong().toString() else "%.3f".format(Locale.ROOT, value)
    }
}
