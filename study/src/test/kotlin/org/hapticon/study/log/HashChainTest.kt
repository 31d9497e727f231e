package org.hapticon.study.log

import org.hapticon.core.io.Json
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class HashChainTest {
    private fun log(size: Int): List<LogEntry> {
        val log = EventLog.start("P004-E")
        log.append(StudyEvent.SessionStarted("study", 1, 4, Long.MIN_VALUE), 1_700_000_000_000)
        for (i in 1 until size) log.append(StudyEvent.Answer("icons", "s$i", 1 + i % 5), 1_700_000_000_000 + i)
        return log.entries
    }

    @Test
    fun untouchedChain_isIntact() {
        assertEquals(ChainVerification.Intact, log(10).verifyChain())
        assertEquals(ChainVerification.Intact, emptyList<LogEntry>().verifyChain())
        assertEquals(ChainVerification.Intact, log(1).verifyChain())
    }

    @Test
    fun firstEntry_pinnedHash() {
        val first = log(1)[0]
        assertEquals(LogEntry.GENESIS_HASH, first.previousHash)
        assertEquals("""{"protocol":"study","revision":1,"participantIndex":4,"seed":"-9223372036854775808"}""", first.payload)
        assertEquals(
            """["0","1700000000000","P004-E","session_started","{\"protocol\":\"study\",\"revision\":1,\"participantIndex\":4,\"seed\":\"-9223372036854775808\"}","${"0".repeat(64)}"]""",
            LogEntry.canonicalForm(first.sequence, first.timestampMillis, first.participantId, first.type, first.payload, first.previousHash),
        )
        // Computed independently: python3 hashlib.sha256 of the canonical form above.
        assertEquals("1c9fd68767098a16c4de7b9e8701fd7f29562a884e00d35e0548a56292280846", first.hash)
        assertEquals(StudyEvent.SessionStarted("study", 1, 4, Long.MIN_VALUE), first.event)
    }

    @Test
    fun editedPayload_detectedAtThatRow() {
        val entries = log(6).toMutableList()
        entries[3] = entries[3].copy(payload = entries[3].payload.replace("\"value\":4", "\"value\":5"))
        assertEquals(ChainVerification.Broken(3, ChainProblem.EDITED, "entry 3 does not match its hash"), entries.verifyChain())
    }

    @Test
    fun editedTimestampOrParticipant_detected() {
        val entries = log(4)
        assertEquals(ChainProblem.EDITED, (entries.toMutableList().also { it[2] = it[2].copy(timestampMillis = 0) }.verifyChain() as ChainVerification.Broken).problem)
        assertEquals(ChainProblem.EDITED, (entries.toMutableList().also { it[0] = it[0].copy(participantId = "P005-B") }.verifyChain() as ChainVerification.Broken).problem)
    }

    @Test
    fun deletedRow_detectedWhereTheGapIs() {
        val entries = log(6).toMutableList().apply { removeAt(2) }
        assertEquals(ChainVerification.Broken(2, ChainProblem.DELETED, "entries 2..2 are missing before entry 3"), entries.verifyChain())
        val firstGone = log(3).drop(1)
        assertEquals(ChainVerification.Broken(0, ChainProblem.DELETED, "entries 0..0 are missing before entry 1"), firstGone.verifyChain())
    }

    @Test
    fun swappedPair_detectedAsReordered() {
        val entries = log(6).toMutableList().apply { add(3, removeAt(4)) }
        assertEquals(ChainVerification.Broken(3, ChainProblem.REORDERED, "entry 4 is where entry 3 belongs"), entries.verifyChain())
    }

    @Test
    fun forgedRowWithValidHash_detectedAsRelinked() {
        val entries = log(5).toMutableList()
        val forged = LogEntry.create(2, entries[2].timestampMillis, "P004-E", StudyEvent.Answer("icons", "s2", 5), "f".repeat(64))
        entries[2] = forged
        assertEquals(ChainVerification.Broken(2, ChainProblem.RELINKED, "entry 2 does not link to the entry before it"), entries.verifyChain())
    }

    @Test
    fun resume_refusesBrokenChainAndOtherParticipant() {
        val entries = log(3)
        expect("cannot resume a broken log: deleted at index 0: entries 0..0 are missing before entry 1") { EventLog.resume("P004-E", entries.drop(1)) }
        expect("entry 0 belongs to P004-E, not P000-A") { EventLog.resume("P000-A", entries) }
        val resumed = EventLog.resume("P004-E", entries)
        resumed.append(StudyEvent.SessionEnded, 5)
        assertEquals(ChainVerification.Intact, resumed.entries.verifyChain())
        assertEquals(4, resumed.entries.size)
    }

    @Test
    fun everyEventType_payloadRoundTrips() {
        val events = listOf(
            StudyEvent.SessionStarted("p", 2, 7, 123), StudyEvent.SessionEnded, StudyEvent.TaskStarted("t"), StudyEvent.TaskEnded("t"),
            StudyEvent.StimulusShown("t", "s"), StudyEvent.IconPressed("t", "s"), StudyEvent.PlaybackStarted("t", "s"),
            StudyEvent.PlaybackFinished("t", "s"), StudyEvent.Answer("t", "s", 4),
        )
        for (event in events) assertEquals(event, StudyEvent.of(event.type, Json.decode(LogEntry.canonicalJson(StudyEvent.payload(event)))))
        expect("unknown event type \"nap\"") { StudyEvent.of("nap", Json.decode("{}")) }
        expect("payload.value: expected an integer, got \"4\"") { StudyEvent.of("answer", Json.decode("""{"task":"t","stimulus":"s","value":"4"}""")) }
    }

    private fun expect(message: String, block: () -> Unit) =
        assertEquals(message, assertThrows(IllegalArgumentException::class.java) { block() }.message)
}
