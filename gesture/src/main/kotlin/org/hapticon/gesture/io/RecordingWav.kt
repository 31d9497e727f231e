package org.hapticon.gesture.io

import org.hapticon.core.io.WavFormatException
import org.hapticon.core.io.WavReader
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import java.io.InputStream

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
}
