package org.hapticon.companion.study

import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assume.assumeTrue
import org.junit.Test
import java.sql.DriverManager

/**
 * The collector over a real PostgreSQL, only when HAPTICON_POSTGRES_URL is set to a `--db` value such as
 * `postgresql://localhost/hapticon?user=hapticon&password=…`. Uses (and then deletes) study "pg-test".
 */
class PostgresCollectorTest {
    @Test fun uploadReUploadAndDownloadOnPostgres() {
        val db = System.getenv("HAPTICON_POSTGRES_URL")
        assumeTrue("HAPTICON_POSTGRES_URL not set: skipping the PostgreSQL collector test", !db.isNullOrBlank())
        val url = ResultStore.jdbcUrl(db!!)
        val upload = StudyResults.exampleCsv().replace("demo-study,", "pg-test,")
        val store = ResultStore(url)
        deleteStudy(url)
        try {
            CollectorHarness(store).use { h ->
                assertEquals("{\"study_id\":\"pg-test\",\"rows\":29,\"inserted\":29,\"unchanged\":0}\n", h.upload(upload, studyId = "pg-test").body())
                assertEquals("{\"study_id\":\"pg-test\",\"rows\":29,\"inserted\":0,\"unchanged\":29}\n", h.upload(upload, studyId = "pg-test").body())
                val bad = h.upload(upload.replace("2026-11-20T10:00:00Z", "never"), studyId = "pg-test")
                assertEquals(400, bad.statusCode())
                assertEquals(upload, h.get("/v1/studies/pg-test/results.csv").body())
            }
        } finally {
            deleteStudy(url)
        }
    }

    private fun deleteStudy(url: String) {
        DriverManager.getConnection(url).use { c ->
            c.prepareStatement("DELETE FROM study_results WHERE study_id = 'pg-test'").use { it.executeUpdate() }
        }
    }
}
