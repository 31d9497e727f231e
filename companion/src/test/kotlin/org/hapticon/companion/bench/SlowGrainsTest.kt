package org.hapticon.companion.bench

import org.junit.Assert.assertEquals
import org.junit.Test

class SlowGrainsTest {
    @Test
    fun stealTicks_recordedProcStat_readsTheEighthValueOfThatCpusLine() {
        assertEquals(29425L, ProcStat.stealTicks(PROC_STAT, 0))
        assertEquals(33726L, ProcStat.stealTicks(PROC_STAT, 1))
        // No cpu2 line on this 2-vCPU guest.
        assertEquals(-1L, ProcStat.stealTicks(PROC_STAT, 2))
    }

    @Test
    fun parse_recordedProcStat_fillsTheAggregateAndEveryCpusSteal() {
        val bytes = PROC_STAT.toByteArray()
        val aggregate = LongArray(ProcStat.CPU_FIELDS)
        val steal = LongArray(4) { -1L }
        assertEquals(2, ProcStat.parse(bytes, bytes.size, aggregate, steal))
        assertEquals(listOf(3811715L, 4840, 294629, 773324, 8387, 0, 13265, 63151, 0, 0), aggregate.toList())
        assertEquals(listOf(29425L, 33726, -1, -1), steal.toList())
    }

    @Test
    fun parse_textWithoutCpuLines_isMinusOne() {
        val bytes = "intr 5 0 0\nctxt 66915612\n".toByteArray()
        assertEquals(-1, ProcStat.parse(bytes, bytes.size, LongArray(ProcStat.CPU_FIELDS), LongArray(2)))
    }

    @Test
    fun processor_recordedTaskStat_isField39_evenWithSpacesAndParenthesesInTheName() {
        val cat = TASK_STAT.toByteArray()
        assertEquals(1, ProcStat.processor(cat, cat.size))
        val odd = TASK_STAT.replace("(cat)", "(hapticon (x) y)").toByteArray()
        assertEquals(1, ProcStat.processor(odd, odd.size))
        val short = "7594 (cat) R 7590".toByteArray()
        assertEquals(-1, ProcStat.processor(short, short.size))
    }

    @Test
    fun safepointLog_jdk17Lines_giveEachSafepointsStartAndEnd() {
        val log = """
            [24651943020025ns] Safepoint "ParallelGCSystemGC", Time since last: 80283838 ns, Reaching safepoint: 7114 ns, Cleanup: 54892 ns, At safepoint: 42333331 ns, Total: 42395337 ns
            [24652943020025ns] some other line
            [24653000000000ns] Safepoint "Cleanup", Time since last: 1000000000 ns, Reaching safepoint: 3000 ns, Cleanup: 1000 ns, At safepoint: 150000 ns, Total: 154000 ns
        """.trimIndent()
        assertEquals(
            listOf(
                Safepoint("ParallelGCSystemGC", 24651943020025 - 42395337, 24651943020025),
                Safepoint("Cleanup", 24653000000000 - 154000, 24653000000000),
            ),
            SafepointLog.parse(log),
        )
    }

    @Test
    fun overlapNanos_countsTheGrainsTimeInsideSafepointsOnce() {
        val safepoints = listOf(Safepoint("a", 100, 200), Safepoint("b", 150, 260), Safepoint("c", 400, 500))
        // Grain 120..450: 120..260 (a and b overlap, counted once) + 400..450.
        assertEquals(140L + 50L, SafepointLog.overlapNanos(safepoints, 120, 450))
        assertEquals(0L, SafepointLog.overlapNanos(safepoints, 260, 400))
    }

    @Test
    fun causes_eachGrainByEveryCauseThatExplainsIt_andTheRestUnexplained() {
        val ms = 1_000_000L
        val grains = listOf(
            SlowGrain(3 * ms, 2.5e6, gc = false, safepointNanos = 0, stealTicks = 0), // run queue
            SlowGrain(4 * ms, 0.0, gc = false, safepointNanos = 3_500_000, stealTicks = 0), // safepoint
            SlowGrain(2 * ms, 700_000.0, gc = false, safepointNanos = 600_000, stealTicks = 0), // both together only
            SlowGrain(5 * ms, 0.0, gc = true, safepointNanos = 4_200_000, stealTicks = 0), // a GC, inside a safepoint
            SlowGrain(4 * ms, 0.0, gc = false, safepointNanos = 0, stealTicks = 1), // steal near it
            SlowGrain(4 * ms, 100_000.0, gc = false, safepointNanos = 0, stealTicks = 0), // nothing
            SlowGrain(4 * ms, Double.NaN, gc = false, safepointNanos = -1, stealTicks = -1), // nothing known
        )
        assertEquals(SlowGrainCauses(7, runQueue = 1, safepoint = 2, gc = 1, steal = 1, waitAndSafepoint = 1, unexplained = 2), SlowGrainCauses.of(grains, ms))
        assertEquals(SlowGrainCauses.NONE, SlowGrainCauses.of(emptyList(), ms))
    }

    private companion object {
        // Recorded on this machine (2 vCPUs, KVM), 2026-11-26; the intr line shortened.
        val PROC_STAT = """
            cpu  3811715 4840 294629 773324 8387 0 13265 63151 0 0
            cpu0 1912504 3490 135332 401325 2142 0 527 29425 0 0
            cpu1 1899210 1350 159297 371999 6244 0 12737 33726 0 0
            intr 26932375 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1 16 0 0 0 0 4972 784 0 417 1 3822527 0
            ctxt 66915612
            btime 1795683953
            processes 1141160
            procs_running 11
        """.trimIndent() + "\n"

        val TASK_STAT = "7594 (cat) R 7590 7590 30687 0 -1 4194304 101 0 0 0 0 0 0 0 20 0 1 0 2486374 3133440 381 18446744073709551615 " +
            "94082712494080 94082712513961 140722541958400 0 0 0 0 0 0 0 0 0 17 1 0 0 0 0 0 94082712529968 94082712531584 94082891350016 " +
            "140722541963961 140722541963988 140722541963988 140722541965291 0\n"
    }
}
