package org.hapticon.app.study

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ParticipantId
import org.hapticon.study.ProtocolJson
import org.hapticon.study.StudyProtocol
import org.hapticon.study.log.EventLog
import org.hapticon.study.log.LogEntry
import org.hapticon.study.log.StudyEvent

/** The masking noise of a protocol: [color] (or [NoiseColor.OFF]) at [levelDbfs], capped at [NoiseFiles.MAX_LEVEL_DBFS]. */
data class MaskingSetting(val color: NoiseColor = NoiseColor.OFF, val levelDbfs: Double = NoiseFiles.DEFAULT_LEVEL_DBFS) {
    init {
        require(levelDbfs.isFinite()) { "masking level must be a finite dBFS value, was $levelDbfs" }
    }

    /** The level actually played: never above the cap, never below the slider's floor. */
    val cappedLevelDbfs: Double get() = levelDbfs.coerceIn(NoiseFiles.MIN_LEVEL_DBFS, NoiseFiles.MAX_LEVEL_DBFS)

    /** Whether any noise plays. */
    val isOn: Boolean get() = color != NoiseColor.OFF
}

/**
 * A protocol as the app keeps it: the study module's [protocol], the [seed] of its random designs, its [masking]
 * noise, and whether it is the built-in default ([readOnly]: duplicate it to edit).
 */
data class StoredProtocol(
    val protocol: StudyProtocol,
    val seed: Long = 0L,
    val masking: MaskingSetting = MaskingSetting(),
    val readOnly: Boolean = false,
) {
    companion object {
        /** The originating study, always present and read-only. */
        val DEFAULT: StoredProtocol = StoredProtocol(OriginatingStudy.PROTOCOL, readOnly = true)

        /**
         * The originating study's own procedure ([OriginatingStudy.PAPER_PROTOCOL]), always present and read-only,
         * with the paper's white-noise masking on.
         */
        val PAPER: StoredProtocol = StoredProtocol(OriginatingStudy.PAPER_PROTOCOL, masking = MaskingSetting(NoiseColor.WHITE), readOnly = true)

        /** The built-in protocols, the default first. */
        val BUILT_IN: List<StoredProtocol> = listOf(DEFAULT, PAPER)
    }
}

/** A started session: who ([participant], [participantIndex]), under which [protocol] (as it ran) and masking. */
data class SessionRecord(
    val id: Long,
    val protocol: StudyProtocol,
    val participant: String,
    val participantIndex: Int,
    val seed: Long,
    val masking: MaskingSetting,
    val startedAtMillis: Long,
)

/** A session in the researcher's list: [answers] of [trials] rated, [finished] once SessionEnded is logged. */
data class SessionSummary(
    val id: Long,
    val protocolId: String,
    val participant: String,
    val participantIndex: Int,
    val answers: Int,
    val trials: Int,
    val finished: Boolean,
)

/** Protocols, sessions and their append-only event logs. */
interface StudyRepository {
    /** The built-in protocols first (the default, then the paper's procedure), then the stored ones by id; emits again on every change. */
    fun protocols(): Flow<List<StoredProtocol>>

    /** The protocol [id]: the default or a stored one; null when there is none. */
    suspend fun protocol(id: String): StoredProtocol?

    /** Stores [protocol], replacing one with its id. Throws [IllegalArgumentException] for the default's id or a read-only one. */
    suspend fun saveProtocol(protocol: StoredProtocol)

    /** Deletes stored protocol [id]; its sessions stay (they keep the protocol by value). */
    suspend fun deleteProtocol(id: String)

    /** Every session, newest first, with its progress. */
    fun sessions(): Flow<List<SessionSummary>>

    /**
     * Starts the next participant of [protocol]: the index after the last one of this protocol id, the participant
     * id from it, and the log's first entry (SessionStarted) written in the same transaction. Returns the session.
     */
    suspend fun startSession(protocol: StoredProtocol, nowMillis: Long): SessionRecord

    /** Session [id], or null. */
    suspend fun session(id: Long): SessionRecord?

    /** The sessions of protocol [protocolId], by participant index. */
    suspend fun sessionsOf(protocolId: String): List<SessionRecord>

    /** The log of session [sessionId] in the order it was written. */
    suspend fun entries(sessionId: Long): List<LogEntry>

    /** Appends [entry] to session [sessionId]'s log; fails when its sequence number is taken. */
    suspend fun append(sessionId: Long, entry: LogEntry)
}

/**
 * The study tables' DAOs, as the app's Room database provides them. The study feature reads the database
 * only through this, so `data.database` may depend on `study` (for the entities) and not the reverse.
 */
interface StudyDatabase {
    fun studyProtocolDao(): StudyProtocolDao
    fun studySessionDao(): StudySessionDao
    fun studyEventDao(): StudyEventDao

    /** Runs [block] in one database transaction (Room's `withTransaction`). */
    suspend fun <R> inTransaction(block: suspend () -> R): R
}

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
