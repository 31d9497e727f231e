package org.hapticon.companion.study

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.study.ParticipantId
import org.hapticon.study.compliance.ComplianceStudy

/**
 * `hapticon compliance-schedule --participants N [--repetitions R] [--seed S]`: the Shaping Compliance protocol's
 * trials ([ComplianceStudy.PROTOCOL]) for each participant as CSV
 * `participant,trial,condition,grains,shape,electrodes,repetition`, trial 1-based, to run the study with the
 * app's or the firmware's grain settings and collect the magnitude estimates.
 */
fun runComplianceSchedule(args: List<String>, console: Console) {
    val arguments = Arguments.parse("compliance-schedule", args, valueOptions = setOf("participants", "repetitions", "seed"))
    arguments.requireNoPositionals()
    val participants = arguments.required("participants").let { text ->
        text.toIntOrNull()?.takeIf { it in 1..MAX_SCHEDULE_PARTICIPANTS }
            ?: throw UsageException("--participants must be a whole number in 1..$MAX_SCHEDULE_PARTICIPANTS, got '$text'")
    }
    val repetitions = arguments.int("repetitions", ComplianceStudy.PROTOCOL.repetitions)
    val seedText = arguments.value("seed")
    val seed = if (seedText == null) ComplianceStudy.PROTOCOL.seed else seedText.toLongOrNull() ?: throw UsageException("--seed must be a whole number, got '$seedText'")
    val protocol = try {
        ComplianceStudy.PROTOCOL.copy(repetitions = repetitions, seed = seed)
    } catch (e: IllegalArgumentException) {
        throw UsageException("--repetitions: ${e.message}")
    }
    console.out.println("participant,trial,condition,grains,shape,electrodes,repetition")
    for (p in 0 until participants) {
        for (trial in protocol.trials(p)) {
            val c = trial.condition
            console.out.println("${ParticipantId.of(p)},${trial.index + 1},${c.id},${c.grains},${c.mask.name.lowercase()},${c.mask.pattern},${trial.repetition + 1}")
        }
    }
    console.err.println("compliance-schedule: $participants participants × ${protocol.conditions.size} conditions × $repetitions repetitions, seed $seed")
}
