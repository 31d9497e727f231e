package org.hapticon.app

import android.os.StrictMode

/**
 * What the main thread must not do: disk reads and writes, network, and rendering an icon (the
 * players mark rendering with `StrictMode.noteSlowCall`, see `noteRendering` in playback). The debug build
 * sets this with `penaltyLog()` ([HapticonApplication]); `MainThreadStrictModeTest` sets it with a listener that
 * fails the test while it drives the chat list, a conversation and icon presses. Room already refuses blocking
 * queries on the main thread by itself.
 */
fun mainThreadPolicy(): StrictMode.ThreadPolicy.Builder =
    StrictMode.ThreadPolicy.Builder().detectDiskReads().detectDiskWrites().detectNetwork().detectCustomSlowCalls()
