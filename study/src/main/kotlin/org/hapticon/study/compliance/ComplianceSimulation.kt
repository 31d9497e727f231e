package org.hapticon.study.compliance

import org.hapticon.study.ParticipantId
import org.hapticon.study.design.SplitMix64
import kotlin.math.ln
import kotlin.math.roundToInt
import kotlin.math.sqrt

/**
 * Simulated participants for Task 1, to exercise the analysis end to end where no real answers exist (`hapticon
 * replicate 003` prints their figures apart from the paper's, as simulated and not comparable). Not a model of the
 * paper's people: each one's felt compliance grows with ln(grains + 1) and with the number of active electrodes, with
 * Gaussian noise, and is answered on the person's own scale (a modulus drawn between 1 and 20) rounded to whole numbers,
 * so answers tie and some near-zero ones come out 0 or negative, as the paper's ratings could (:148, :185).
 */
public object ComplianceSimulation {
    /**
     * The raw answers of [participants] people running [protocol] (its trials in each person's order), reproducible
     * from [seed]. [grainWeight] and [electrodeWeight] set how strongly each factor moves the felt compliance, [noise] the
     * spread of one answer, all on the unit of one modulus.
     */
    public fun answers(
        protocol: ComplianceProtocol = ComplianceStudy.PROTOCOL,
        participants: Int = 12,
        seed: Long = 1L,
        grainWeight: Double = 0.35,
        electrodeWeight: Double = 0.12,
        noise: Double = 0.45,
    ): List<MagnitudeEstimate> {
        require(participants in 2..1000) { "participants must be in 2..1000, was $participants" }
        val random = SplitMix64(SplitMix64.mix(seed))
        return (0 until participants).flatMap { p ->
            val modulus = 1.0 + 19.0 * uniform(random)
            protocol.trials(p).map { trial ->
                val felt = grainWeight * ln(trial.condition.grains + 1.0) + electrodeWeight * trial.condition.mask.pattern.activeCount +
                    noise * gaussian(random) - 0.6
                MagnitudeEstimate(ParticipantId.of(p), trial.repetition, trial.condition, (felt * modulus).roundToInt().toDouble())
            }
        }
    }

    /** A uniform draw in [0, 1) from the top 53 bits. */
    private fun uniform(random: SplitMix64): Double = (random.nextLong() ushr 11) * (1.0 / (1L shl 53))

    /** A standard normal draw (Box–Muller). */
    private fun gaussian(random: SplitMix64): Double {
        val u = 1.0 - uniform(random)
        val v = uniform(random)
        return sqrt(-2.0 * ln(u)) * kotlin.math.cos(2 * Math.PI * v)
    }
}
