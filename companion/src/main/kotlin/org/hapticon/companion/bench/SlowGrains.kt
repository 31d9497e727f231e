package org.hapticon.companion.bench

/**
 * Linux's `/proc/stat` CPU lines and a task's `/proc/<pid>/task/<tid>/stat`, parsed from bytes without
 * allocating (the bench reads them between samples). proc(5): each `cpuN` line holds user, nice, system, idle,
 * iowait, irq, softirq, **steal**, guest, guest_nice, in USER_HZ ticks (1/100 s: 10 ms resolution, though the
 * kernel accumulates them in nanoseconds); steal is "stolen time, which is the time spent in other operating
 * systems when running in a virtualized environment" — on this KVM guest, time the hypervisor ran something else
 * on the vCPU. A task's stat field 39, "processor", is the CPU it last ran on.
 */
object ProcStat {
    /** Index of steal among a cpu line's values (the 8th). */
    const val STEAL: Int = 7

    /** Values a cpu line has on current kernels. */
    const val CPU_FIELDS: Int = 10

    /**
     * Parses every `cpu` line of `/proc/stat` text ([length] bytes of [text]): the aggregate line's values into
     * [aggregate] (up to its size), and each `cpuN` line's steal into [stealPerCpu]`[N]` (CPUs beyond its size
     * are skipped). Returns the number of `cpuN` lines seen, -1 if there was no aggregate line.
     */
    fun parse(text: ByteArray, length: Int, aggregate: LongArray, stealPerCpu: LongArray): Int {
        var cpus = 0
        var sawAggregate = false
        var k = 0
        while (k < length) {
            // Each line: "cpu" [N] then space-separated numbers; other lines (intr, ctxt, ...) are skipped.
            if (k + 3 <= length && text[k] == 'c'.code.toByte() && text[k + 1] == 'p'.code.toByte() && text[k + 2] == 'u'.code.toByte()) {
                k += 3
                var cpu = -1
                if (k < length && isDigit(text[k])) {
                    cpu = 0
                    while (k < length && isDigit(text[k])) cpu = cpu * 10 + (text[k++] - '0'.code.toByte())
                }
                var field = 0
                while (k < length && text[k] != '\n'.code.toByte()) {
                    while (k < length && text[k] == ' '.code.toByte()) k++
                    if (k >= length || !isDigit(text[k])) break
                    var value = 0L
                    while (k < length && isDigit(text[k])) value = value * 10 + (text[k++] - '0'.code.toByte())
                    if (cpu < 0) {
                        if (field < aggregate.size) aggregate[field] = value
                    } else if (field == STEAL && cpu < stealPerCpu.size) {
                        stealPerCpu[cpu] = value
                    }
                    field++
                }
                if (cpu < 0) sawAggregate = true else cpus++
            }
            while (k < length && text[k] != '\n'.code.toByte()) k++
            k++
        }
        return if (sawAggregate) cpus else -1
    }

    /** Steal ticks of [cpu] in `/proc/stat` [text], or -1 when it has no such line. */
    fun stealTicks(text: String, cpu: Int): Long {
        require(cpu >= 0) { "cpu must not be negative, was $cpu" }
        val bytes = text.toByteArray(Charsets.US_ASCII)
        val steal = LongArray(cpu + 1) { -1L }
        parse(bytes, bytes.size, LongArray(CPU_FIELDS), steal)
        return steal[cpu]
    }

    /**
     * Field 39 ("processor") of a task's stat text, or -1 if it has fewer fields. Counted after the command
     * name's closing parenthesis (field 2 may hold spaces and parentheses itself), so field 3 is the first there.
     */
    fun processor(text: ByteArray, length: Int): Int {
        var close = -1
        for (k in 0 until length) if (text[k] == ')'.code.toByte()) close = k
        if (close < 0) return -1
        var field = 2
        var k = close + 1
        while (k < length) {
            while (k < length && (text[k] == ' '.code.toByte() || text[k] == '\n'.code.toByte())) k++
            if (k >= length) return -1
            field++
            if (field == PROCESSOR_FIELD) {
                var value = 0
                if (!isDigit(text[k])) return -1
                while (k < length && isDigit(text[k])) value = value * 10 + (text[k++] - '0'.code.toByte())
                return value
            }
            while (k < length && text[k] != ' '.code.toByte() && text[k] != '\n'.code.toByte()) k++
        }
        return -1
    }

    private const val PROCESSOR_FIELD = 39

    private fun isDigit(b: Byte): Boolean = b >= '0'.code.toByte() && b <= '9'.code.toByte()
}

/** One JVM safepoint: every Java thread was stopped (or held from running Java code) from [startNanos] to [endNanos] (System.nanoTime). */
data class Safepoint(val operation: String, val startNanos: Long, val endNanos: Long)

/**
 * HotSpot's `-Xlog:safepoint` lines, written with the `timenanos` decorator (the log's [tn] is
 * `os::javaTimeNanos()`, the clock behind System.nanoTime). JDK 17's `SafepointTracing::end()`
 * (src/hotspot/share/runtime/safepoint.cpp) takes the end time and then logs
 * `Safepoint "NAME", Time since last: N ns, Reaching safepoint: N ns, Cleanup: N ns, At safepoint: N ns, Total: N ns`,
 * Total being end minus begin: so a safepoint ran from (the line's time − Total) to about the line's time.
 */
object SafepointLog {
    private val LINE = Regex("""^\[(\d+)ns]\s+Safepoint "([^"]*)".*\bTotal: (\d+) ns""")

    /** The safepoints in [log] in their order; lines that are not safepoint lines are skipped. */
    fun parse(log: String): List<Safepoint> = log.lineSequence().mapNotNull { line ->
        LINE.find(line)?.let { m ->
            val end = m.groupValues[1].toLong()
            Safepoint(m.groupValues[2], end - m.groupValues[3].toLong(), end)
        }
    }.toList()

    /** Nanoseconds of [from]..[to] during which a safepoint in [safepoints] was in progress (overlaps counted once). */
    fun overlapNanos(safepoints: List<Safepoint>, from: Long, to: Long): Long {
        var covered = 0L
        var reached = from
        for (s in safepoints.sortedBy { it.startNanos }) {
            val start = maxOf(s.startNanos, reached)
            val end = minOf(s.endNanos, to)
            if (end > start) {
                covered += end - start
                reached = end
            }
        }
        return covered
    }
}

/**
 * What was measured about one grain that took longer than the limit: its [latencyNanos], the reader's
 * [runQueueNanos] (runnable, waiting for a CPU; NaN unknown), whether a [gc] ran, [safepointNanos] of the grain
 * inside a JVM safepoint (-1 unknown) and [stealTicks], the hypervisor's steal on the reader's CPU in a window
 * around the grain (USER_HZ ticks of 10 ms; -1 unknown).
 */
data class SlowGrain(
    val latencyNanos: Long,
    val runQueueNanos: Double,
    val gc: Boolean,
    val safepointNanos: Long,
    val stealTicks: Long,
)

/**
 * How many slow grains each cause explains. A grain may count under several causes; [unexplained] counts those
 * no cause explains. [waitAndSafepoint] counts grains that neither the run-queue wait nor the safepoint explains
 * alone but the two together do.
 */
data class SlowGrainCauses(
    val grains: Int,
    val runQueue: Int,
    val safepoint: Int,
    val gc: Int,
    val steal: Int,
    val waitAndSafepoint: Int,
    val unexplained: Int,
) {
    /** Sorts slow grains by cause. */
    companion object {
        /** No slow grain. */
        val NONE: SlowGrainCauses = SlowGrainCauses(0, 0, 0, 0, 0, 0, 0)

        /**
         * A cause explains a grain when the grain, without that time, would have been within [limitNanos]: its
         * run-queue wait or its time inside a safepoint (or both together). A GC explains it when one ran during it
         * (a collection is a safepoint, so its time is in the safepoint figure too when the log is on). Steal
         * explains it when the reader CPU's steal counter moved in the window around the grain — a 10 ms tick
         * says steal happened near the grain, not that it hit the grain, and steal shorter than a tick may not move
         * it at all: an upper and a lower bound at once, as honest as /proc/stat allows.
         */
        fun of(grains: List<SlowGrain>, limitNanos: Long): SlowGrainCauses {
            var runQueue = 0
            var safepoint = 0
            var gc = 0
            var steal = 0
            var together = 0
            var unexplained = 0
            for (g in grains) {
                val wait = if (g.runQueueNanos.isNaN()) 0.0 else g.runQueueNanos
                val stopped = g.safepointNanos.coerceAtLeast(0L).toDouble()
                val byWait = !g.runQueueNanos.isNaN() && g.latencyNanos - wait <= limitNanos
                val bySafepoint = g.safepointNanos >= 0 && g.latencyNanos - stopped <= limitNanos
                val byBoth = !byWait && !bySafepoint && g.latencyNanos - wait - stopped <= limitNanos && (wait > 0 && stopped > 0)
                val bySteal = g.stealTicks > 0
                if (byWait) runQueue++
                if (bySafepoint) safepoint++
                if (g.gc) gc++
                if (bySteal) steal++
                if (byBoth) together++
                if (!byWait && !bySafepoint && !byBoth && !g.gc && !bySteal) unexplained++
            }
            return SlowGrainCauses(grains.size, runQueue, safepoint, gc, steal, together, unexplained)
        }
    }
}
