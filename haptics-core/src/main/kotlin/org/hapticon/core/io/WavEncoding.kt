package org.hapticon.core.io

/** How WAV samples are stored. */
public enum class WavEncoding(
    /** Bytes per sample of one channel. */
    public val bytesPerSample: Int,
) {
    /** Signed 16-bit little-endian integers (format tag 1, WAVE_FORMAT_PCM). */
    PCM16(2),

    /** 32-bit little-endian IEEE floats, nominally in [-1, 1] (format tag 3, WAVE_FORMAT_IEEE_FLOAT). */
    FLOAT32(4),
}
