package org.hapticon.study.export

import kotlinx.serialization.Serializable
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.SchemaJson
import org.hapticon.study.ProtocolDocument
import org.hapticon.study.schema.ProtocolException
import org.hapticon.study.ProtocolJson
import org.hapticon.study.schema.StudyReport
import org.hapticon.study.StudyFormats
import org.hapticon.study.StudyProtocol
import org.hapticon.study.log.LogEntry

/** One participant's full log in a [StudyExport]. */
public data class SessionLog(
    /** The pseudonymous participant id. */
    val participantId: String,
    /** Every entry, oldest first, with its hashes. */
    val entries: List<LogEntry>,
)

/**
 * Everything a study produced, as one JSON document (schema `hapticon.study-export` version 1): the [protocol], then
 * per participant the full event log with hashes, so that an analyst can re-verify every chain
 * ([org.hapticon.study.log.HashChain.verify]) and rebuild every response ([ResponseRows.of]).
 *
 * ```
 * {"schema": "hapticon.study-export", "version": 1, "protocol": {protocol JSON},
 *  "participants": [{"participant": "P000-A", "entries": [{"sequence": 0, "timestamp": 1700000000000,
 *    "participant": "P000-A", "type": "session_started", "payload": "{…}", "previousHash": "000…", "hash": "…"}]}]}
 * ```
 *
 * `payload` is the exact text the hash covers, kept as a string so that no re-encoding can change it.
 */
public data class StudyExport(
    /** The protocol every session ran. */
    val protocol: StudyProtocol,
    /** The participants' logs. */
    val sessions: List<SessionLog>,
) {
    public companion object {
        /** The value of the `schema` member ([StudyFormats.EXPORT_SCHEMA]). */
        public const val SCHEMA: String = StudyFormats.EXPORT_SCHEMA

        /** The schema version this build writes and reads ([StudyFormats.EXPORT_VERSION]). */
        public const val VERSION: Int = StudyFormats.EXPORT_VERSION

        /** Largest export [decode] reads: 64 MiB, a few thousand participants' logs. */
        public const val MAX_LENGTH: Int = 64 shl 20

        /** [export] as indented JSON text. Does not throw. */
        public fun encode(export: StudyExport, indent: String = "  "): String = SchemaJson.encode(
            ExportDocument.serializer(),
            ExportDocument(
                SCHEMA, VERSION.toLong(), ProtocolJson.document(export.protocol),
                export.sessions.map { session ->
                    ParticipantDocument(
                        session.participantId,
                        session.entries.map { EntryDocument(it.sequence, it.timestampMillis, it.participantId, it.type, it.payload, it.previousHash, it.hash) },
                    )
                },
            ),
            indent,
        )

        /**
         * Parses an export. Throws [JsonException] when [text] is not JSON or longer than [MAX_LENGTH], and
         * [ProtocolException] naming the path (for example `participants[0].entries[3].hash`) of a missing or mistyped
         * member or an invalid protocol. Hashes are read as they are; verify them with the log's chain check.
         */
        public fun decode(text: String): StudyExport {
            val report = StudyReport("export", mapOf("" to (SCHEMA to VERSION), "protocol" to (StudyFormats.PROTOCOL_SCHEMA to StudyFormats.PROTOCOL_VERSION)))
            val doc = SchemaJson.decode(ExportDocument.serializer(), Json.decode(text, MAX_LENGTH), report)
            val protocol = try {
                ProtocolJson.protocol(doc.protocol)
            } catch (e: ProtocolException) {
                throw ProtocolException("protocol.${e.path}", e.message.orEmpty().removePrefix("${e.path}: "))
            }
            val sessions = doc.participants.map { participant ->
                SessionLog(
                    participantId = participant.participant,
                    entries = participant.entries.map { LogEntry(it.sequence, it.timestamp, it.participant, it.type, it.payload, it.previousHash, it.hash) },
                )
            }
            return StudyExport(protocol, sessions)
        }
    }
}

/** A study export document; members in schema order. */
@Serializable
internal class ExportDocument(val schema: String, val version: Long, val protocol: ProtocolDocument, val participants: List<ParticipantDocument>)

/** One participant's log in an [ExportDocument]. */
@Serializable
internal class ParticipantDocument(val participant: String, val entries: List<EntryDocument>)

/** One [LogEntry]; `payload` is the exact hashed text. */
@Serializable
internal class EntryDocument(
    val sequence: Long,
    val timestamp: Long,
    val participant: String,
    val type: String,
    val payload: String,
    val previousHash: String,
    val hash: String,
)
