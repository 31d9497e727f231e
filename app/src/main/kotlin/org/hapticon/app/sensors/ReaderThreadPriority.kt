package org.hapticon.app.sensors

import android.os.Process
import android.util.Log

/**
 * The sensor reader thread's set-up (sensor-bridge's `SensorReader` `threadSetup`, through `SensorSession`):
 * that thread decodes every sample and decides the vibration grains on it (`GrainEngine` is a frame listener of
 * the session), so a grain is late whenever the thread waits for a CPU. It is raised to
 * [Process.THREAD_PRIORITY_URGENT_AUDIO] (-19), the priority Android gives its most important audio threads,
 * because it has an audio thread's job: a deadline every sample. `Process.setThreadPriority(int)` sets the
 * calling thread's Linux nice value (android.os.Process, "Set the priority of the calling thread, based on
 * Linux priorities"); this runs once, on the reader thread, before its first read, so nothing is added per
 * sample. The constant's own KDoc says applications should not normally take this priority; an app may
 * (AOSP's system/core/rootdir/init.rc: "set RLIMIT_NICE to allow priorities from 19 to -20", `setrlimit nice 40
 * 40`, inherited by every app), and this thread is the one whose deadline the user feels. docs/performance.md,
 * "What the OS adds on a quiet machine".
 */
object ReaderThreadPriority {
    /** The nice value asked for: Android's urgent-audio priority. */
    const val PRIORITY: Int = Process.THREAD_PRIORITY_URGENT_AUDIO

    /**
     * Raises the calling thread (the reader) to [PRIORITY]. A phone that refuses (SecurityException) keeps the
     * thread at its default priority and the stream runs on: a late grain is better than no grains.
     */
    fun applyToCurrentThread() {
        try {
            Process.setThreadPriority(PRIORITY)
        } catch (e: SecurityException) {
            // Once per stream, before the first read: not on the per-sample path.
            Log.w("ReaderThreadPriority", "sensor reader stays at its default priority: ${e.message}")
        }
    }
}
