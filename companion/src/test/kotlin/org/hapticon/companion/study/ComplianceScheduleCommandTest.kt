package org.hapticon.companion.study

import org.hapticon.companion.cli
import org.hapticon.study.ParticipantId
import org.junit.Assert.assertEquals
import org.junit.Test

class ComplianceScheduleCommandTest {
    @Test
    fun schedule_published_threeBlocksOfTwelve_calibratedBeforeEach() {
        val result = cli("compliance-schedule", "--participants", "2")
        assertEquals(result.toString(), 0, result.exitCode)
        val lines = result.stdout.lines().filter { it.isNotEmpty() }
        assertEquals("participant,trial,condition,grains,shape,electrodes,repetition,before", lines[0])
        val rows = lines.drop(1).map { it.split(',') }
        assertEquals(72, rows.size)
        val first = rows.filter { it[0] == ParticipantId.of(0) }
        assertEquals((1..36).map { "$it" }, first.map { it[1] })
        assertEquals(setOf("9", "19", "39"), first.map { it[3] }.toSet())
        assertEquals(setOf("large-square", "small-square", "vertical-line", "horizontal-line"), first.map { it[4] }.toSet())
        assertEquals(List(12) { "1" } + List(12) { "2" } + List(12) { "3" }, first.map { it[6] })
        assertEquals(mapOf(0 to "calibrate", 12 to "break+calibrate", 24 to "break+calibrate"), first.withIndex().filter { it.value[7].isNotEmpty() }.associate { it.index to it.value[7] })
        val square = rows.first { it[2] == "g39-large-square" }
        assertEquals(listOf("39", "large-square", "XXX/XXX/XXX"), square.subList(3, 6))
        assertEquals(listOf("compliance-schedule: shaping-compliance: 2 participants × 12 conditions × 3 repetitions (blocks, williams order), seed 0"), result.stderrLines)
    }

    @Test
    fun schedule_extendedAndShapes_areOneListCalibratedOnce() {
        val extended = cli("compliance-schedule", "--participants", "1", "--protocol", "shaping-compliance-extended").stdout.lines().drop(1).filter { it.isNotEmpty() }
        assertEquals(60, extended.size)
        assertEquals(listOf("calibrate"), extended.map { it.split(',')[7] }.filter { it.isNotEmpty() })
        val shapes = cli("compliance-schedule", "--participants", "1", "--protocol", "shaping-compliance-shapes").stdout.lines().drop(1).filter { it.isNotEmpty() }
        assertEquals(15, shapes.size)
        assertEquals(setOf("39"), shapes.map { it.split(',')[3] }.toSet())
    }

    @Test
    fun schedule_badArguments_exitTwo() {
        assertEquals(listOf("hapticon: --participants must be a whole number in 1..100000, got '0'"), cli("compliance-schedule", "--participants", "0").stderrLines)
        assertEquals(listOf("hapticon: --repetitions: repetitions must be in 1..20, was 21"), cli("compliance-schedule", "--participants", "1", "--repetitions", "21").stderrLines)
        assertEquals(
            listOf("hapticon: --protocol must be one of shaping-compliance, shaping-compliance-shapes, shaping-compliance-extended, got 'soft'"),
            cli("compliance-schedule", "--participants", "1", "--protocol", "soft").stderrLines,
        )
    }
}
