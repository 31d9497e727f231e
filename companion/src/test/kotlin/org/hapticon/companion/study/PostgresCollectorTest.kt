package org.hapticon.companion.study

import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.fail
import org.junit.Assume.assumeTrue
import org.junit.Test
import java.sql.DriverManager

/**
 * The collector over a real PostgreSQL, when HAPTICON_POSTGRES_URL is set to a `--db` value such as
 * `postgresql://localhost/hapticon?user=hapticon&password=…` (`.ci/run` starts one and sets it). Without it the
 * test is skipped, except on CI (CI=true), where it fails: the scale-out path must be proven on every run.
 * Uses (and then deletes) study "pg-test" and its tokens.
 */
class PostgresCollectorTest {
    @Test fun uploadReUploadAndDownloadOnPostgres_withTokensInTheSameDatabase() {
        val db = System.getenv("HAPTICON_POSTGRES_URL")
        if (db.isNullOrBlank() && System.getenv("CI") == "true") fail("HAPTICON_POSTGRES_URL not set; CI must run the PostgreSQL collector test (.ci/postgres.sh)")
        assumeTrue("HAPTICON_POSTGRES_URL not set: skipping the PostgreSQL collector test", !db.isNullOrBlank())
        val url = ResultStore.jdbcUrl(db!!)
        val upload = StudyResults.exampleCsv().replace("demo-study,", "pg-test,")
        val store = ResultStore(url)
        val tokens = CollectorTokens(store)
        deleteStudy(url)
        try {
            val up = arrayOf("Authorization", "Bearer " + tokens.add("pg-test", TokenRole.UPLOAD).token)
            val issued = tokens.add("pg-test", TokenRole.DOWNLOAD)
            val down = arrayOf("Authorization", "Bearer " + issued.token)
            CollectorHarness(store, CollectorAccess.Tokens(tokens)).use { h ->
                assertEquals(401, h.upload(upload, "pg-test").statusCode())
                assertEquals("{\"study_id\":\"pg-test\",\"rows\":29,\"inserted\":29,\"unchanged\":0}\n", h.upload(upload, "pg-test", "text/csv", *up).body())
                assertEquals("{\"study_id\":\"pg-test\",\"rows\":29,\"inserted\":0,\"unchanged\":29}\n", h.upload(upload, "pg-test", "text/csv", *up).body())
                val bad = h.upload(upload.replace("2026-11-20T10:00:00Z", "never"), "pg-test", "text/csv", *up)
                assertEquals(400, bad.statusCode())
                assertEquals(403, h.get("/v1/studies/pg-test/results.csv", *up).statusCode())
                assertEquals(upload, h.get("/v1/studies/pg-test/results.csv", *down).body())
            }
            DriverManager.getConnection(url).use { c ->
                c.prepareStatement("SELECT secret_sha256 FROM collector_tokens WHERE token_id = ?").use { s ->
                    s.setString(1, issued.info.id)
                    s.executeQuery().use { r ->
                        r.next()
                        assertEquals(CollectorTokens.sha256Hex(issued.token.substringAfterLast('.')), r.getString(1))
                        assertFalse(r.next())
                    }
                }
            }
        } finally {
            deleteStudy(url)
        }
    }

    private fun deleteStudy(url: String) {
        DriverManager.getConnection(url).use { c ->
            c.prepareStatement("DELETE FROM study_results WHERE study_id = 'pg-test'").use { it.executeUpdate() }
            c.prepareStatement("DELETE FROM collector_tokens WHERE study_id = 'pg-test'").use { it.executeUpdate() }
        }
    }
}
