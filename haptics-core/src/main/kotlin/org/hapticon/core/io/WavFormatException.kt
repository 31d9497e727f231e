package org.hapticon.core.io

import java.io.IOException

/** A WAV stream is malformed, truncated, too large, or in a format [WavReader] does not read. */
public class WavFormatException(message: String) : IOException(message)
