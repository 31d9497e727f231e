package org.hapticon.companion.study

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli
import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream
import java.net.InetAddress
import java.net.ServerSocket
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse

/** The collector over SQLite in a temporary file. */
class CollectorTest {
    @get:Rule val temp = TemporaryFolder()

    private val upload = StudyResults.exampleCsv()

    private fun sqlite(): ResultStore = ResultStore(ResultStore.jdbcUrl("sqlite:" + File(temp.root, "results.db").path))

    /** The example with line [line] (1-based, header = 1) changed by [edit]. */
    private fun editLine(line: Int, edit: (String) -> String): String =
        upload.lines().mapIndexed { i, text -> if (i == line - 1) edit(text) else text }.joinToString("\n")

    @Test fun uploadReUploadAndDownload() {
        CollectorHarness(sqlite()).use { h ->
            val first = h.upload(upload)
            assertEquals(first.body(), 200, first.statusCode())
            assertEquals("{\"study_id\":\"demo-study\",\"rows\":29,\"inserted\":29,\"unchanged\":0}\n", first.body())
            val again = h.upload(upload)
            assertEquals("{\"study_id\":\"demo-study\",\"rows\":29,\"inserted\":0,\"unchanged\":29}\n", again.body())
            assertEquals(29, h.store.rows("demo-study").size)
            val download = h.get("/v1/studies/demo-study/results.csv")
            assertEquals(200, download.statusCode())
            assertEquals("text/csv; charset=utf-8", download.headers().firstValue("Content-Type").get())
            assertEquals(upload, download.body())
            assertEquals("{\"status\":\"ok\"}\n", h.get("/health").body())
        }
    }

    @Test fun partialThenFullUploadInsertsOnlyTheNewRows() {
        CollectorHarness(sqlite()).use { h ->
            val firstHalf = upload.lines().take(11).joinToString("\n", postfix = "\n")
            assertEquals(200, h.upload(firstHalf).statusCode())
            assertEquals("{\"study_id\":\"demo-study\",\"rows\":29,\"inserted\":19,\"unchanged\":10}\n", h.upload(upload).body())
        }
    }

    @Test fun malformedRowIsRejectedAndNothingStored() {
        CollectorHarness(sqlite()).use { h ->
            val body = editLine(5) { it.replace("1-5?\",5,", "1-5?\",high,") }
            val response = h.upload(body)
            assertEquals(400, response.statusCode())
            assertEquals("{\"error\":\"line 5: response 'high' is not a whole number in 1..11 (the item's scale)\",\"line\":5}\n", response.body())
            assertEquals(0, h.store.rows("demo-study").size)
            assertEquals(404, h.get("/v1/studies/demo-study/results.csv").statusCode())
        }
    }

    @Test fun conflictingReUploadRollsBackTheWholeUpload() {
        CollectorHarness(sqlite()).use { h ->
            val firstTwo = upload.lines().take(3).joinToString("\n", postfix = "\n")
            assertEquals(200, h.upload(firstTwo).statusCode())
            // Line 3 (P01 calm trial 1) now says 3 instead of 5; line 30 is new but must not be stored either.
            val changed = editLine(3) { it.replace("1-5?\",5,", "1-5?\",3,") }
            val response = h.upload(changed)
            assertEquals(400, response.statusCode())
            assertEquals(
                "{\"error\":\"line 3: participant 'P01' task 'calm' trial 1 is already stored with different values\",\"line\":3}\n",
                response.body(),
            )
            assertEquals(2, h.store.rows("demo-study").size)
        }
    }

    @Test fun requestProblemsAreJsonErrors() {
        CollectorHarness(sqlite()).use { h ->
            assertEquals("{\"error\":\"missing X-Study-Id header\"}\n", h.upload(upload, studyId = null).body())
            val other = h.upload(upload, studyId = "other")
            assertEquals("{\"error\":\"line 2: study_id 'demo-study' does not match X-Study-Id 'other'\",\"line\":2}\n", other.body())
            assertEquals(415, h.upload(upload, contentType = "application/json").statusCode())
            assertEquals(200, h.upload(upload, contentType = "text/csv; charset=utf-8").statusCode())
            val header = h.upload("participant,task\nP1,t\n")
            assertTrue(header.body(), header.body().startsWith("{\"error\":\"line 1: header must be exactly study_id,protocol_version,"))
            assertEquals("{\"error\":\"line 1: no rows after the header\",\"line\":1}\n", h.upload(upload.lines().first() + "\n").body())
            val time = h.upload(editLine(2) { it.replace("2026-11-20T10:00:00Z", "yesterday") })
            assertEquals("{\"error\":\"line 2: answered_at 'yesterday' is not an ISO-8601 time such as 2026-11-22T02:00:00Z\",\"line\":2}\n", time.body())
            val count = h.upload(editLine(2) { it.replace("demo-study,1,processing,P01,0,", "demo-study,1,processing,P01,-1,") })
            assertEquals("{\"error\":\"line 2: participant_index '-1' is not a whole number ≥ 0\",\"line\":2}\n", count.body())
            assertEquals(404, h.get("/v1/studies/../results.csv").statusCode())
            assertEquals(405, h.get("/v1/results").statusCode())
            assertEquals(404, h.get("/healthz").statusCode())
        }
    }

    @Test fun collectCommandServesUntilStoppedAndAnalyzeReadsTheDownload() {
        val db = File(temp.root, "cli.db")
        val added = cli("collect", "token", "add", "--study", "demo-study", "--role", "upload", "--db", "sqlite:${db.path}")
        assertEquals(added.toString(), 0, added.exitCode)
        val addedDownload = cli("collect", "token", "add", "--study", "demo-study", "--role", "download", "--db", "sqlite:${db.path}")
        val uploadToken = added.stdout.trim()
        val downloadToken = addedDownload.stdout.trim()
        assertTrue(uploadToken, uploadToken.matches(Regex("hct1\\.[0-9a-f]{16}\\.[A-Za-z0-9_-]{43}")))
        assertTrue(added.stderr, added.stderr.matches(Regex("collect: upload token [0-9a-f]{16} for study 'demo-study' \\(shown once; only its SHA-256 is stored\\)\n")))
        val out = ByteArrayOutputStream()
        var downloaded = ""
        runCollect(
            listOf("--port", "0", "--db", "sqlite:${db.path}"),
            Console(PrintStream(out, true, "UTF-8"), PrintStream(ByteArrayOutputStream())),
            started = { server ->
                val client = HttpClient.newHttpClient()
                val base = "http://127.0.0.1:${server.port}"
                val post = HttpRequest.newBuilder(URI("$base/v1/results")).POST(HttpRequest.BodyPublishers.ofString(upload))
                    .header("Content-Type", "text/csv").header("X-Study-Id", "demo-study").header("Authorization", "Bearer $uploadToken").build()
                assertEquals(200, client.send(post, HttpResponse.BodyHandlers.ofString()).statusCode())
                val get = HttpRequest.newBuilder(URI("$base/v1/studies/demo-study/results.csv")).header("Authorization", "Bearer $downloadToken").build()
                downloaded = client.send(get, HttpResponse.BodyHandlers.ofString()).body()
            },
            waitForStop = {},
        )
        assertTrue(out.toString("UTF-8"), out.toString("UTF-8").matches(Regex("collect: limits: 256 connections, 10000 ms idle timeout, 16 MiB per upload, 20 requests/s per address \\(bursts of 100\\), responses 1\\.\\.11\ncollect: listening on http://127\\.0\\.0\\.1:\\d+ \\(sqlite:.*cli\\.db, 2 tokens\\); Ctrl-C stops it\n")))
        assertEquals(upload, downloaded)
        val results = temp.newFile("downloaded.csv").apply { writeText(downloaded) }
        val analysis = cli("analyze", results.path, "--out", File(temp.root, "analysis").path)
        assertEquals(analysis.toString(), 0, analysis.exitCode)
    }

    @Test fun collectWithoutTokensSaysHowToAddOne_allowAnonymousWarnsOnStderr() {
        val db = "sqlite:" + File(temp.root, "empty.db").path
        val out = ByteArrayOutputStream()
        val err = ByteArrayOutputStream()
        var status = 0
        runCollect(listOf("--port", "0", "--db", db), Console(PrintStream(out, true, "UTF-8"), PrintStream(err, true, "UTF-8")), started = { server ->
            val get = HttpRequest.newBuilder(URI("http://127.0.0.1:${server.port}/v1/studies/demo-study/results.csv")).build()
            status = HttpClient.newHttpClient().send(get, HttpResponse.BodyHandlers.ofString()).statusCode()
        }, waitForStop = {})
        assertEquals(401, status)
        assertTrue(out.toString("UTF-8"), out.toString("UTF-8").contains("no tokens yet: every /v1 request gets 401; add one with 'hapticon collect token add --study ID --role upload'"))
        assertEquals("", err.toString("UTF-8"))
        out.reset()
        runCollect(listOf("--port", "0", "--db", db, "--allow-anonymous", "--rate", "5", "--burst", "7", "--max-body-mb", "2", "--scale-points", "5"), Console(PrintStream(out, true, "UTF-8"), PrintStream(err, true, "UTF-8")), started = { server ->
            val get = HttpRequest.newBuilder(URI("http://127.0.0.1:${server.port}/v1/studies/demo-study/results.csv")).build()
            status = HttpClient.newHttpClient().send(get, HttpResponse.BodyHandlers.ofString()).statusCode()
        }, waitForStop = {})
        assertEquals(404, status) // no token needed, and no such study yet
        assertTrue(out.toString("UTF-8"), out.toString("UTF-8").contains(", anonymous access); Ctrl-C stops it"))
        assertTrue(out.toString("UTF-8"), out.toString("UTF-8").contains("collect: limits: 256 connections, 10000 ms idle timeout, 2 MiB per upload, 5 requests/s per address (bursts of 7), responses 1..5\n"))
        assertTrue(err.toString("UTF-8"), err.toString("UTF-8").startsWith("collect: WARNING: --allow-anonymous: NO AUTHENTICATION. Anyone who can reach 127.0.0.1:"))
    }

    @Test fun collectUsageErrors() {
        assertEquals(listOf("hapticon: --db must be sqlite:PATH or postgresql://HOST/DB?user=.., got 'mysql://x'"), cli("collect", "--db", "mysql://x").stderrLines)
        assertEquals(listOf("hapticon: --port must be in 0..65535, got 70000"), cli("collect", "--port", "70000").stderrLines)
        assertEquals(listOf("hapticon: --rate must be in 1..100000, got 0"), cli("collect", "--rate", "0").stderrLines)
        assertEquals(listOf("hapticon: --max-body-mb must be in 1..1024, got 2048"), cli("collect", "--max-body-mb", "2048").stderrLines)
        assertEquals(listOf("hapticon: --scale-points must be in 2..11 (a Likert item's points), got 12"), cli("collect", "--scale-points", "12").stderrLines)
        assertEquals(listOf("hapticon: unknown option --token-file for collect"), cli("collect", "--token-file", "nope").stderrLines)
        val db = "sqlite:" + File(temp.root, "tokens.db").path
        assertEquals(listOf("hapticon: collect token needs add, list or revoke"), cli("collect", "token").stderrLines)
        assertEquals(listOf("hapticon: --role must be upload or download, got 'admin'"), cli("collect", "token", "add", "--study", "s", "--role", "admin", "--db", db).stderrLines)
        assertEquals(listOf("hapticon: collect token add needs --study"), cli("collect", "token", "add", "--role", "upload", "--db", db).stderrLines)
        assertEquals(listOf("hapticon: --study must be 1-64 letters, digits, '.', '_' or '-', got '../x'"), cli("collect", "token", "add", "--study", "../x", "--role", "upload", "--db", db).stderrLines)
        assertEquals(listOf("hapticon: no token with id 'abc'"), cli("collect", "token", "revoke", "abc", "--db", db).stderrLines)
        ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { taken ->
            val busy = cli("collect", "--port", taken.localPort.toString(), "--db", "sqlite:" + File(temp.root, "busy.db").path)
            assertEquals(2, busy.exitCode)
            assertTrue(busy.stderr, busy.stderr.startsWith("hapticon: cannot listen on 127.0.0.1:${taken.localPort}: "))
        }
    }
}
