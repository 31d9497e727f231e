package org.hapticon.app.study

import kotlinx.coroutines.flow.Flow
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.StudyProtocol
import org.hapticon.study.log.LogEntry

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
