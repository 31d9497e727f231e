package org.hapticon.companion.study

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.sensors.InputFiles
import org.hapticon.core.io.JsonException
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ParticipantId
import org.hapticon.study.schema.ProtocolException
import org.hapticon.study.ProtocolJson
import org.hapticon.study.StudyProtocol
import org.hapticon.study.design.Counterbalancing
import org.hapticon.study.design.OrderScheme
import org.hapticon.study.ParticipantSchedule
import java.io.File

/** Most participants `schedule` lists: far beyond any lab study, small enough that the output stays a file, not a flood. */
const val MAX_SCHEDULE_PARTICIPANTS: Int = 100_000

/** `--design` values. */
val DESIGN_CHOICES: Map<String, OrderScheme> = OrderScheme.entries.associateByTo(LinkedHashMap()) { it.jsonName }

/**
 * `hapticon schedule --participants N --design paper|williams|full|random|fixed [--seed S] [--protocol FILE]`: the task
 * order of every participant as CSV `participant,position,task`, a blank line, then every stimulus order as CSV
 * `participant,task,position,stimulus`. `participant` is the pseudonymous id (P000-A, ...), positions are 1-based.
 * `--design` replaces the protocol's task order; stimulus orders follow each task's own scheme. One line on stderr
 * says whether N completes the design's cycle.
 */
fun runSchedule(args: List<String>, console: Console) {
    val arguments = Arguments.parse("schedule", args, valueOptions = setOf("participants", "design", "seed", "protocol"))
    arguments.requireNoPositionals()
    val participants = arguments.required("participants").let { text ->
        text.toIntOrNull()?.takeIf { it in 1..MAX_SCHEDULE_PARTICIPANTS }
            ?: throw UsageException("--participants must be a whole number in 1..$MAX_SCHEDULE_PARTICIPANTS, got '$text'")
    }
    arguments.required("design")
    val design = arguments.choice("design", DESIGN_CHOICES, OrderScheme.FIXED)
    val seed = arguments.value("seed")?.let { it.toLongOrNull() ?: throw UsageException("--seed must be a whole number (64-bit), got '$it'") } ?: 0L
    val protocol = (arguments.value("protocol")?.let(::loadProtocol) ?: OriginatingStudy.PROTOCOL).copy(taskOrder = design)
    val schedules = try {
        (0 until participants).map { ParticipantSchedule.of(protocol, it, seed) }
    } catch (e: IllegalArgumentException) {
        throw UsageException("cannot schedule ${protocol.id}: ${e.message}")
    }
    // No quoting needed: participant, task and stimulus ids are restricted to A-Z a-z 0-9 _ . -
    val out = StringBuilder("participant,position,task\n")
    for (schedule in schedules) {
        val id = ParticipantId.of(schedule.participantIndex)
        schedule.tasks.forEachIndexed { i, task -> out.append(id).append(',').append(i + 1).append(',').append(task.id).append('\n') }
    }
    out.append("\nparticipant,task,position,stimulus\n")
    for (schedule in schedules) {
        val id = ParticipantId.of(schedule.participantIndex)
        for (task in schedule.tasks) {
            schedule.stimuli.getValue(task.id).forEachIndexed { i, stimulus ->
                out.append(id).append(',').append(task.id).append(',').append(i + 1).append(',').append(stimulus.id).append('\n')
            }
        }
    }
    console.out.print(out)
    console.err.println(describeBalance(protocol, participants))
}

/** `hapticon study-protocol [--out FILE]`: the default protocol as indented JSON, to stdout or FILE. */
fun runStudyProtocol(args: List<String>, console: Console) {
    val arguments = Arguments.parse("study-protocol", args, valueOptions = setOf("out"))
    arguments.requireNoPositionals()
    val json = ProtocolJson.encode(OriginatingStudy.PROTOCOL) + "\n"
    val out = arguments.value("out")
    if (out == null) {
        console.out.print(json)
    } else {
        OutputFiles.write(File(out)) { it.write(json.toByteArray(Charsets.UTF_8)) }
        console.err.println("study-protocol: wrote $out")
    }
}

/** The protocol in the file at [path]; every problem is a one-line [UsageException] naming the file and the field. */
internal fun loadProtocol(path: String): StudyProtocol {
    val text = InputFiles.readText("protocol", path)
    return try {
        ProtocolJson.decode(text)
    } catch (e: JsonException) {
        throw UsageException("protocol file $path is not valid JSON: ${e.message}")
    } catch (e: ProtocolException) {
        throw UsageException("protocol file $path is not a valid study protocol: ${e.message}")
    }
}

/** The stderr line: the design's cycle, and whether [participants] fills whole cycles (only then is it balanced). */
internal fun describeBalance(protocol: StudyProtocol, participants: Int): String {
    val design = protocol.taskOrder.jsonName
    val cycle = Counterbalancing.cycleLength(protocol.taskOrder, protocol.counterbalancedTasks.size)
        ?: return "schedule: $participants participants, $design task order (seeded shuffle, balanced only on average)"
    val balance = if (participants % cycle == 0L) "balanced" else "not balanced: not a multiple of the cycle"
    return "schedule: $participants participants, $design task order over ${protocol.counterbalancedTasks.size} tasks, " +
        "cycle of $cycle participant${if (cycle == 1L) "" else "s"}: $balance"
}
