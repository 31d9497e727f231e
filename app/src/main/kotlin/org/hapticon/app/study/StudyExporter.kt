package org.hapticon.app.study

import android.content.Context
import android.content.Intent
import androidx.core.content.FileProvider
import java.io.File
import java.io.IOException
import java.net.URI
import org.hapticon.study.StudyProtocol
import org.hapticon.study.export.ResponseCsv
import org.hapticon.study.export.ResponseRow
import org.hapticon.study.export.ResponseRows
import org.hapticon.study.export.SessionLog
import org.hapticon.study.export.StudyExport
import org.hapticon.study.log.ChainVerification
import org.hapticon.study.log.HashChain
import org.hapticon.study.log.LogEntry

/** A session's chain check, in the researcher's words: "log intact" or "log edited at row N". */
data class SessionCheck(val participant: String, val verification: ChainVerification) {
    /** "log intact", or what broke and at which row (0-based, as the log's sequence numbers). */
    val summary: String
        get() = when (verification) {
            ChainVerification.Intact -> "log intact"
            is ChainVerification.Broken -> "log ${verification.problem.name.lowercase()} at row ${verification.index}"
        }
}

/** What [StudyExporter.export] wrote: the two files, the CSV text (for upload) and every session's chain check. */
data class ExportResult(val csvFile: File, val jsonFile: File, val csv: String, val rows: Int, val checks: List<SessionCheck>)

/**
 * Writes a protocol's results into [directory] (cacheDir/exports): the long-format CSV and the full JSON record of
 * the study module, named after the study id and [clock]'s time.
 */
class StudyExporter(private val directory: File, private val clock: () -> Long = System::currentTimeMillis) {
    /**
     * Exports [sessions] (each with its log, oldest first) of [protocol]. A session whose protocol revision differs
     * from [protocol]'s is skipped from the CSV rows (its answers would not match the plan) but kept in the JSON.
     * Throws [IOException] when the files cannot be written.
     */
    @Throws(IOException::class)
    fun export(protocol: StudyProtocol, sessions: List<Pair<SessionRecord, List<LogEntry>>>): ExportResult {
        if (!directory.isDirectory && !directory.mkdirs()) throw IOException("cannot create $directory")
        val rows = ArrayList<ResponseRow>()
        for ((record, entries) in sessions) {
            if (record.protocol.revision == protocol.revision) rows += ResponseRows.of(record.protocol, entries)
        }
        val csv = ResponseCsv.write(rows)
        val json = StudyExport.encode(StudyExport(protocol, sessions.map { (record, entries) -> SessionLog(record.participant, entries) }))
        val stem = "${protocol.id}-r${protocol.revision}-${clock()}"
        // The shared file is opened in spreadsheets: formula-like cells neutralised (OWASP). The upload keeps [csv]
        // as it is; the collector neutralises its own downloads.
        val csvFile = File(directory, "$stem.csv").apply { writeText(ResponseCsv.write(rows, forSpreadsheet = true)) }
        val jsonFile = File(directory, "$stem.json").apply { writeText(json) }
        val checks = sessions.map { (record, entries) -> SessionCheck(record.participant, HashChain.verify(entries)) }
        return ExportResult(csvFile, jsonFile, csv, rows.size, checks)
    }

    companion object {
        /** The FileProvider authority of the exports (see the manifest and res/xml/file_paths.xml). */
        const val AUTHORITY: String = "org.hapticon.app.exports"

        /** An ACTION_SEND intent for [file] as a content URI the receiving app may read, with [mimeType]. */
        fun shareIntent(context: Context, file: File, mimeType: String): Intent = Intent(Intent.ACTION_SEND).apply {
            type = mimeType
            putExtra(Intent.EXTRA_STREAM, FileProvider.getUriForFile(context, AUTHORITY, file))
            putExtra(Intent.EXTRA_SUBJECT, file.name)
            addFlags(Intent.FLAG_GRANT_READ_URI_PERMISSION)
        }
    }
}
