package org.hapticon.sensor.protocol.stream

/**
 * A push-style decoder: bytes go in through [feed] in chunks of any size, and complete frames go out
 * to the decoder's listener synchronously, on the calling thread, before [feed] returns. Splitting
 * the same bytes differently gives the same frames.
 *
 * Decoders never throw on bad input and never block: garbage, broken frames and overlong input are
 * skipped and counted in [stats]. Buffers are bounded and allocated once, so feeding does not
 * allocate in steady state. Not thread-safe: feed from one thread at a time.
 */
public interface StreamDecoder {
    /** What this decoder has seen so far. */
    public val stats: StreamStats

    /**
     * Decodes [length] bytes of [bytes] from [offset], delivering every frame they complete.
     * @throws IndexOutOfBoundsException if the range falls outside [bytes].
     */
    public fun feed(bytes: ByteArray, offset: Int = 0, length: Int = bytes.size - offset)

    /**
     * Ends the stream (end of a recording, unplug, port closed): an unfinished frame is counted as
     * [FrameError.TRUNCATED] and its bytes as dropped. The decoder then starts afresh, as if just
     * created, except that [stats] keep counting.
     */
    public fun finish()
}
