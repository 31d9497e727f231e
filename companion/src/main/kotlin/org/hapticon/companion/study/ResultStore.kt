package org.hapticon.companion.study

import java.sql.Connection
import java.sql.DriverManager
import java.sql.SQLException

/** What one upload did: [inserted] new rows, [unchanged] rows already stored with the same content. */
class UploadOutcome(val inserted: Int, val unchanged: Int)

/**
 * The collector's database, over JDBC: SQLite (`sqlite:PATH`) or PostgreSQL (`postgresql://HOST[:PORT]/DB?user=..`).
 * One table `study_results`, primary key (study_id, participant, task, trial). A connection per call,
 * so a restarted PostgreSQL or a locked SQLite file costs one failed request, not the service.
 */
class ResultStore(private val jdbcUrl: String) {
    init {
        connect().use { c ->
            c.createStatement().use { it.executeUpdate(CREATE_TABLE) }
            addEnvelopeModelColumn(c)
        }
    }

    /**
     * A table made before results carried `envelope_model` gets the column, its old rows reading `unknown`: nothing
     * stored is lost, and nobody is told which model those participants felt when it was never recorded.
     */
    private fun addEnvelopeModelColumn(c: Connection) {
        val columns = c.metaData.getColumns(null, null, "study_results", null).use { r ->
            buildSet { while (r.next()) add(r.getString("COLUMN_NAME").lowercase()) }
        }
        if (columns.isNotEmpty() && "envelope_model" !in columns) {
            c.createStatement().use { it.executeUpdate("ALTER TABLE study_results ADD COLUMN envelope_model TEXT NOT NULL DEFAULT 'unknown'") }
        }
    }

    /**
     * Stores [rows] in one transaction: new keys are inserted, keys already stored with identical fields
     * are skipped (re-upload is idempotent), and a key stored with different fields fails the whole upload
     * with [InvalidUploadException] naming the row's line ([lines] holds each row's upload line).
     */
    fun store(rows: List<ResultRow>, lines: List<Int>): UploadOutcome = connect().use { c ->
        c.autoCommit = false
        try {
            var inserted = 0
            var unchanged = 0
            val seen = HashMap<List<String>, ResultRow>()
            c.prepareStatement(SELECT_ONE).use { select ->
                c.prepareStatement(INSERT).use { insert ->
                    for ((i, row) in rows.withIndex()) {
                        val earlier = seen[row.key] ?: find(select, row)
                        if (earlier != null) {
                            if (earlier != row) throw InvalidUploadException(lines[i], "line ${lines[i]}: participant '${row["participant"]}' task '${row["task"]}' trial ${row["trial"]} is already stored with different values")
                            unchanged++
                            continue
                        }
                        bind(insert, row.fields)
                        insert.executeUpdate()
                        seen[row.key] = row
                        inserted++
                    }
                }
            }
            c.commit()
            UploadOutcome(inserted, unchanged)
        } catch (e: Exception) {
            c.rollback()
            throw e
        }
    }

    /** The rows of [studyId], ordered by participant_index, participant, task_position, task, trial. */
    fun rows(studyId: String): List<ResultRow> = connect().use { c ->
        c.prepareStatement("SELECT $COLUMNS FROM study_results WHERE study_id = ? ORDER BY participant_index, participant, task_position, task, trial").use { s ->
            s.setString(1, studyId)
            s.executeQuery().use { r ->
                val rows = ArrayList<ResultRow>()
                while (r.next()) rows += readRow(r)
                rows
            }
        }
    }

    /** True when the database answers. */
    fun isHealthy(): Boolean = try {
        connect().use { it.isValid(HEALTH_TIMEOUT_SECONDS) }
    } catch (e: SQLException) {
        false
    }

    private fun find(select: java.sql.PreparedStatement, row: ResultRow): ResultRow? {
        select.setString(1, row["study_id"])
        select.setString(2, row["participant"])
        select.setString(3, row["task"])
        select.setInt(4, row["trial"].toInt())
        return select.executeQuery().use { r ->
            if (r.next()) readRow(r) else null
        }
    }

    /** The current row of [r], selected as [COLUMNS]. */
    private fun readRow(r: java.sql.ResultSet): ResultRow = ResultRow(ResultRows.HEADER.indices.map { r.getString(it + 1) })

    private fun bind(insert: java.sql.PreparedStatement, fields: List<String>) {
        for ((i, name) in ResultRows.HEADER.withIndex()) {
            if (name in ResultRows.INTEGER_COLUMNS) insert.setInt(i + 1, fields[i].toInt()) else insert.setString(i + 1, fields[i])
        }
    }

    /** A new connection to the database (the caller closes it); [CollectorTokens] keeps its table here too. */
    internal fun connect(): Connection {
        val connection = DriverManager.getConnection(jdbcUrl)
        // Uploads run on several server threads: let a SQLite writer wait for the file lock instead of failing at once.
        if (jdbcUrl.startsWith("jdbc:sqlite:")) connection.createStatement().use { it.execute("PRAGMA busy_timeout = $SQLITE_BUSY_TIMEOUT_MS") }
        return connection
    }

    companion object {
        /**
         * The JDBC URL for a `--db` value: `sqlite:PATH` or `postgresql://…` (query parameters such as
         * user and password pass through to the driver). [IllegalArgumentException] for anything else.
         */
        fun jdbcUrl(db: String): String = when {
            db.startsWith("sqlite:") && db.length > "sqlite:".length -> "jdbc:$db"
            db.startsWith("postgresql://") && db.length > "postgresql://".length -> "jdbc:$db"
            else -> throw IllegalArgumentException("--db must be sqlite:PATH or postgresql://HOST/DB?user=.., got '$db'")
        }

        private val COLUMNS = ResultRows.HEADER.joinToString(", ")
        private val CREATE_TABLE = "CREATE TABLE IF NOT EXISTS study_results (" +
            ResultRows.HEADER.joinToString(", ") { "$it ${if (it in ResultRows.INTEGER_COLUMNS) "INTEGER" else "TEXT"} NOT NULL" } +
            ", PRIMARY KEY (study_id, participant, task, trial))"
        private val INSERT = "INSERT INTO study_results ($COLUMNS) VALUES (${ResultRows.HEADER.joinToString(", ") { "?" }})"
        private val SELECT_ONE = "SELECT $COLUMNS FROM study_results WHERE study_id = ? AND participant = ? AND task = ? AND trial = ?"
        private const val HEALTH_TIMEOUT_SECONDS = 2
        private const val SQLITE_BUSY_TIMEOUT_MS = 10_000
    }
}
