package org.hapticon.app.study

import androidx.room.ColumnInfo
import androidx.room.Dao
import androidx.room.Embedded
import androidx.room.Entity
import androidx.room.Index
import androidx.room.Insert
import androidx.room.OnConflictStrategy
import androidx.room.PrimaryKey
import androidx.room.Query
import androidx.room.Upsert
import kotlinx.coroutines.flow.Flow
import org.hapticon.study.log.LogEntry

/**
 * A protocol the researcher made or edited (added in v4). [json] is the protocol in the study module's JSON;
 * [seed] drives the `random` design; [masking] is a [NoiseColor] name played at [maskingLevelDbfs] during tasks.
 * The default protocol is not stored: it comes from the study module, read-only.
 */
@Entity(tableName = "study_protocols")
data class StudyProtocolEntity(
    @PrimaryKey val id: String,
    val json: String,
    val seed: Long,
    val masking: String,
    @ColumnInfo(name = "masking_level_dbfs") val maskingLevelDbfs: Double,
    @ColumnInfo(name = "updated_at") val updatedAtMillis: Long,
)

/**
 * One participant's session (added in v4). The protocol is kept by value ([protocolJson]) as it ran, so a later
 * edit of the protocol cannot change what an old session means. Participant indices count per protocol id.
 */
@Entity(
    tableName = "study_sessions",
    indices = [Index(value = ["protocol_id", "participant_index"], unique = true)],
)
data class StudySessionEntity(
    @PrimaryKey(autoGenerate = true) val id: Long = 0,
    @ColumnInfo(name = "protocol_id") val protocolId: String,
    @ColumnInfo(name = "protocol_json") val protocolJson: String,
    val participant: String,
    @ColumnInfo(name = "participant_index") val participantIndex: Int,
    val seed: Long,
    val masking: String,
    @ColumnInfo(name = "masking_level_dbfs") val maskingLevelDbfs: Double,
    @ColumnInfo(name = "started_at") val startedAtMillis: Long,
)

/**
 * One row of a session's hash-chained event log (added in v4): the study module's [LogEntry] plus the session it
 * belongs to. Rows are only ever inserted; [StudyEventDao] has no update or delete, so the app cannot rewrite
 * history, and anyone who does (raw SQL) breaks the chain.
 */
@Entity(tableName = "study_events", primaryKeys = ["session_id", "seq"])
data class StudyEventEntity(
    @ColumnInfo(name = "session_id") val sessionId: Long,
    val seq: Long,
    val timestamp: Long,
    val participant: String,
    val type: String,
    val payload: String,
    @ColumnInfo(name = "prev_hash") val prevHash: String,
    val hash: String,
)

/** The log entry this row stores. */
fun StudyEventEntity.asLogEntry(): LogEntry = LogEntry(seq, timestamp, participant, type, payload, prevHash, hash)

/** [this] as the row of session [sessionId]. */
fun LogEntry.asEntity(sessionId: Long): StudyEventEntity =
    StudyEventEntity(sessionId, sequence, timestampMillis, participantId, type, payload, previousHash, hash)

/** A session with how far it got, for the researcher's list. */
data class SessionProgressRow(
    @Embedded val session: StudySessionEntity,
    val answers: Int,
    val ended: Int,
)

/** Stored protocols. */
@Dao
interface StudyProtocolDao {
    @Query("SELECT * FROM study_protocols ORDER BY id")
    fun protocols(): Flow<List<StudyProtocolEntity>>

    @Query("SELECT * FROM study_protocols WHERE id = :id")
    suspend fun protocol(id: String): StudyProtocolEntity?

    @Upsert
    suspend fun upsert(protocol: StudyProtocolEntity)

    @Query("DELETE FROM study_protocols WHERE id = :id")
    suspend fun delete(id: String)
}

/** Sessions: created once, never changed (their progress lives in the event log). */
@Dao
interface StudySessionDao {
    @Insert(onConflict = OnConflictStrategy.ABORT)
    suspend fun insert(session: StudySessionEntity): Long

    @Query("SELECT * FROM study_sessions WHERE id = :id")
    suspend fun session(id: Long): StudySessionEntity?

    @Query("SELECT * FROM study_sessions WHERE protocol_id = :protocolId ORDER BY participant_index")
    suspend fun sessionsOf(protocolId: String): List<StudySessionEntity>

    @Query("SELECT MAX(participant_index) FROM study_sessions WHERE protocol_id = :protocolId")
    suspend fun lastParticipantIndex(protocolId: String): Int?

    @Query(
        """
        SELECT s.*,
          (SELECT COUNT(*) FROM study_events e WHERE e.session_id = s.id AND e.type = 'answer') AS answers,
          (SELECT COUNT(*) FROM study_events e WHERE e.session_id = s.id AND e.type = 'session_ended') AS ended
        FROM study_sessions s ORDER BY s.id DESC
        """,
    )
    fun progress(): Flow<List<SessionProgressRow>>
}

/** The event log: append-only on purpose, with inserts and queries only. */
@Dao
interface StudyEventDao {
    /** Appends a row; a second row with the same sequence number fails (ABORT) instead of replacing history. */
    @Insert(onConflict = OnConflictStrategy.ABORT)
    suspend fun insert(event: StudyEventEntity)

    /** The rows of a session in the order they were written (rowid), so a row moved by raw SQL shows as moved. */
    @Query("SELECT * FROM study_events WHERE session_id = :sessionId ORDER BY rowid")
    suspend fun events(sessionId: Long): List<StudyEventEntity>
}
