package org.hapticon.app.study

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.study.ParticipantId
import org.hapticon.study.ProtocolJson
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.LogEntry
import org.hapticon.study.log.StudyEvent

/** [StudyRepository] on Room. */
class RoomStudyRepository(private val db: StudyDatabase) : StudyRepository {
    private val protocols = db.studyProtocolDao()
    private val sessions = db.studySessionDao()
    private val events = db.studyEventDao()

    override fun protocols(): Flow<List<StoredProtocol>> = protocols.protocols().map { rows ->
        // A row that no longer parses (a stricter future rule) is left out rather than crashing the list.
        StoredProtocol.BUILT_IN + rows.mapNotNull { runCatching { it.asStoredProtocol() }.getOrNull() }
    }

    override suspend fun protocol(id: String): StoredProtocol? =
        StoredProtocol.BUILT_IN.firstOrNull { it.protocol.id == id } ?: protocols.protocol(id)?.asStoredProtocol()

    override suspend fun saveProtocol(protocol: StoredProtocol) {
        require(!protocol.readOnly) { "protocol ${protocol.protocol.id} is read-only; duplicate it to edit" }
        require(StoredProtocol.BUILT_IN.none { it.protocol.id == protocol.protocol.id }) {
            "the id ${protocol.protocol.id} belongs to a built-in protocol; choose another id"
        }
        protocols.upsert(
            StudyProtocolEntity(
                id = protocol.protocol.id,
                json = ProtocolJson.encode(protocol.protocol, ""),
                seed = protocol.seed,
                masking = protocol.masking.color.name,
                maskingLevelDbfs = protocol.masking.levelDbfs,
                updatedAtMillis = System.currentTimeMillis(),
            ),
        )
    }

    override suspend fun deleteProtocol(id: String) = protocols.delete(id)

    override fun sessions(): Flow<List<SessionSummary>> = sessions.progress().map { rows ->
        rows.map { row ->
            val trials = runCatching { ProtocolJson.decode(row.session.protocolJson).tasks.sumOf { it.stimuli.size } }.getOrDefault(0)
            SessionSummary(
                row.session.id, row.session.protocolId, row.session.participant, row.session.participantIndex,
                row.answers, trials, row.ended > 0,
            )
        }
    }

    override suspend fun startSession(protocol: StoredProtocol, nowMillis: Long): SessionRecord = db.inTransaction {
        val index = (sessions.lastParticipantIndex(protocol.protocol.id) ?: -1) + 1
        val participant = ParticipantId.of(index)
        val entity = StudySessionEntity(
            protocolId = protocol.protocol.id,
            protocolJson = ProtocolJson.encode(protocol.protocol, ""),
            participant = participant,
            participantIndex = index,
            seed = protocol.seed,
            masking = protocol.masking.color.name,
            maskingLevelDbfs = protocol.masking.levelDbfs,
            startedAtMillis = nowMillis,
        )
        val id = sessions.insert(entity)
        val first = EventLog.start(participant).append(
            StudyEvent.SessionStarted(protocol.protocol.id, protocol.protocol.revision, index, protocol.seed), nowMillis,
        )
        events.insert(first.asEntity(id))
        entity.copy(id = id).asRecord()
    }

    override suspend fun session(id: Long): SessionRecord? = sessions.session(id)?.asRecord()

    override suspend fun sessionsOf(protocolId: String): List<SessionRecord> = sessions.sessionsOf(protocolId).map { it.asRecord() }

    override suspend fun entries(sessionId: Long): List<LogEntry> = events.events(sessionId).map { it.asLogEntry() }

    override suspend fun append(sessionId: Long, entry: LogEntry) = events.insert(entry.asEntity(sessionId))

    private fun StudyProtocolEntity.asStoredProtocol() =
        StoredProtocol(ProtocolJson.decode(json), seed, MaskingSetting(NoiseColor.of(masking), maskingLevelDbfs))

    private fun StudySessionEntity.asRecord() = SessionRecord(
        id, ProtocolJson.decode(protocolJson), participant, participantIndex, seed,
        MaskingSetting(NoiseColor.of(masking), maskingLevelDbfs), startedAtMillis,
    )
}
