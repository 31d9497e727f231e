package org.hapticon.study.compliance

/** The answers read from compliance answer files: Task 1's ratings and Task 2's drawings. */
public data class ComplianceAnswers(val ratings: List<MagnitudeEstimate>, val drawings: List<ShapeDrawing>)

/**
 * The compliance study's answers file, one row per answered trial, written by the app as each answer is given and read
 * by `hapticon compliance-analysis`:
 *
 * `protocol,participant,trial,repetition,condition,grains,shape,electrodes,rating,more_compliant,contours`
 *
 * trial and repetition 1-based; `rating` is Task 1's signed number (empty in Task 2); `more_compliant` is Task 2's
 * `yes`/`no` and `contours` its drawing ([ShapeDrawings.encode]; both empty in Task 1). Participant names and protocol
 * ids are letters, digits, `-` and `_`, and no other field holds a comma or quote, so no field is quoted.
 */
public object ComplianceAnswersCsv {
    /** The header line. */
    public const val HEADER: String = "protocol,participant,trial,repetition,condition,grains,shape,electrodes,rating,more_compliant,contours"

    /** The row of Task 1 trial [trial] of [protocol], answered by [participant] with [rating]. */
    public fun ratingRow(protocol: ComplianceProtocol, participant: String, trial: ComplianceTrial, rating: Double): String =
        row(protocol, participant, trial, rating.toString(), "", "")

    /** The row of Task 2 trial [trial] of [protocol]: whether it felt [moreCompliant] and the [contours] drawn. */
    public fun drawingRow(protocol: ComplianceProtocol, participant: String, trial: ComplianceTrial, moreCompliant: Boolean, contours: List<List<DrawingPoint>>): String =
        row(protocol, participant, trial, "", if (moreCompliant) "yes" else "no", ShapeDrawings.encode(contours))

    private fun row(protocol: ComplianceProtocol, participant: String, trial: ComplianceTrial, rating: String, more: String, contours: String): String {
        val c = trial.condition
        return listOf(
            protocol.id, participant, trial.index + 1, trial.repetition + 1, c.id, c.grains, ComplianceCondition.shapeName(c.mask), c.mask.pattern, rating, more, contours,
        ).joinToString(",")
    }

    /**
     * The answers in [text] (one file; [source] names it in errors). A header line is expected first; blank lines are
     * skipped.
     * @throws IllegalArgumentException with `source:line: reason` for the first bad line.
     */
    public fun read(text: String, source: String): ComplianceAnswers {
        val ratings = ArrayList<MagnitudeEstimate>()
        val drawings = ArrayList<ShapeDrawing>()
        val lines = text.lines()
        require(lines.firstOrNull()?.trim() == HEADER) { "$source:1: not a compliance answers file (the header must be $HEADER)" }
        for ((i, line) in lines.withIndex().drop(1)) {
            if (line.isBlank()) continue
            val at = "$source:${i + 1}"
            val f = line.split(',')
            require(f.size == 11) { "$at: ${f.size} fields, expected 11" }
            val condition = ComplianceCondition.parse(f[4]) ?: throw IllegalArgumentException("$at: unknown condition '${f[4]}'")
            val repetition = f[3].toIntOrNull()?.takeIf { it >= 1 } ?: throw IllegalArgumentException("$at: repetition '${f[3]}' is not a whole number from 1")
            when {
                f[8].isNotEmpty() -> {
                    val rating = MagnitudeEstimation.parse(f[8]) ?: throw IllegalArgumentException("$at: rating '${f[8]}' is not a number")
                    ratings += MagnitudeEstimate(f[1], repetition - 1, condition, rating)
                }
                f[9] == "yes" || f[9] == "no" -> {
                    val contours = try {
                        ShapeDrawings.decode(f[10])
                    } catch (e: IllegalArgumentException) {
                        throw IllegalArgumentException("$at: ${e.message}")
                    }
                    drawings += ShapeDrawing(f[1], repetition - 1, condition, f[9] == "yes", contours)
                }
                else -> throw IllegalArgumentException("$at: neither a rating nor a drawing")
            }
        }
        return ComplianceAnswers(ratings, drawings)
    }
}
