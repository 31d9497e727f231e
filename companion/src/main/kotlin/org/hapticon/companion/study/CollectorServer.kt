package org.hapticon.companion.study

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.shortNumber
import org.eclipse.jetty.http.HttpHeader
import org.eclipse.jetty.http.HttpStatus
import org.eclipse.jetty.io.Content
import org.eclipse.jetty.server.Handler
import org.eclipse.jetty.server.HttpConfiguration
import org.eclipse.jetty.server.HttpConnectionFactory
import org.eclipse.jetty.server.NetworkConnectionLimit
import org.eclipse.jetty.server.Request
import org.eclipse.jetty.server.Response
import org.eclipse.jetty.server.Server
import org.eclipse.jetty.server.ServerConnector
import org.eclipse.jetty.server.handler.DoSHandler
import org.eclipse.jetty.util.Callback
import org.eclipse.jetty.util.thread.QueuedThreadPool
import java.io.IOException
import java.nio.ByteBuffer
import java.nio.charset.CharacterCodingException
import java.nio.charset.CodingErrorAction
import java.sql.SQLException
import java.time.Duration
import java.util.concurrent.CompletionException
import java.util.concurrent.TimeoutException

/**
 * The collector's hard limits. [idleTimeoutMillis]: a connection that sends nothing for this long is closed
 * (a stalled upload gets 408 if it can still hear it). [maxConnections]: connections beyond this wait in the
 * kernel's accept queue. [maxThreads]: Jetty's pool; a request body is read without holding a thread, so a
 * stalled upload costs a connection, not a thread. [maxBodyBytes]: larger uploads get 413.
 * [requestsPerSecondPerAddress] and [burstPerAddress]: each client address may make requests at this rate
 * with bursts up to this many (a leaky bucket, Jetty's `DoSHandler`); beyond it the request gets 429 at once,
 * before authentication or any body byte is read, so one address cannot flood the token checks or the
 * database. A phone uploads once per session, so the defaults only stop floods. Behind a reverse proxy every
 * request comes from the proxy's address: then set the limit there (docs/security.md).
 */
class CollectorLimits(
    val idleTimeoutMillis: Long = 10_000,
    val maxConnections: Int = 256,
    val maxThreads: Int = 32,
    val maxBodyBytes: Int = 16 shl 20,
    val requestsPerSecondPerAddress: Int = 20,
    val burstPerAddress: Int = 100,
) {
    init {
        require(idleTimeoutMillis > 0) { "idle timeout must be > 0 ms" }
        require(maxConnections > 0) { "at least one connection" }
        require(maxThreads >= MIN_THREADS) { "Jetty needs at least $MIN_THREADS threads (acceptor, selector, requests)" }
        require(maxBodyBytes > 0) { "body limit must be > 0 bytes" }
        require(requestsPerSecondPerAddress > 0) { "rate limit must be > 0 requests per second" }
        require(burstPerAddress > 0) { "burst must be > 0 requests" }
    }

    companion object {
        /** One acceptor, one selector and a few request threads. */
        const val MIN_THREADS: Int = 8
    }
}

/** Who may use the `/v1` endpoints: holders of a [CollectorTokens] token, or (only when chosen explicitly) anybody. */
sealed interface CollectorAccess {
    /** Each request needs `Authorization: Bearer TOKEN`, of the right role, for the study it touches. */
    class Tokens(val tokens: CollectorTokens) : CollectorAccess

    /** No authentication at all: `hapticon collect --allow-anonymous`, logged loudly. */
    data object Anonymous : CollectorAccess
}

/**
 * The study collector's HTTP service on [host]:[port] (0 picks a free port, see [port]) over [store]:
 * `POST /v1/results` (text/csv body, `X-Study-Id` header, an upload token of that study) stores an upload in
 * one transaction, `GET /v1/studies/{id}/results.csv` (a download token of that study) serves a study's rows
 * with formula-like cells neutralised ([SpreadsheetCsv.neutralise]), `GET /health` answers `{"status":"ok"}` to anybody.
 * Errors are JSON `{"error": …}`: 401 without a valid token, 403 for a token of another role or study.
 *
 * Jetty 12 (core handlers, no servlet API): its NIO connector parses headers without a thread per
 * connection, so slow clients cannot exhaust a pool as they did the JDK's `HttpServer` with 4 threads; the
 * body is read asynchronously under [CollectorLimits] (idle timeout, connection limit, size limit).
 */
class CollectorServer(
    private val store: ResultStore,
    private val access: CollectorAccess,
    host: String,
    port: Int,
    private val limits: CollectorLimits = CollectorLimits(),
    /** The responses an item may have: `--scale-points N` makes it 1..N; by default any Likert item Hapticon runs. */
    private val responses: IntRange = ResultRows.ANY_SCALE,
) {
    private val pool = QueuedThreadPool(limits.maxThreads, MIN_IDLE_THREADS).apply {
        name = "collector"
        isDaemon = true // a server left running must not keep a finished command's JVM alive
    }
    private val server = Server(pool)
    private val connector = ServerConnector(server, 1, 1, HttpConnectionFactory(HttpConfiguration().apply { sendServerVersion = false }))

    init {
        quietJettyLogging()
        connector.host = host
        connector.port = port
        connector.idleTimeout = limits.idleTimeoutMillis
        server.addConnector(connector)
        server.addBean(NetworkConnectionLimit(limits.maxConnections, connector))
        // Tracks at most MAX_TRACKED_ADDRESSES addresses at once (idle ones are forgotten after a few seconds);
        // beyond that Jetty refuses new addresses too, so a spoofing flood cannot grow the table without bound.
        server.handler = DoSHandler(
            Routes(),
            DoSHandler.ID_FROM_REMOTE_ADDRESS,
            // Jetty refuses the request that fills the bucket (12.1.14: `++bucket >= size`), so size = burst + 1.
            DoSHandler.LeakingBucketTrackerFactory(limits.requestsPerSecondPerAddress, limits.burstPerAddress + 1, Duration.ofSeconds(10)),
            DoSHandler.StatusRejectHandler(HttpStatus.TOO_MANY_REQUESTS_429),
            MAX_TRACKED_ADDRESSES,
        )
        server.stopTimeout = STOP_TIMEOUT_MILLIS
    }

    /** The port the service listens on (after [start]). */
    val port: Int get() = connector.localPort

    /** Starts serving; [IOException] when the address cannot be bound. */
    fun start() {
        try {
            server.start()
        } catch (e: IOException) {
            server.stop()
            throw IOException(e.cause?.message ?: e.message, e)
        }
    }

    /**
     * Stops serving at once: an upload in progress is rolled back and its client gets no 200, so it uploads
     * again (idempotent). No graceful wait: Jetty's would wait for every idle keep-alive connection to close.
     */
    fun stop() = server.stop()

    private class Reply(val status: Int, val contentType: String, val body: ByteArray)

    private inner class Routes : Handler.Abstract() {
        override fun handle(request: Request, response: Response, callback: Callback): Boolean {
            val path = request.httpURI.path
            when {
                path == "/health" -> send(response, callback, guarded { health(request) })
                path == "/v1/results" -> upload(request, response, callback)
                path.startsWith("/v1/studies/") -> send(response, callback, guarded { download(request, path) })
                else -> send(response, callback, error(404, "no such resource"))
            }
            return true
        }
    }

    private fun json(status: Int, vararg members: Pair<String, JsonElement>): Reply =
        Reply(status, "application/json", (SchemaJson.encodeElement(JsonObject(linkedMapOf(*members))) + "\n").toByteArray(Charsets.UTF_8))

    private fun error(status: Int, message: String, line: Int? = null): Reply =
        if (line == null) json(status, "error" to JsonPrimitive(message)) else json(status, "error" to JsonPrimitive(message), "line" to shortNumber(line.toDouble()))

    private fun health(request: Request): Reply {
        if (request.method != "GET") return error(405, "use GET")
        return if (store.isHealthy()) json(200, "status" to JsonPrimitive("ok")) else error(503, "database unavailable")
    }

    private fun upload(request: Request, response: Response, callback: Callback) {
        var studyId = ""
        val refused = guarded {
            if (request.method != "POST") return@guarded error(405, "use POST")
            val contentType = request.headers[HttpHeader.CONTENT_TYPE]?.substringBefore(';')?.trim()?.lowercase()
            if (contentType != "text/csv") return@guarded error(415, "Content-Type must be text/csv, got '${contentType.orEmpty()}'")
            studyId = request.headers["X-Study-Id"]?.trim() ?: return@guarded error(400, "missing X-Study-Id header")
            if (!ResultRows.STUDY_ID.matches(studyId)) return@guarded error(400, "X-Study-Id must be 1-64 letters, digits, '.', '_' or '-'")
            authorize(request, TokenRole.UPLOAD, studyId)?.let { return@guarded it }
            if (request.headers.getLongField(HttpHeader.CONTENT_LENGTH) > limits.maxBodyBytes) return@guarded tooLarge()
            null
        }
        // Refused before its body was read: say the connection closes (RFC 9112 §9.6). Jetty closes it anyway when
        // the unread body has not arrived, but the reply is already sent without that header then, so a client
        // (the JDK's HttpClient) pooled the connection and its next POST failed with "received no bytes".
        if (refused != null) return send(response, callback, refused, closeConnection = true)
        // Read the whole body without holding a thread, then parse and store it on the pool: a client that
        // stalls mid-body costs one connection until the idle timeout, and nothing is stored from a partial body.
        Content.Source.asByteArrayAsync(request, limits.maxBodyBytes).whenCompleteAsync({ bytes, failure ->
            // A body that failed (cut short, stalled, too large) leaves the connection in an unknown state: close it.
            if (failure != null) send(response, callback, bodyFailed(failure), closeConnection = true)
            else send(response, callback, guarded { store(bytes, studyId) })
        }, pool)
    }

    private fun store(bytes: ByteArray, studyId: String): Reply {
        val text = try {
            Charsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT)
                .decode(ByteBuffer.wrap(bytes)).toString()
        } catch (e: CharacterCodingException) {
            return error(400, "body is not UTF-8")
        }
        return try {
            val upload = ResultRows.parse(text, studyId, responses)
            val outcome = store.store(upload.rows, upload.lines)
            json(
                200, "study_id" to JsonPrimitive(studyId), "rows" to shortNumber(upload.rows.size.toDouble()),
                "inserted" to shortNumber(outcome.inserted.toDouble()), "unchanged" to shortNumber(outcome.unchanged.toDouble()),
            )
        } catch (e: InvalidUploadException) {
            error(400, e.message.orEmpty(), e.line)
        }
    }

    /** Why reading a body failed: cut short (400), stalled past the idle timeout (408) or over the limit (413). */
    private fun bodyFailed(failure: Throwable): Reply {
        val cause = if (failure is CompletionException) failure.cause ?: failure else failure
        return when {
            cause is TimeoutException || cause.cause is TimeoutException ->
                error(408, "request body stalled for ${limits.idleTimeoutMillis} ms; nothing stored")
            cause is IOException -> error(400, "request body cut short (${cause.message ?: cause.javaClass.simpleName}); nothing stored")
            // Content.Source.asByteArrayAsync's maxSize (Jetty 12.1 ContentSourceRetainableByteBuffer: "… exceeded").
            cause is IllegalStateException && cause.message.orEmpty().endsWith("exceeded") -> tooLarge()
            else -> error(400, "request body unreadable (${cause.javaClass.simpleName}); nothing stored")
        }
    }

    private fun tooLarge() = error(413, "body larger than ${limits.maxBodyBytes} bytes")

    private fun download(request: Request, path: String): Reply {
        if (request.method != "GET") return error(405, "use GET")
        val match = DOWNLOAD_PATH.matchEntire(path) ?: return error(404, "no such resource")
        val studyId = match.groupValues[1]
        authorize(request, TokenRole.DOWNLOAD, studyId)?.let { return it }
        val rows = store.rows(studyId)
        if (rows.isEmpty()) return error(404, "no results for study '$studyId'")
        return Reply(200, "text/csv; charset=utf-8", ResultRows.format(rows).toByteArray(Charsets.UTF_8))
    }

    /** Null when [request] may act as [role] on [studyId]; else the 401 or 403 reply. */
    private fun authorize(request: Request, role: TokenRole, studyId: String): Reply? {
        val tokens = when (access) {
            CollectorAccess.Anonymous -> return null
            is CollectorAccess.Tokens -> access.tokens
        }
        val header = request.headers[HttpHeader.AUTHORIZATION]?.trim().orEmpty()
        if (!header.startsWith("Bearer ", ignoreCase = true)) return error(401, "missing bearer token")
        val token = tokens.authenticate(header.substring("Bearer ".length).trim()) ?: return error(401, "unknown or revoked token")
        // The same answer for another study's token whatever that study is, so tokens cannot probe for studies.
        if (token.studyId != studyId) return error(403, "this token is not for study '$studyId'")
        if (token.role != role) return error(403, "this token may only ${token.role.word}, not ${role.word}")
        return null
    }

    private inline fun guarded(handle: () -> Reply?): Reply? = try {
        handle()
    } catch (e: SQLException) {
        error(503, "database error: ${e.message?.lineSequence()?.firstOrNull().orEmpty()}")
    } catch (e: Exception) {
        error(500, "internal error: ${e.javaClass.simpleName}")
    }

    private fun send(response: Response, callback: Callback, reply: Reply?, closeConnection: Boolean = false) {
        val r = reply ?: error(500, "internal error: no reply")
        response.status = r.status
        if (closeConnection) response.headers.put(HttpHeader.CONNECTION, "close")
        response.headers.put(HttpHeader.CONTENT_TYPE, r.contentType)
        if (r.status == 401) response.headers.put(HttpHeader.WWW_AUTHENTICATE, "Bearer")
        response.write(true, ByteBuffer.wrap(r.body), callback) // a client that went away fails the callback; nothing to tell it
    }

    companion object {
        private const val MIN_IDLE_THREADS = 4
        private const val STOP_TIMEOUT_MILLIS = 0L
        private const val MAX_TRACKED_ADDRESSES = 10_000
        private val DOWNLOAD_PATH = Regex("/v1/studies/([A-Za-z0-9._-]{1,64})/results\\.csv")

        /**
         * Jetty logs through SLF4J, and HiveMQ's jar (on the companion's classpath for `hapticon broker`)
         * brings a logback.xml that prints INFO to stdout, which belongs to the command: warnings only.
         */
        private fun quietJettyLogging() {
            (org.slf4j.LoggerFactory.getLogger("org.eclipse.jetty") as? ch.qos.logback.classic.Logger)?.level = ch.qos.logback.classic.Level.WARN
        }
    }
}
