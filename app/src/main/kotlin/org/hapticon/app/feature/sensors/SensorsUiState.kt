package org.hapticon.app.feature.sensors

import androidx.compose.runtime.Immutable
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.PlotSource
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.live.StreamCounters
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.SensorProtocols

/** What the Sensors screen shows. */
sealed interface SensorsUiState {
    data object Loading : SensorsUiState

    /** The phone cannot host USB devices: nothing can be plugged in. */
    data object NoUsbHost : SensorsUiState

    data class Ready(
        val devices: List<SensorDevice>,
        /** The board Connect opens: the user's choice, else the first one. */
        val selectedDeviceId: String?,
        val protocol: SensorProtocol,
        val baudRate: Int,
        val connection: SessionState,
        val canConnect: Boolean,
        val canDisconnect: Boolean,
        /** What the last stream gave; kept after it stops. Null before any byte arrived. */
        val stream: StreamUi?,
        val grains: GrainUi,
        val glove: GloveUi,
        /** The protocols the user may choose from ([SensorProtocols.DEFAULT] in the app). */
        val protocols: List<SensorProtocol> = SensorProtocols.DEFAULT.entries,
    ) : SensorsUiState
}

/** The live (or last) stream. */
@Immutable
data class StreamUi(
    /** The board's own description (framed protocol's device info). */
    val deviceDescription: String?,
    val channels: List<ChannelUi>,
    val counters: StreamCounters,
    val measuredRateHz: Double?,
    /** Samples received; the plots redraw when it changes. */
    val samples: Long,
    /** Where the plots read their points (the stream's ring buffer; read-only here). */
    val plot: PlotSource,
    /** A sensor output (grains, glove) that failed and was stopped. */
    val outputError: String?,
)

data class ChannelUi(val index: Int, val name: String, val valueText: String, val plotted: Boolean)

/** The FSR grain mode's controls and what it did. */
data class GrainUi(
    val enabled: Boolean,
    val channel: Int,
    val channelNames: List<String>,
    /** Null: automatic (from the channel's unit, else FSR ADC counts). */
    val input: ForceInput?,
    val count: Int,
    val distribution: BinDistribution,
    val amplitude: Int,
    val fallbackSampleRateHz: Int,
    /** The rate the board announced (framed protocol), used instead of [fallbackSampleRateHz]. */
    val deviceSampleRateHz: Int?,
    val grainsPlayed: Long,
    val error: String?,
)

/** Which channels carry the glove's thumb and middle finger. */
data class GloveUi(
    val thumbChannel: Int,
    val middleChannel: Int,
    val adcBits: Int,
    val adcBitsFromDevice: Int?,
    val channelNames: List<String>,
)
