package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.study.design.Counterbalancing
import org.hapticon.study.design.OrderScheme

/**
 * One condition of the compliance study: [grains] per full press (0 = no grains; bins = grains + 1) rendered on
 * the electrodes of [mask]. [id] is `g<grains>-<mask>`, e.g. `g19-triangle`.
 */
public data class ComplianceCondition(val grains: Int, val mask: ElectrodeMask) {
    init {
        require(grains in GrainSettings.MIN_GRAIN_COUNT..GrainSettings.MAX_GRAIN_COUNT) { "grains must be in 0..99, was $grains" }
    }

    /** `g<grains>-<mask in lower case with - for _>`. */
    public val id: String get() = "g$grains-${mask.name.lowercase().replace('_', '-')}"

    /** The grain settings of this condition over [base]'s range, filter and grain length. */
    public fun grainSettings(base: GrainSettings = GrainSettings()): GrainSettings = base.copy(grainCount = grains)

    /**
     * This condition as the board's SET_GRAINS parameters, sent when its trial starts: [grains] over the board's
     * force [range] (from its device info, [FirmwareForceRange.fromStream]) on [mask]'s electrodes, each at the
     * person's calibrated step in [steps] (electrodes 0..8; the board drives only the mask's members).
     * @throws org.hapticon.sensor.safety.SafetyLimitException for a step outside 0..200 (above 2.7 mA);
     *   IllegalArgumentException for a mask of fewer than 4 electrodes (too weak in the paper's pilot).
     */
    public fun firmwareParams(steps: List<Int>, range: FirmwareForceRange, distribution: BinDistribution = BinDistribution.LINEAR): FirmwareGrainParams =
        FirmwareGrainParams.of(grains, distribution, range, mask.pattern, steps)
}

/** One trial: the [index]-th (0-based) stimulus a participant feels, [condition] for the [repetition]-th time. */
public data class ComplianceTrial(val index: Int, val condition: ComplianceCondition, val repetition: Int)

/**
 * A compliance study with magnitude estimation: the participant presses the sensor under each condition and
 * answers with a positive number for how soft it felt ([MagnitudeEstimation]). Every condition comes [repetitions]
 * times; the whole list of trials is shuffled per participant by [Counterbalancing] ([OrderScheme.RANDOM],
 * [seed]) unless [order] says otherwise.
 */
public data class ComplianceProtocol(
    val id: String,
    val title: String,
    val instructions: String,
    val conditions: List<ComplianceCondition>,
    val repetitions: Int = 1,
    val order: OrderScheme = OrderScheme.RANDOM,
    val seed: Long = 0L,
    val distribution: BinDistribution = BinDistribution.LINEAR,
) {
    init {
        require(conditions.isNotEmpty()) { "a compliance study needs at least one condition" }
        require(conditions.map { it.id }.toSet().size == conditions.size) { "conditions must be distinct" }
        require(repetitions in 1..MAX_REPETITIONS) { "repetitions must be in 1..$MAX_REPETITIONS, was $repetitions" }
        require(order != OrderScheme.FULL || conditions.size * repetitions <= Counterbalancing.MAX_FULL_ITEMS) {
            "full counterbalancing takes at most ${Counterbalancing.MAX_FULL_ITEMS} trials"
        }
    }

    /** The trials of participant [participantIndex] (0-based), in the order they are felt. */
    public fun trials(participantIndex: Int): List<ComplianceTrial> {
        val all = (0 until repetitions).flatMap { r -> conditions.map { it to r } }
        return Counterbalancing.order(order, all.size, participantIndex, seed)
            .mapIndexed { i, k -> ComplianceTrial(i, all[k].first, all[k].second) }
    }

    public companion object {
        /** Most repetitions of each condition. */
        public const val MAX_REPETITIONS: Int = 20
    }
}

/**
 * Shaping Compliance's conditions (the electrotactile compliance illusion, CHI 2024): 0, 9, 19 and 39 grains
 * (10–40 bins; 0 is the no-grain baseline) × its five electrode shapes, 20 conditions, answered by magnitude
 * estimation. The paper's number of repetitions is not restated here (not re-checked): [PROTOCOL] shows each
 * condition 3 times, and a researcher can change it with [ComplianceProtocol.copy].
 */
public object ComplianceStudy {
    /** The protocol id. */
    public const val ID: String = "shaping-compliance"

    /** The grain counts of the study: 0 (no grains), 9, 19, 39. */
    public val GRAINS: List<Int> = listOf(0, 9, 19, 39)

    /** Every condition: each grain count on each electrode shape, grains outermost. */
    public val CONDITIONS: List<ComplianceCondition> = GRAINS.flatMap { g -> ElectrodeMask.entries.map { ComplianceCondition(g, it) } }

    /** The study as a protocol. */
    public val PROTOCOL: ComplianceProtocol = ComplianceProtocol(
        id = ID,
        title = "Electrotactile compliance (magnitude estimation)",
        instructions = "Press the sensor slowly all the way and release. Then type a number for how soft it felt: " +
            "any positive number you like for the first one, then numbers in proportion (twice as soft, twice the number).",
        conditions = CONDITIONS,
        repetitions = 3,
    )
}
