package org.hapticon.companion.study

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.study.ParticipantId
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceStudy

/**
 * `hapticon compliance-schedule --participants N [--protocol ID] [--repetitions R] [--seed S]`: a compliance protocol's
 * trials for each participant as CSV `participant,trial,condition,grains,shape,electrodes,repetition,before`, trial and
 * repetition 1-based; `before` says what comes first: `calibrate` (the electrotactile calibration), `break+calibrate`, or
 * nothing. The protocol is Shaping Compliance's Task 1 as published unless `--protocol` names another
 * ([ComplianceStudy.ALL]).
 */
fun runComplianceSchedule(args: List<String>, console: Console) {
    val arguments = Arguments.parse("compliance-schedule", args, valueOptions = setOf("participants", "protocol", "repetitions", "seed"))
    arguments.requireNoPositionals()
    val participants = arguments.required("participants").let { text ->
        text.toIntOrNull()?.takeIf { it in 1..MAX_SCHEDULE_PARTICIPANTS }
            ?: throw UsageException("--participants must be a whole number in 1..$MAX_SCHEDULE_PARTICIPANTS, got '$text'")
    }
    val base = arguments.value("protocol")?.let { id ->
        ComplianceStudy.byId(id) ?: throw UsageException("--protocol must be one of ${ComplianceStudy.ALL.joinToString { it.id }}, got '$id'")
    } ?: ComplianceStudy.PROTOCOL
    val repetitions = arguments.int("repetitions", base.repetitions)
    val seedText = arguments.value("seed")
    val seed = if (seedText == null) base.seed else seedText.toLongOrNull() ?: throw UsageException("--seed must be a whole number, got '$seedText'")
    val protocol = try {
        base.copy(repetitions = repetitions, seed = seed)
    } catch (e: IllegalArgumentException) {
        throw UsageException("--repetitions: ${e.message}")
    }
    console.out.println("participant,trial,condition,grains,shape,electrodes,repetition,before")
    for (p in 0 until participants) {
        for (trial in protocol.trials(p)) {
            val c = trial.condition
            val before = listOfNotNull("break".takeIf { trial.breakBefore }, "calibrate".takeIf { trial.calibrateBefore }).joinToString("+")
            console.out.println(
                "${ParticipantId.of(p)},${trial.index + 1},${c.id},${c.grains},${ComplianceCondition.shapeName(c.mask)},${c.mask.pattern},${trial.repetition + 1},$before",
            )
        }
    }
    console.err.println(
        "compliance-schedule: ${protocol.id}: $participants participants × ${protocol.conditions.size} conditions × $repetitions repetitions " +
            "(${protocol.repetitionOrder.name.lowercase()}, ${protocol.order.jsonName} order), seed $seed",
    )
}
