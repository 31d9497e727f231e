package org.hapticon.companion.study

import org.hapticon.companion.cli
import org.hapticon.study.ParticipantId
import org.junit.Assert.assertEquals
import org.junit.Test

class ComplianceScheduleCommandTest {
    @Test
    fun schedule_twoParticipants_listsEveryTrialOnce() {
        val result = cli("compliance-schedule", "--participants", "2", "--repetitions", "1")
        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.lines().filter { it.isNotEmpty() }
        assertEquals("participant,trial,condition,grains,shape,electrodes,repetition", lines[0])
        val rows = lines.drop(1).map { it.split(',') }
        assertEquals(40, rows.size)
        val first = rows.filter { it[0] == ParticipantId.of(0) }
        assertEquals((1..20).map { "$it" }, first.map { it[1] })
        assertEquals(20, first.map { it[2] }.toSet().size)
        assertEquals(setOf("0", "9", "19", "39"), first.map { it[3] }.toSet())
        val square = rows.first { it[2] == "g39-large-square" }
        assertEquals(listOf("39", "large_square", "XXX/XXX/XXX", "1"), square.subList(3, 7))
        assertEquals(listOf("compliance-schedule: 2 participants × 20 conditions × 1 repetitions, seed 0"), result.stderrLines)
    }

    @Test
    fun schedule_badCounts_exitTwo() {
        assertEquals(listOf("hapticon: --participants must be a whole number in 1..100000, got '0'"), cli("compliance-schedule", "--participants", "0").stderrLines)
        assertEquals(listOf("hapticon: --repetitions: repetitions must be in 1..20, was 21"), cli("compliance-schedule", "--participants", "1", "--repetitions", "21").stderrLines)
    }
}
