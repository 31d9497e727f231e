package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.study.design.Counterbalancing
import org.hapticon.study.design.OrderScheme
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class ComplianceStudyTest {
    @Test
    fun published_task1_isThreeGrainLevelsTimesFourShapesTimesThree() {
        // 003_8ca1dc8f53472543.txt:144, :150: 3 grain levels × 4 electrode conditions × 3 repetitions = 36 trials.
        val protocol = ComplianceStudy.PROTOCOL
        assertEquals("shaping-compliance", protocol.id)
        assertEquals(12, protocol.conditions.size)
        assertEquals(listOf(9, 19, 39), protocol.conditions.map { it.grains }.distinct())
        assertEquals(
            listOf(ElectrodeMask.LARGE_SQUARE, ElectrodeMask.SMALL_SQUARE, ElectrodeMask.VERTICAL_LINE, ElectrodeMask.HORIZONTAL_LINE),
            protocol.conditions.map { it.mask }.distinct(),
        )
        assertEquals(3, protocol.repetitions)
        assertEquals(36, protocol.trialCount)
        assertEquals(ComplianceTask.MAGNITUDE, protocol.task)
        assertEquals(40, ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE).grainSettings().binCount)
        assertEquals("g19-triangle", ComplianceCondition(19, ElectrodeMask.TRIANGLE).id)
        assertEquals(ComplianceCondition(19, ElectrodeMask.VERTICAL_LINE), ComplianceCondition.parse("g19-vertical-line"))
        assertNull(ComplianceCondition.parse("g19-circle"))
    }

    @Test
    fun published_trials_areThreeBlocks_eachACounterbalancedOrderOfAllTwelve_calibratedAndBrokenBefore() {
        val protocol = ComplianceStudy.PROTOCOL
        val rows = Counterbalancing.williamsSquare(12)
        val seen = HashSet<List<Int>>()
        for (p in 0 until 12) {
            val trials = protocol.trials(p)
            assertEquals(36, trials.size)
            assertEquals((0 until 36).toList(), trials.map { it.index })
            for (r in 0 until 3) {
                val block = trials.subList(r * 12, r * 12 + 12)
                assertEquals(List(12) { r }, block.map { it.repetition })
                // Every condition once per repetition, in row 3p + r of the Williams square: a different order each time.
                val order = block.map { protocol.conditions.indexOf(it.condition) }
                assertEquals(rows[(3 * p + r) % 12], order)
                seen += order
                // The calibration before each repetition (:152) and a break after each (:150).
                assertEquals(listOf(true) + List(11) { false }, block.map { it.calibrateBefore })
                assertEquals(listOf(r > 0) + List(11) { false }, block.map { it.breakBefore })
            }
        }
        // Twelve participants use each of the square's 12 rows three times.
        assertEquals(rows.toSet(), seen)
    }

    @Test
    fun extended_isOurs_sixtyTrialsInOneShuffledList_calibratedOnce() {
        val protocol = ComplianceStudy.EXTENDED
        assertEquals(20, protocol.conditions.size)
        assertEquals(listOf(0, 9, 19, 39), protocol.conditions.map { it.grains }.distinct())
        assertEquals(ElectrodeMask.entries.toSet(), protocol.conditions.map { it.mask }.toSet())
        val first = protocol.trials(0)
        assertEquals(60, first.size)
        assertEquals(protocol.conditions.flatMap { c -> (0..2).map { c to it } }.toSet(), first.map { it.condition to it.repetition }.toSet())
        assertEquals(listOf(true) + List(59) { false }, first.map { it.calibrateBefore })
        assertTrue(first.none { it.breakBefore })
        // Shuffled as one list: repetitions mix.
        assertNotEquals(first.map { it.repetition }, first.map { it.repetition }.sorted())
        assertEquals(first, protocol.trials(0))
        assertNotEquals(first, protocol.trials(1))
    }

    @Test
    fun shapes_task2_isFiveShapesAt39GrainsTimesThree_randomWithoutBreak() {
        // 003_8ca1dc8f53472543.txt:171, :175.
        val protocol = ComplianceStudy.SHAPES_PROTOCOL
        assertEquals(ComplianceTask.DRAWING, protocol.task)
        assertEquals(ElectrodeMask.entries.toSet(), protocol.conditions.map { it.mask }.toSet())
        assertEquals(setOf(39), protocol.conditions.map { it.grains }.toSet())
        val trials = protocol.trials(3)
        assertEquals(15, trials.size)
        assertEquals(listOf(true) + List(14) { false }, trials.map { it.calibrateBefore })
        assertTrue(trials.none { it.breakBefore })
        assertEquals(ComplianceStudy.SHAPES_PROTOCOL, ComplianceStudy.byId("shaping-compliance-shapes"))
    }

    @Test
    fun protocol_emptyDuplicateTooManyOrCalibrationWithoutBlocks_isRejected() {
        for (make in listOf(
            { ComplianceStudy.PROTOCOL.copy(conditions = emptyList()) },
            { ComplianceStudy.PROTOCOL.copy(conditions = ComplianceStudy.CONDITIONS + ComplianceStudy.CONDITIONS.first()) },
            { ComplianceStudy.PROTOCOL.copy(repetitions = 0) },
            { ComplianceStudy.EXTENDED.copy(order = OrderScheme.FULL) },
            { ComplianceStudy.PROTOCOL.copy(repetitionOrder = RepetitionOrder.SHUFFLED) },
            { ComplianceCondition(100, ElectrodeMask.TRIANGLE) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
        // Full counterbalancing of one 12-trial block is allowed (12 ≤ 20 items); of 36 shuffled trials it is not.
        assertEquals(36, ComplianceStudy.PROTOCOL.copy(order = OrderScheme.FULL).trials(5).size)
    }

    @Test
    fun ratings_signedAnyFiniteNumber_parsedWithEitherDecimalMark() {
        assertEquals(-2.5, MagnitudeEstimation.parse(" -2,5 "))
        assertEquals(0.0, MagnitudeEstimation.parse("0"))
        assertEquals(12.0, MagnitudeEstimation.parse("+12"))
        assertEquals(0.25, MagnitudeEstimation.parse(".25"))
        for (bad in listOf("", "soft", "1.2.3", "NaN", "Infinity", "1e400", "--1")) assertNull(bad, MagnitudeEstimation.parse(bad))
        for (bad in listOf(Double.NaN, Double.POSITIVE_INFINITY)) {
            try {
                MagnitudeEstimate("ann", 0, ComplianceStudy.CONDITIONS[0], bad)
                fail("accepted $bad")
            } catch (e: IllegalArgumentException) {
                assertEquals("a rating must be a finite number, was $bad", e.message)
            }
        }
    }

    @Test
    fun standardize_dividesByEachParticipantsRepetitionSd_keepingZeroAtZero() {
        val c = ComplianceStudy.CONDITIONS
        // Ann's repetition 0: 0, 2, 4 (sd 2); repetition 1: −1, 1, 3 (sd 2); Bob answers ten times larger (sd 20).
        val raw = listOf(
            MagnitudeEstimate("ann", 0, c[0], 0.0), MagnitudeEstimate("ann", 0, c[1], 2.0), MagnitudeEstimate("ann", 0, c[2], 4.0),
            MagnitudeEstimate("ann", 1, c[0], -1.0), MagnitudeEstimate("ann", 1, c[1], 1.0), MagnitudeEstimate("ann", 1, c[2], 3.0),
            MagnitudeEstimate("bob", 0, c[0], 0.0), MagnitudeEstimate("bob", 0, c[1], 20.0), MagnitudeEstimate("bob", 0, c[2], 40.0),
        )
        val scores = MagnitudeEstimation.standardize(raw).map { it.value }
        assertEquals(listOf(0.0, 1.0, 2.0, -0.5, 0.5, 1.5, 0.0, 1.0, 2.0), scores)
        assertEquals(emptyList<MagnitudeEstimate>(), MagnitudeEstimation.standardize(emptyList()))
        val flat = raw.take(3).map { it.copy(value = 5.0) }
        try {
            MagnitudeEstimation.standardize(flat)
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertEquals("ann, repetition 1: every answer is 5.0, so there is no scale to divide by", e.message)
        }
    }

    @Test
    fun analysis_addsTheReferenceRows_andReportsThePapersThreeAnalyses() {
        val answers = ComplianceSimulation.answers(participants = 6, seed = 3)
        val scores = MagnitudeEstimation.standardize(answers)
        // Grains × electrode: 36 answers + 12 reference rows per participant (one per repetition and shape).
        val two = ComplianceAnalysis.grainsByShapeData(scores)
        assertEquals(6 * 48, two.size)
        assertEquals(6 * 12, two.count { it.levels[0] == "0" && it.value == 0.0 })
        // Number of electrodes: one reference row per participant, repetition and grain level, as many as the small square's.
        val count = ComplianceAnalysis.electrodeCountData(scores)
        assertEquals(mapOf("0" to 54, "4" to 54, "6" to 108, "9" to 54), count.groupingBy { it.levels[0] }.eachCount())
        assertEquals(6 * 18, ComplianceAnalysis.orientationData(scores).size)

        val result = ComplianceAnalysis.run(answers)
        assertEquals(6, result.participants)
        assertEquals(listOf("grains", "electrode", "grains:electrode"), result.grainsByShape.map { it.effect })
        assertEquals(listOf(3, 3, 9), result.grainsByShape.map { it.dfEffect })
        // Within-subject residual df: 288 rows − 6 subjects − 15 effect df.
        assertEquals(267, result.grainsByShape[0].dfError)
        assertEquals(listOf("0-9", "0-19", "0-39", "9-19", "9-39", "19-39"), result.grainContrasts.map { "${it.first}-${it.second}" })
        assertEquals(listOf("0-4", "0-6", "0-9", "4-6", "4-9", "6-9"), result.electrodeContrasts.map { "${it.first}-${it.second}" })
        assertEquals(1, result.orientation.dfEffect)
        assertEquals(16, result.cells.size)
        assertEquals(0.0, result.cells.first { it.grains == 0 }.median, 0.0)
        assertEquals(0, result.leftOut)
        assertEquals(6 * 60 - 6 * 36, ComplianceAnalysis.run(ComplianceSimulation.answers(ComplianceStudy.EXTENDED, participants = 6, seed = 3)).leftOut)
    }

    @Test
    fun analysis_incompleteSession_isRefusedNamingTheCell() {
        val answers = ComplianceSimulation.answers(participants = 3, seed = 2)
        val missing = answers.filterNot { it.participant == answers.last().participant && it.condition == ComplianceStudy.CONDITIONS[5] && it.repetition == 1 }
        try {
            ComplianceAnalysis.run(missing)
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertTrue(e.message, e.message!!.contains("every subject needs the same number in every cell"))
        }
        assertFalse(missing.size == answers.size)
    }
}
