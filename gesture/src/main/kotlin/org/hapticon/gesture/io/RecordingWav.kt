package org.hapticon.gesture.io

import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavFormatException
import org.hapticon.core.io.WavReader
import org.hapticon.core.io.WavWriter
import org.hapticon.core.render.FloatArraySampleStream
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import java.io.InputStream
import java.io.OutputStream

/** Reads a vibration-sensor WAV (PCM16 or float, via haptics-core [WavReader]) as a one-channel [Recording]. */
public object RecordingWav {
    /** Name of the channel a WAV becomes. */
    public const val CHANNEL_NAME: String = "vibration"

    /**
     * Reads the WAV in [input]: mono, or the first (left) channel of a stereo file, as channel
     * [CHANNEL_NAME] with unit "" (samples in [-1, 1] full scale). Throws [RecordingFormatException] (with
     * [source] in the message) for anything [WavReader] rejects, including more than [maxSamples] samples.
     */
    public fun read(input: InputStream, source: String = "recording.wav", maxSamples: Int = WavReader.DEFAULT_MAX_SAMPLES): Recording {
        val audio = try {
            WavReader.read(input, maxSamples)
        } catch (e: WavFormatException) {
            throw RecordingFormatException("$source: ${e.message}")
        }
        val first = audio.channel(0)
        val samples = DoubleArray(first.size) { first[it].toDouble() }
        return Recording(audio.sampleRate.toDouble(), listOf(Channel(CHANNEL_NAME, "", samples)))
    }

    /**
     * Writes channel [channelName] (default: the first) of [recording] to [out] as a mono WAV via haptics-core
     * [WavWriter]. The sample rate must be a whole number of Hz; samples should be in [-1, 1] (PCM16 clips
     * beyond). Throws [IllegalArgumentException] for a missing channel, a fractional rate or a non-finite sample.
     */
    public fun write(recording: Recording, out: OutputStream, channelName: String? = null, encoding: WavEncoding = WavEncoding.PCM16) {
        val channel = recording.requireChannel(channelName)
        val rate = recording.sampleRate
        require(rate == Math.rint(rate) && rate <= Int.MAX_VALUE) { "a WAV needs a whole number of Hz, the recording has $rate" }
        val samples = channel.toDoubleArray()
        val bad = samples.indexOfFirst { !it.isFinite() }
        require(bad < 0) { "channel ${channel.name} has a non-finite sample at index $bad" }
        WavWriter.write(FloatArraySampleStream(FloatArray(samples.size) { samples[it].toFloat() }, rate.toInt()), out, encoding)
    }
}
