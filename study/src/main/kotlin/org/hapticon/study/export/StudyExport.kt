package org.hapticon.study.export

import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue
import org.hapticon.study.JsonFields
import org.hapticon.study.ProtocolException
import org.hapticon.study.ProtocolJson
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
        /** The value of the `schema` member. */
        public const val SCHEMA: String = "hapticon.study-export"

        /** The schema version this build writes and reads. */
        public const val VERSION: Int = 1

        /** Largest export [decode] reads: 64 MiB, a few thousand participants' logs. */
        public const val MAX_LENGTH: Int = 64 shl 20

        /** [export] as indented JSON text. Does not throw. */
        public fun encode(export: StudyExport, indent: String = "  "): String = Json.encode(
            JsonObject(
                linkedMapOf(
                    "schema" to JsonString(SCHEMA),
                    "version" to JsonNumber(VERSION),
                    "protocol" to ProtocolJson.toJsonValue(export.protocol),
                    "participants" to JsonArray(
                        export.sessions.map { session ->
                            JsonObject(linkedMapOf("participant" to JsonString(session.participantId), "entries" to JsonArray(session.entries.map(::entryJson))))
                        },
                    ),
                ),
            ),
            indent,
        )

        /**
         * Parses an export. Throws [JsonException] when [text] is not JSON or longer than [MAX_LENGTH], and
         * [ProtocolException] naming the path (for example `participants[0].entries[3].hash`) of a missing or mistyped
         * member or an invalid protocol. Hashes are read as they are; verify them with the log's chain check.
         */
        public fun decode(text: String): StudyExport {
            val doc = JsonFields.of(Json.decode(text, MAX_LENGTH), "", "export")
            doc.requireSchema(SCHEMA, VERSION)
            val protocol = try {
                ProtocolJson.fromJsonValue(doc.optional("protocol") ?: doc.missing("protocol"))
            } catch (e: ProtocolException) {
                throw ProtocolException("protocol.${e.path}", e.message.orEmpty().removePrefix("${e.path}: "))
            }
            val sessions = doc.objects("participants") { participant ->
                SessionLog(
                    participantId = participant.string("participant"),
                    entries = participant.objects("entries") { entry ->
                        LogEntry(
                            sequence = entry.long("sequence"),
                            timestampMillis = entry.long("timestamp"),
                            participantId = entry.string("participant"),
                            type = entry.string("type"),
                            payload = entry.string("payload"),
                            previousHash = entry.string("previousHash"),
                            hash = entry.string("hash"),
                        )
                    },
                )
            }
            return StudyExport(protocol, sessions)
        }

        private fun entryJson(entry: LogEntry): JsonValue = JsonObject(
            linkedMapOf(
                "sequence" to JsonNumber(entry.sequence),
                "timestamp" to JsonNumber(entry.timestampMillis),
                "participant" to JsonString(entry.participantId),
                "type" to JsonString(entry.type),
                "payload" to JsonString(entry.payload),
                "previousHash" to JsonString(entry.previousHash),
                "hash" to JsonString(entry.hash),
            ),
        )
    }
}
