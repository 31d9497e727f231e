package org.hapticon.companion.study

import java.io.File
import java.net.InetSocketAddress
import java.net.Socket
import java.sql.DriverManager
import kotlinx.serialization.json.Json
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import org.hapticon.companion.cli
import org.hapticon.study.export.Csv
import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

/** The collector against hostile clients: tokens by study and role, stalled and cut-short uploads, formula cells. */
class CollectorSecurityTest {
    @get:Rule val temp = TemporaryFolder()

    private val upload = StudyResults.exampleCsv()
    private val dbFile get() = File(temp.root, "results.db")

    private fun sqlite(): ResultStore = ResultStore(ResultStore.jdbcUrl("sqlite:" + dbFile.path))

    private fun bearer(token: String) = arrayOf("Authorization", "Bearer $token")

    @Test fun tokens_roleAndStudy_uploadCannotDownload_otherStudyRefused_revokedRefused() {
        val store = sqlite()
        val tokens = CollectorTokens(store)
        val uploadA = tokens.add("demo-study", TokenRole.UPLOAD).token
        val downloadA = tokens.add("demo-study", TokenRole.DOWNLOAD)
        val uploadB = tokens.add("study-b", TokenRole.UPLOAD).token
        val downloadB = tokens.add("study-b", TokenRole.DOWNLOAD).token
        CollectorHarness(store, CollectorAccess.Tokens(tokens)).use { h ->
            val csv = "/v1/studies/demo-study/results.csv"
            assertEquals("{\"error\":\"missing bearer token\"}\n", h.upload(upload).body())
            assertEquals(401, h.upload(upload).statusCode())
            assertEquals("Bearer", h.upload(upload).headers().firstValue("WWW-Authenticate").get())
            assertEquals("{\"error\":\"unknown or revoked token\"}\n", h.upload(upload, "demo-study", "text/csv", *bearer("s3cret")).body())
            // The right id with another secret is refused: the id alone is not a credential.
            val forged = uploadA.substringBeforeLast('.') + "." + downloadA.token.substringAfterLast('.')
            assertEquals(401, h.upload(upload, "demo-study", "text/csv", *bearer(forged)).statusCode())
            // A download token cannot upload; study B's upload token cannot upload into study A.
            assertEquals("{\"error\":\"this token may only download, not upload\"}\n", h.upload(upload, "demo-study", "text/csv", *bearer(downloadA.token)).body())
            val other = h.upload(upload, "demo-study", "text/csv", *bearer(uploadB))
            assertEquals(403, other.statusCode())
            assertEquals("{\"error\":\"this token is not for study 'demo-study'\"}\n", other.body())
            assertEquals(0, store.rows("demo-study").size)

            assertEquals("{\"study_id\":\"demo-study\",\"rows\":29,\"inserted\":29,\"unchanged\":0}\n", h.upload(upload, "demo-study", "text/csv", *bearer(uploadA)).body())
            // An upload token cannot download, not even the study it uploaded to; B's download token cannot read A.
            assertEquals("{\"error\":\"this token may only upload, not download\"}\n", h.get(csv, *bearer(uploadA)).body())
            assertEquals(403, h.get(csv, *bearer(downloadB)).statusCode())
            assertEquals(401, h.get(csv).statusCode())
            assertEquals(upload, h.get(csv, *bearer(downloadA.token)).body())
            assertEquals(200, h.get("/health").statusCode()) // health stays open for monitoring

            assertTrue(tokens.revoke(downloadA.info.id))
            assertEquals("{\"error\":\"unknown or revoked token\"}\n", h.get(csv, *bearer(downloadA.token)).body())
        }
    }

    @Test fun tokens_storedAsSha256Only_theSecretIsNowhereInTheDatabase() {
        val store = sqlite()
        val issued = CollectorTokens(store).add("demo-study", TokenRole.UPLOAD)
        val secret = issued.token.substringAfterLast('.')
        assertEquals(43, secret.length) // 32 random bytes, base64url without padding
        DriverManager.getConnection("jdbc:sqlite:" + dbFile.path).use { c ->
            c.createStatement().use { s ->
                s.executeQuery("SELECT token_id, study_id, role, secret_sha256, created_at FROM collector_tokens").use { r ->
                    assertTrue(r.next())
                    assertEquals(issued.info.id, r.getString(1))
                    assertEquals("demo-study", r.getString(2))
                    assertEquals("upload", r.getString(3))
                    assertEquals(CollectorTokens.sha256Hex(secret), r.getString(4))
                    assertEquals(64, r.getString(4).length)
                    assertFalse(r.next())
                }
            }
        }
        // Not in any column, nor anywhere in the file's bytes.
        assertFalse(String(dbFile.readBytes(), Charsets.ISO_8859_1).contains(secret))
        // The same secret under another id is a different token, and a malformed one is simply unknown.
        assertNull(CollectorTokens(store).authenticate("hct1.0000000000000000.$secret"))
        assertNull(CollectorTokens(store).authenticate("hct1.${issued.info.id}"))
        assertEquals("demo-study", CollectorTokens(store).authenticate(issued.token)?.studyId)
    }

    @Test fun tokenCommands_addListRevoke_listShowsNoSecret() {
        val db = "sqlite:" + dbFile.path
        val token = cli("collect", "token", "add", "--study", "demo-study", "--role", "download", "--db", db).stdout.trim()
        val id = token.split('.')[1]
        val list = cli("collect", "token", "list", "--db", db)
        assertTrue(list.stdout, list.stdout.matches(Regex("id,study_id,role,created_at\n$id,demo-study,download,\\d{4}-\\d\\d-\\d\\dT[0-9:.]+Z\n")))
        assertEquals("collect: revoked token $id\n", cli("collect", "token", "revoke", id, "--db", db).stdout)
        assertEquals("id,study_id,role,created_at\n", cli("collect", "token", "list", "--db", db).stdout)
    }

    /**
     * Four slow-loris clients (header lines trickling in) and four stalled uploads (headers complete, half
     * the body sent) on a pool of only [CollectorLimits.MIN_THREADS] threads: `/health` still answers within 1 s.
     */
    @Test fun health_eightStalledClients_answersWithinOneSecond() {
        val limits = CollectorLimits(idleTimeoutMillis = 30_000, maxThreads = CollectorLimits.MIN_THREADS)
        CollectorHarness(sqlite(), CollectorAccess.Anonymous, limits).use { h ->
            val quietStart = System.nanoTime()
            assertEquals(200, h.get("/health").statusCode())
            val quietMillis = (System.nanoTime() - quietStart) / 1_000_000
            val stalled = ArrayList<Socket>()
            try {
                repeat(4) {
                    stalled += connect(h.server.port).apply {
                        getOutputStream().write("POST /v1/results HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/csv\r\nX-Stu".toByteArray())
                        getOutputStream().flush()
                    }
                }
                repeat(4) {
                    val body = upload.toByteArray()
                    stalled += connect(h.server.port).apply {
                        getOutputStream().write(headers(body.size).toByteArray() + body.copyOf(body.size / 2))
                        getOutputStream().flush()
                    }
                }
                Thread.sleep(200) // let the server take all eight in
                val started = System.nanoTime()
                val health = h.get("/health")
                val millis = (System.nanoTime() - started) / 1_000_000
                println("CollectorSecurityTest: GET /health on ${limits.maxThreads} threads: $quietMillis ms with no other client, $millis ms with 8 stalled clients")
                assertEquals(200, health.statusCode())
                assertTrue("GET /health took $millis ms", millis < 1_000)
                assertEquals(0, h.store.rows("demo-study").size)
            } finally {
                stalled.forEach { it.close() }
            }
        }
    }

    /** The connection bound is a hard limit: a third client waits until one of two open connections closes. */
    @Test fun rateLimit_oneAddressOverItsBurst_gets429_andIsServedAgainAfterADrip() {
        // 1 request/s with bursts of 10: of 30 back-to-back requests from 127.0.0.1 (a fraction of a second, seconds
        // on a loaded machine), the burst plus one per elapsed second get through; the rest get 429.
        CollectorHarness(sqlite(), limits = CollectorLimits(requestsPerSecondPerAddress = 1, burstPerAddress = 10)).use { h ->
            val started = System.nanoTime()
            val statuses = List(30) { h.get("/health").statusCode() }
            val seconds = (System.nanoTime() - started) / 1e9
            val served = statuses.count { it == 200 }
            assertEquals(setOf(200, 429), statuses.toSet())
            assertTrue("$served served in $seconds s", served in 10..10 + seconds.toInt() + 1)
            assertEquals(List(10) { 200 }, statuses.take(10)) // the burst first
            // A refused request leaves the bucket full (Jetty 12.1: bucket = min(size, bucket - drips + 1), served while
            // below size), so the first request after a flood needs two drips.
            Thread.sleep(2_100)
            assertEquals(200, h.get("/health").statusCode())
        }
    }

    @Test fun connections_overTheLimit_waitUntilOneCloses() {
        CollectorHarness(sqlite(), limits = CollectorLimits(maxConnections = 2, idleTimeoutMillis = 30_000)).use { h ->
            val open = List(2) { connect(h.server.port) }
            try {
                Thread.sleep(200) // both accepted
                connect(h.server.port).use { third ->
                    third.soTimeout = 500
                    third.getOutputStream().write("GET /health HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n".toByteArray())
                    val waited = runCatching { third.getInputStream().read() }
                    assertTrue("the third connection was served while two were open: $waited", waited.exceptionOrNull() is java.net.SocketTimeoutException)
                    open[0].close()
                    third.soTimeout = 5_000
                    val response = third.getInputStream().readBytes().toString(Charsets.UTF_8)
                    assertTrue(response, response.startsWith("HTTP/1.1 200 ")) // a timed-out read consumes nothing
                }
            } finally {
                open.forEach { it.close() }
            }
        }
    }

    @Test fun upload_bodyCutShort_400_nothingStored() {
        CollectorHarness(sqlite()).use { h ->
            val body = upload.toByteArray()
            connect(h.server.port).use { s ->
                s.getOutputStream().write(headers(body.size).toByteArray() + body.copyOf(body.size - 100))
                s.shutdownOutput() // the client's side ends 100 bytes early
                val response = s.getInputStream().readBytes().toString(Charsets.UTF_8)
                assertTrue(response, response.startsWith("HTTP/1.1 400 "))
                assertTrue(response, response.contains("{\"error\":\"request body cut short ("))
                assertTrue(response, response.endsWith("); nothing stored\"}\n"))
            }
            assertEquals(0, h.store.rows("demo-study").size)
            assertEquals(200, h.upload(upload).statusCode()) // and the service is fine afterwards
        }
    }

    @Test fun upload_bodyStalledPastIdleTimeout_408_nothingStored() {
        CollectorHarness(sqlite(), limits = CollectorLimits(idleTimeoutMillis = 300)).use { h ->
            val body = upload.toByteArray()
            connect(h.server.port).use { s ->
                s.getOutputStream().write(headers(body.size).toByteArray() + body.copyOf(body.size / 2))
                s.getOutputStream().flush()
                val response = s.getInputStream().readBytes().toString(Charsets.UTF_8)
                assertTrue(response, response.startsWith("HTTP/1.1 408 "))
                assertTrue(response, response.endsWith("{\"error\":\"request body stalled for 300 ms; nothing stored\"}\n"))
            }
            assertEquals(0, h.store.rows("demo-study").size)
        }
    }

    /**
     * A refusal sent before the body arrived says `Connection: close` and closes: without the header the JDK's
     * HttpClient pooled the connection Jetty was closing, and its next POST failed with "HTTP/1.1 header parser
     * received no bytes" (seen once in CI, on the token test above).
     */
    @Test fun upload_refusedBeforeItsBodyArrives_saysTheConnectionCloses() {
        val store = sqlite()
        CollectorHarness(store, CollectorAccess.Tokens(CollectorTokens(store))).use { h ->
            connect(h.server.port).use { s ->
                s.getOutputStream().write(headers(upload.toByteArray().size).toByteArray()) // no token, no body yet
                s.getOutputStream().flush()
                val response = s.getInputStream().readBytes().toString(Charsets.UTF_8) // to the server's close
                assertTrue(response, response.startsWith("HTTP/1.1 401 "))
                assertTrue(response, response.contains("\r\nConnection: close\r\n", ignoreCase = true))
            }
            assertEquals(401, h.upload(upload).statusCode()) // and the pooled client goes on
            assertEquals(401, h.upload(upload).statusCode())
        }
    }

    @Test fun upload_overTheSizeLimit_413_declaredOrChunked() {
        CollectorHarness(sqlite(), limits = CollectorLimits(maxBodyBytes = 1_000)).use { h ->
            val declared = h.upload(upload) // Content-Length 3,000-odd
            assertEquals(413, declared.statusCode())
            assertEquals("{\"error\":\"body larger than 1000 bytes\"}\n", declared.body())
            connect(h.server.port).use { s ->
                val chunk = upload.toByteArray()
                val request = "POST /v1/results HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/csv\r\nX-Study-Id: demo-study\r\n" +
                    "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n${Integer.toHexString(chunk.size)}\r\n"
                s.getOutputStream().write(request.toByteArray() + chunk + "\r\n0\r\n\r\n".toByteArray())
                s.getOutputStream().flush()
                val response = s.getInputStream().readBytes().toString(Charsets.UTF_8)
                assertTrue(response, response.startsWith("HTTP/1.1 413 "))
            }
            assertEquals(0, h.store.rows("demo-study").size)
        }
    }

    @Test fun download_formulaCells_comeBackNeutralised_storedUnchanged() {
        // Signed numbers too: `+1` and `-2` in a name or text are text to the analyst, and OWASP lists `+` and `-`.
        val hostile = listOf("=HYPERLINK(\"http://evil.example\",\"click\")", "+1+cmd|' /C calc'!A0", "-2+3", "@SUM(A1:A9)", "\tx", "\r=1+1", "+1", "-2")
        // One row per hostile text (the text column) and participant; the numbers stay numbers.
        // Written with SpreadsheetCsv.field, not SpreadsheetCsv.line, which would neutralise the cells on the way up already.
        val texts = hostile + "ok"
        val body = upload.lineSequence().first() + "\n" + texts.mapIndexed { i, text ->
            val participant = if (text.startsWith("+") || text.startsWith("-")) text else "P01"
            listOf("demo-study", "1", "processing", participant, "0", "calm", "0", "$i", "text", "", text, "", "q", "3", "10", "0", "2026-11-20T10:00:00Z")
                .joinToString(",", postfix = "\n") { SpreadsheetCsv.field(it) }
        }.joinToString("")
        CollectorHarness(sqlite()).use { h ->
            val stored = h.upload(body)
            assertEquals(stored.body(), 200, stored.statusCode())
            // Rows come back by participant; the trial number is the row's index in texts.
            assertEquals(hostile + "ok", h.store.rows("demo-study").sortedBy { it["trial"].toInt() }.map { it["text"] }) // stored as uploaded
            val records = Csv.parse(h.get("/v1/studies/demo-study/results.csv").body(), "download").drop(1)
                .sortedBy { it.fields[ResultRows.column("trial")].toInt() }
            assertEquals(hostile.map { "'$it" } + "ok", records.map { it.fields[ResultRows.column("text")] })
            assertEquals(listOf("P01", "'+1+cmd|' /C calc'!A0", "'-2+3", "P01", "P01", "P01", "'+1", "'-2", "P01"), records.map { it.fields[ResultRows.column("participant")] })
            assertEquals(List(texts.size) { "3" }, records.map { it.fields[ResultRows.column("response")] })
            assertEquals(List(texts.size) { "10" }, records.map { it.fields[ResultRows.column("response_time_ms")] })
        }
    }

    @Test fun upload_numbersOutsideDecimalDigitsOrTheScale_andUnprintableIdentifiers_refusedWithTheirLine_nothingStored() {
        // Each hostile value goes into line 3 of the example (P01 calm trial 1, response 5): one column at a time.
        fun hostile(column: String, value: String): String {
            val lines = upload.lines().toMutableList()
            val fields = Csv.parse(lines[2], "row").single().fields.toMutableList()
            fields[ResultRows.column(column)] = value
            lines[2] = fields.joinToString(",") { SpreadsheetCsv.field(it) }
            return lines.joinToString("\n")
        }
        val cases = listOf(
            // Java's Double.valueOf reads the first three as 4, 8 and 4; `analyze` would take 0x1p3 as an 8 on a 1-5 item.
            Triple("response", "4d", "response '4d' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "0x1p3", "response '0x1p3' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", " 4 ", "response ' 4 ' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "+1", "response '+1' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "-2", "response '-2' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "4.0", "response '4.0' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "04", "response '04' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "6", "response '6' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "0", "response '0' is not a whole number in 1..5 (the item's scale)"),
            Triple("response", "1e0", "response '1e0' is not a whole number in 1..5 (the item's scale)"),
            Triple("participant", "P\u000001", "participant 'P\\u000001' holds a control character (U+0000 at character 2)"),
            Triple("participant", "P01\u001b[2J", "participant 'P01\\u001b[2J' holds a control character (U+001B at character 4)"),
            Triple("participant", " P01", "participant ' P01' starts or ends with a space"),
            Triple("participant", "P01\n", "participant 'P01\\u000a' holds a control character (U+000A at character 4)"),
            Triple("icon", "hug\u202e", "icon 'hug\\u202e' holds an invisible formatting character (U+202E at character 4)"),
            Triple("text", "hi\u0007", "text 'hi\\u0007' holds a control character (U+0007 at character 3)"),
            Triple("response_time_ms", "0x10", "response_time_ms '0x10' is not a whole number ≥ 0"),
        )
        CollectorHarness(sqlite(), responses = 1..5).use { h ->
            for ((column, value, problem) in cases) {
                val response = h.upload(hostile(column, value))
                assertEquals(response.body(), 400, response.statusCode())
                val error = Json.parseToJsonElement(response.body()).jsonObject
                assertEquals("line 3: $problem", error.getValue("error").jsonPrimitive.content)
                assertEquals("3", error.getValue("line").jsonPrimitive.content)
            }
            assertEquals(0, h.store.rows("demo-study").size)
            // The untouched example, within 1..5, is stored whole; free text keeps its line breaks and tabs.
            assertEquals(200, h.upload(hostile("text", "two\nlines\tand a tab")).statusCode())
            assertEquals(29, h.store.rows("demo-study").size)
        }
    }

    private fun connect(port: Int) = Socket().apply {
        connect(InetSocketAddress("127.0.0.1", port), 2_000)
        soTimeout = 10_000
    }

    private fun headers(contentLength: Int) =
        "POST /v1/results HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/csv\r\nX-Study-Id: demo-study\r\nContent-Length: $contentLength\r\n\r\n"
}
