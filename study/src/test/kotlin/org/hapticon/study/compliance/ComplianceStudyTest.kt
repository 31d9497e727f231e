package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.study.design.OrderScheme
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Assert.fail
import org.junit.Test

class ComplianceStudyTest {
    @Test
    fun protocol_conditions_areFourGrainCountsTimesFiveShapes() {
        val protocol = ComplianceStudy.PROTOCOL
        assertEquals(20, protocol.conditions.size)
        assertEquals(listOf(0, 9, 19, 39), protocol.conditions.map { it.grains }.distinct())
        assertEquals(ElectrodeMask.entries.toSet(), protocol.conditions.map { it.mask }.toSet())
        assertEquals("g19-triangle", ComplianceCondition(19, ElectrodeMask.TRIANGLE).id)
        assertEquals("g0-large-square", protocol.conditions.first().id)
        // Grains = bins − 1: the 39-grain conditions cut the range into 40 bins.
        assertEquals(40, ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE).grainSettings().binCount)
    }

    @Test
    fun trials_everyConditionEachRepetitionOnce_shuffledPerParticipant() {
        val protocol = ComplianceStudy.PROTOCOL
        val first = protocol.trials(0)
        assertEquals(60, first.size)
        assertEquals((0 until 60).toList(), first.map { it.index })
        assertEquals(protocol.conditions.flatMap { c -> (0..2).map { c to it } }.toSet(), first.map { it.condition to it.repetition }.toSet())
        assertEquals(first, protocol.trials(0))
        assertNotEquals(first, protocol.trials(1))
        val fixed = protocol.copy(order = OrderScheme.FIXED, repetitions = 1).trials(5)
        assertEquals(protocol.conditions, fixed.map { it.condition })
    }

    @Test
    fun protocol_emptyDuplicateOrTooManyRepetitions_isRejected() {
        for (make in listOf(
            { ComplianceStudy.PROTOCOL.copy(conditions = emptyList()) },
            { ComplianceStudy.PROTOCOL.copy(conditions = ComplianceStudy.CONDITIONS + ComplianceStudy.CONDITIONS.first()) },
            { ComplianceStudy.PROTOCOL.copy(repetitions = 0) },
            { ComplianceStudy.PROTOCOL.copy(order = OrderScheme.FULL) },
            { ComplianceCondition(100, ElectrodeMask.TRIANGLE) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun normalize_removesEachParticipantsModulus() {
        // Bob answers exactly ten times Ann's numbers: after normalisation both say the same.
        val raw = listOf(
            MagnitudeEstimate("ann", "a", 1.0), MagnitudeEstimate("ann", "b", 4.0),
            MagnitudeEstimate("bob", "a", 10.0), MagnitudeEstimate("bob", "b", 40.0),
        )
        val normalized = MagnitudeEstimation.normalize(raw).map { it.value }
        // Geometric means: Ann 2, Bob 20, all four (1·4·10·40)^(1/4) = 6.3246; each answer / own mean × grand mean.
        val grand = Math.pow(1.0 * 4 * 10 * 40, 0.25)
        val expected = listOf(0.5 * grand, 2.0 * grand, 0.5 * grand, 2.0 * grand)
        for (i in expected.indices) assertEquals(expected[i], normalized[i], 1e-12)
        val means = MagnitudeEstimation.conditionMeans(raw)
        assertEquals(listOf("a", "b"), means.keys.toList())
        assertEquals(0.5 * grand, means.getValue("a"), 1e-12)
        assertEquals(2.0 * grand, means.getValue("b"), 1e-12)
        assertEquals(emptyList<MagnitudeEstimate>(), MagnitudeEstimation.normalize(emptyList()))
    }

    @Test
    fun estimate_zeroNegativeNanOrInfinite_isRejected() {
        for (bad in listOf(0.0, -1.0, Double.NaN, Double.POSITIVE_INFINITY)) {
            try {
                MagnitudeEstimate("ann", "a", bad)
                fail("accepted $bad")
            } catch (e: IllegalArgumentException) {
                assertEquals("an estimate must be a positive number, was $bad", e.message)
            }
        }
    }
}
