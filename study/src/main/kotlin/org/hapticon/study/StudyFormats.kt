package org.hapticon.study

/**
 * Every schema name and version of the study family, in one place: the protocol ([ProtocolJson]) and the export
 * that nests it ([org.hapticon.study.export.StudyExport]). The study log has no version of its own: its rows are
 * hash-chained, so their spelling never changes (`LogEntry.canonicalForm`). The other families keep theirs in
 * `org.hapticon.core.io.HapticFormats`, `org.hapticon.messaging.WireFormats`, `org.hapticon.gesture.GestureFormats`
 * and `org.hapticon.sensor.SensorFormats`; docs/json.md lists them all.
 *
 * A version is what this build writes and the newest it reads; raising one is a format change that older builds
 * will refuse (docs/json.md, "Versions").
 */
public object StudyFormats {
    /** `schema` of a study protocol. */
    public const val PROTOCOL_SCHEMA: String = "hapticon.study"

    /** Version of the study protocol. */
    public const val PROTOCOL_VERSION: Int = 1

    /** `schema` of a study export (data of one or more sessions with their protocol). */
    public const val EXPORT_SCHEMA: String = "hapticon.study-export"

    /** Version of the study export. */
    public const val EXPORT_VERSION: Int = 1
}
