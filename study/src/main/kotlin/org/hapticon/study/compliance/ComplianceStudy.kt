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
    public val id: String get() = "g$grains-${shapeName(mask)}"

    /** The grain settings of this condition over [base]'s range, filter and grain length. */
    public fun grainSettings(base: GrainSettings = GrainSettings()): GrainSettings = base.copy(grainCount = grains)

    /**
     * This condition as the board's SET_GRAINS parameters, sent when its trial starts: [grains] over the board's
     * force [range] (from its device info, [FirmwareForceRange.fromStream]) on [mask]'s electrodes, each at the
     * person's calibrated step in [steps] (electrodes 0..8; the board drives only the mask's members), with the dead
     * time of the grain's own delivery (no grain while one is delivered, 003_8ca1dc8f53472543.txt:97).
     * @throws org.hapticon.sensor.safety.SafetyLimitException for a step outside 0..200 (above 2.7 mA);
     *   IllegalArgumentException for a mask of fewer than 4 electrodes (too weak in the paper's pilot).
     */
    public fun firmwareParams(steps: List<Int>, range: FirmwareForceRange, distribution: BinDistribution = BinDistribution.LINEAR): FirmwareGrainParams =
        FirmwareGrainParams.of(grains, distribution, range, mask.pattern, steps)

    public companion object {
        /** The shape's name in ids and files: `large-square`, `small-square`, `vertical-line`, `horizontal-line`, `triangle`. */
        public fun shapeName(mask: ElectrodeMask): String = mask.name.lowercase().replace('_', '-')

        /** The condition with [id] (`g<grains>-<shape>`), or null when it is not one. */
        public fun parse(id: String): ComplianceCondition? {
            val match = Regex("g([0-9]{1,2})-([a-z-]+)").matchEntire(id) ?: return null
            val mask = ElectrodeMask.entries.firstOrNull { shapeName(it) == match.groupValues[2] } ?: return null
            return ComplianceCondition(match.groupValues[1].toInt(), mask)
        }
    }
}

/**
 * One trial: the [index]-th (0-based) stimulus a participant feels, [condition] for the [repetition]-th (0-based)
 * time. [calibrateBefore] is true when the electrodes are calibrated right before it (the session's first trial, and
 * in Shaping Compliance's Task 1 the first of every repetition); [breakBefore] when a short break comes first.
 */
public data class ComplianceTrial(
    val index: Int,
    val condition: ComplianceCondition,
    val repetition: Int,
    val calibrateBefore: Boolean = index == 0,
    val breakBefore: Boolean = false,
)

/** What the participant does in each trial. */
public enum class ComplianceTask {
    /** Task 1: rates the compliance felt against the bare desk with a signed number ([MagnitudeEstimation]). */
    MAGNITUDE,

    /** Task 2: says whether it felt more compliant than the desk, then draws the contour of where ([ShapeDrawing]). */
    DRAWING,
}

/** How the trials of a compliance protocol are grouped. */
public enum class RepetitionOrder {
    /**
     * Every repetition is a block with each condition once, in its own counterbalanced order, with a short break
     * between blocks: Shaping Compliance's Task 1 ("In each repetition, 12 trials were performed in a different
     * counterbalanced order. A short break was followed after each repetition", 003_8ca1dc8f53472543.txt:150).
     */
    BLOCKS,

    /** One list of every condition × repetition in one order, without breaks: Task 2's "randomized order without a break" (:175). */
    SHUFFLED,
}

/**
 * A compliance study: the participant presses with the finger-worn array on a hard surface under each [conditions]
 * entry, [repetitions] times, and answers as [task] says.
 *
 * With [RepetitionOrder.BLOCKS] repetition r of participant p is ordered by [Counterbalancing] with [order] as if it
 * were participant p·repetitions + r (so with [OrderScheme.WILLIAMS] every repetition of a participant is another row of
 * the balanced Latin square, and 12 conditions over 4 participants use all 12 rows), or with [OrderScheme.RANDOM] as
 * its own shuffle (stream r); with [RepetitionOrder.SHUFFLED] the whole list is one order for participant p.
 * [calibrateEachRepetition] asks for the electrotactile calibration before every block, not only before the first trial.
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
    val task: ComplianceTask = ComplianceTask.MAGNITUDE,
    val repetitionOrder: RepetitionOrder = RepetitionOrder.SHUFFLED,
    val calibrateEachRepetition: Boolean = false,
) {
    init {
        require(conditions.isNotEmpty()) { "a compliance study needs at least one condition" }
        require(conditions.map { it.id }.toSet().size == conditions.size) { "conditions must be distinct" }
        require(repetitions in 1..MAX_REPETITIONS) { "repetitions must be in 1..$MAX_REPETITIONS, was $repetitions" }
        val ordered = if (repetitionOrder == RepetitionOrder.BLOCKS) conditions.size else conditions.size * repetitions
        require(order != OrderScheme.FULL || ordered <= Counterbalancing.MAX_FULL_ITEMS) {
            "full counterbalancing takes at most ${Counterbalancing.MAX_FULL_ITEMS} trials per order"
        }
        require(!calibrateEachRepetition || repetitionOrder == RepetitionOrder.BLOCKS) { "calibrating before each repetition needs repetitions in blocks" }
    }

    /** How many trials a participant does. */
    public val trialCount: Int get() = conditions.size * repetitions

    /** The trials of participant [participantIndex] (0-based), in the order they are felt. */
    public fun trials(participantIndex: Int): List<ComplianceTrial> = when (repetitionOrder) {
        RepetitionOrder.SHUFFLED -> {
            val all = (0 until repetitions).flatMap { r -> conditions.map { it to r } }
            Counterbalancing.order(order, all.size, participantIndex, seed)
                .mapIndexed { i, k -> ComplianceTrial(i, all[k].first, all[k].second) }
        }
        RepetitionOrder.BLOCKS -> (0 until repetitions).flatMap { r ->
            val block = if (order == OrderScheme.RANDOM) {
                Counterbalancing.order(order, conditions.size, participantIndex, seed, stream = r)
            } else {
                Counterbalancing.order(order, conditions.size, participantIndex * repetitions + r, seed)
            }
            block.mapIndexed { j, k ->
                val first = j == 0
                ComplianceTrial(r * conditions.size + j, conditions[k], r, calibrateBefore = first && (r == 0 || calibrateEachRepetition), breakBefore = first && r > 0)
            }
        }
    }

    public companion object {
        /** Most repetitions of each condition. */
        public const val MAX_REPETITIONS: Int = 20
    }
}

/**
 * Shaping Compliance (the electrotactile compliance illusion, CHI 2024; 003_8ca1dc8f53472543.txt) as protocols.
 *
 * [PROTOCOL] is Task 1 as published and the default: 3 grain levels (9, 19, 39) × 4 electrode conditions (large
 * square, small square, vertical line, horizontal line) × 3 repetitions = 36 trials (:144, :150), each repetition a
 * block of the 12 conditions in a counterbalanced order with a break after it, the calibration redone before each
 * repetition (:152), and answers by signed magnitude estimation of compliance against the bare desk (:146–:148). How
 * the orders were counterbalanced is paper silent: ours is a Williams square (balanced Latin square), a different row
 * for every repetition of every participant.
 *
 * [EXTENDED] is ours, kept as a named variant: 0, 9, 19 and 39 grains × all five shapes (Task 2's triangle added,
 * :171) × 3 = 60 trials in one shuffled list, calibrated once. The 0-grain conditions ask the participant about the
 * no-stimulus reference that the paper only added to its analysis as 0 (:161).
 *
 * [SHAPES] is Task 2: the five shapes at 39 grains × 3 repetitions = 15 trials in a randomized order without a break,
 * after the same calibration as Task 1 (:171, :175), each answered by drawing the felt area ([ComplianceTask.DRAWING]).
 */
public object ComplianceStudy {
    /** The published Task 1's id. */
    public const val ID: String = "shaping-compliance"

    /** Our 60-trial variant's id. */
    public const val EXTENDED_ID: String = "shaping-compliance-extended"

    /** Task 2's id. */
    public const val SHAPES_ID: String = "shaping-compliance-shapes"

    /** Task 1's grain levels: 9, 19, 39 (003_8ca1dc8f53472543.txt:144). */
    public val GRAINS: List<Int> = listOf(9, 19, 39)

    /** Task 1's electrode conditions, in the paper's order: large square, small square, vertical line, horizontal line (:144). */
    public val SHAPES: List<ElectrodeMask> = listOf(ElectrodeMask.LARGE_SQUARE, ElectrodeMask.SMALL_SQUARE, ElectrodeMask.VERTICAL_LINE, ElectrodeMask.HORIZONTAL_LINE)

    /** Task 1's 12 conditions, grains outermost. */
    public val CONDITIONS: List<ComplianceCondition> = GRAINS.flatMap { g -> SHAPES.map { ComplianceCondition(g, it) } }

    /** Task 2's shapes: Task 1's four and the triangle (:171). */
    public val DRAWN_SHAPES: List<ElectrodeMask> = listOf(
        ElectrodeMask.LARGE_SQUARE, ElectrodeMask.HORIZONTAL_LINE, ElectrodeMask.VERTICAL_LINE, ElectrodeMask.SMALL_SQUARE, ElectrodeMask.TRIANGLE,
    )

    /** Task 2's grains: 39 for every shape (:171). */
    public const val DRAWING_GRAINS: Int = 39

    /**
     * What the participant is told before each Task 1 trial: the paper's definition of compliance (:146) and its
     * rating rules (:148, :150), in our words where the paper reports them rather than quoting a script.
     */
    public const val MAGNITUDE_INSTRUCTIONS: String =
        "Compliance is the sensation that the contact area displaces into the surface under pressure. " +
            "First press the bare desk without stimulation: its compliance is 0. Then press slowly and release with the stimulation on, " +
            "and rate the compliance of the stimulated area against the desk: a positive number if it was more compliant, a negative " +
            "number if less, 0 if the same. Any numbers you like, whole or decimal; keep one scale within a repetition. Rate only " +
            "compliance, not how strong the stimulation was or how large the area. Try the desk or the stimulus again as often as you like."

    /** What the participant is told before each Task 2 trial (:175). */
    public const val DRAWING_INSTRUCTIONS: String =
        "Press slowly and release with the stimulation on. Did it feel more compliant than the bare desk? Then draw the closed " +
            "outline of the area where you felt compliance, inside the outline of the device; draw several outlines if you felt " +
            "several areas."

    /** Task 1 as published: 36 trials in three counterbalanced blocks, calibrated before each. */
    public val PROTOCOL: ComplianceProtocol = ComplianceProtocol(
        id = ID,
        title = "Shaping Compliance, Task 1: compliance magnitude (as published)",
        instructions = MAGNITUDE_INSTRUCTIONS,
        conditions = CONDITIONS,
        repetitions = 3,
        order = OrderScheme.WILLIAMS,
        repetitionOrder = RepetitionOrder.BLOCKS,
        calibrateEachRepetition = true,
    )

    /** Ours: 0/9/19/39 grains × five shapes × 3 = 60 trials, one shuffled list, calibrated once. */
    public val EXTENDED: ComplianceProtocol = ComplianceProtocol(
        id = EXTENDED_ID,
        title = "Compliance magnitude, extended (ours: 0 grains and the triangle added)",
        instructions = MAGNITUDE_INSTRUCTIONS,
        conditions = (listOf(0) + GRAINS).flatMap { g -> DRAWN_SHAPES.map { ComplianceCondition(g, it) } },
        repetitions = 3,
        order = OrderScheme.RANDOM,
    )

    /** Task 2 as published: five shapes at 39 grains × 3 = 15 trials in a random order without a break. */
    public val SHAPES_PROTOCOL: ComplianceProtocol = ComplianceProtocol(
        id = SHAPES_ID,
        title = "Shaping Compliance, Task 2: draw the shape felt (as published)",
        instructions = DRAWING_INSTRUCTIONS,
        conditions = DRAWN_SHAPES.map { ComplianceCondition(DRAWING_GRAINS, it) },
        repetitions = 3,
        order = OrderScheme.RANDOM,
        task = ComplianceTask.DRAWING,
    )

    /** Every compliance protocol, the published Task 1 first. */
    public val ALL: List<ComplianceProtocol> = listOf(PROTOCOL, SHAPES_PROTOCOL, EXTENDED)

    /** The protocol with [id], or null. */
    public fun byId(id: String): ComplianceProtocol? = ALL.firstOrNull { it.id == id }
}
