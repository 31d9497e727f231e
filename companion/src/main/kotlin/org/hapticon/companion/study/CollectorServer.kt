package org.hapticon.companion.study

import com.sun.net.httpserver.HttpExchange
import com.sun.net.httpserver.HttpServer
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue
import java.io.IOException
import java.net.InetSocketAddress
import java.nio.charset.CharacterCodingException
import java.nio.charset.CodingErrorAction
import java.security.MessageDigest
import java.sql.SQLException
import java.util.concurrent.Executors

/**
 * The study collector's HTTP service on [host]:[port] (0 picks a free port, see [port]) over [store]:
 * `POST /v1/results` (text/csv body, `X-Study-Id` header) stores an upload in one transaction,
 * `GET /v1/studies/{id}/results.csv` serves a study's rows, `GET /health` answers `{"status":"ok"}`.
 * With a [token], the /v1 endpoints need `Authorization: Bearer TOKEN`. Errors are JSON `{"error": …}`.
 */
class CollectorServer(private val store: ResultStore, host: String, port: Int, private val token: String?) {
    private val server: HttpServer = HttpServer.create(InetSocketAddress(host, port), 0)
    private val executor = Executors.newFixedThreadPool(THREADS)

    init {
        server.executor = executor
        server.createContext("/health") { exchange -> respond(exchange) { health(exchange) } }
        server.createContext("/v1/results") { exchange -> respond(exchange) { authorized(exchange) { upload(exchange) } } }
        server.createContext("/v1/studies/") { exchange -> respond(exchange) { authorized(exchange) { download(exchange) } } }
    }

    /** The port the service listens on. */
    val port: Int get() = server.address.port

    /** Starts serving. */
    fun start() = server.start()

    /** Stops serving, letting requests in progress finish for up to a second. */
    fun stop() {
        server.stop(1)
        executor.shutdown()
    }

    private class Reply(val status: Int, val contentType: String, val body: ByteArray)

    private fun json(status: Int, vararg members: Pair<String, JsonValue>): Reply =
        Reply(status, "application/json", (Json.encode(JsonObject(linkedMapOf(*members))) + "\n").toByteArray(Charsets.UTF_8))

    private fun error(status: Int, message: String, line: Int? = null): Reply =
        if (line == null) json(status, "error" to JsonString(message)) else json(status, "error" to JsonString(message), "line" to JsonNumber(line.toDouble()))

    private fun health(exchange: HttpExchange): Reply {
        if (exchange.requestURI.path != "/health") return error(404, "no such resource")
        if (exchange.requestMethod != "GET") return error(405, "use GET")
        return if (store.isHealthy()) json(200, "status" to JsonString("ok")) else error(503, "database unavailable")
    }

    private fun upload(exchange: HttpExchange): Reply {
        if (exchange.requestMethod != "POST") return error(405, "use POST")
        if (exchange.requestURI.path != "/v1/results") return error(404, "no such resource")
        val contentType = exchange.requestHeaders.getFirst("Content-Type")?.substringBefore(';')?.trim()?.lowercase()
        if (contentType != "text/csv") return error(415, "Content-Type must be text/csv, got '${contentType.orEmpty()}'")
        val studyId = exchange.requestHeaders.getFirst("X-Study-Id")?.trim()
            ?: return error(400, "missing X-Study-Id header")
        if (!ResultRows.STUDY_ID.matches(studyId)) return error(400, "X-Study-Id must be 1-64 letters, digits, '.', '_' or '-'")
        val bytes = exchange.requestBody.use { it.readNBytes(MAX_BODY_BYTES + 1) }
        if (bytes.size > MAX_BODY_BYTES) return error(413, "body larger than $MAX_BODY_BYTES bytes")
        val text = try {
            Charsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT)
                .decode(java.nio.ByteBuffer.wrap(bytes)).toString()
        } catch (e: CharacterCodingException) {
            return error(400, "body is not UTF-8")
        }
        return try {
            val upload = ResultRows.parse(text, studyId)
            val outcome = store.store(upload.rows, upload.lines)
            json(
                200, "study_id" to JsonString(studyId), "rows" to JsonNumber(upload.rows.size.toDouble()),
                "inserted" to JsonNumber(outcome.inserted.toDouble()), "unchanged" to JsonNumber(outcome.unchanged.toDouble()),
            )
        } catch (e: InvalidUploadException) {
            error(400, e.message.orEmpty(), e.line)
        }
    }

    private fun download(exchange: HttpExchange): Reply {
        if (exchange.requestMethod != "GET") return error(405, "use GET")
        val match = DOWNLOAD_PATH.matchEntire(exchange.requestURI.path) ?: return error(404, "no such resource")
        val rows = store.rows(match.groupValues[1])
        if (rows.isEmpty()) return error(404, "no results for study '${match.groupValues[1]}'")
        return Reply(200, "text/csv; charset=utf-8", ResultRows.format(rows).toByteArray(Charsets.UTF_8))
    }

    private inline fun authorized(exchange: HttpExchange, handle: () -> Reply): Reply {
        if (token == null) return handle()
        val given = exchange.requestHeaders.getFirst("Authorization")?.removePrefix("Bearer ")?.trim().orEmpty()
        // Constant-time comparison: the time taken must not tell how much of a guessed token was right.
        if (!MessageDigest.isEqual(given.toByteArray(), token.toByteArray())) {
            return error(401, "missing or wrong bearer token")
        }
        return handle()
    }

    private fun respond(exchange: HttpExchange, handle: () -> Reply) {
        val reply = try {
            handle()
        } catch (e: SQLException) {
            error(503, "database error: ${e.message?.lineSequence()?.firstOrNull().orEmpty()}")
        } catch (e: Exception) {
            error(500, "internal error: ${e.javaClass.simpleName}")
        }
        try {
            exchange.responseHeaders.set("Content-Type", reply.contentType)
            if (reply.status == 401) exchange.responseHeaders.set("WWW-Authenticate", "Bearer")
            exchange.sendResponseHeaders(reply.status, reply.body.size.toLong())
            exchange.responseBody.use { it.write(reply.body) }
        } catch (e: IOException) {
            // The client went away; nothing to tell it.
        } finally {
            exchange.close()
        }
    }

    companion object {
        /** Largest upload accepted: a whole study's results are a few hundred kilobytes. */
        const val MAX_BODY_BYTES: Int = 16 shl 20
        private const val THREADS = 4
        private val DOWNLOAD_PATH = Regex("/v1/studies/([A-Za-z0-9._-]{1,64})/results\\.csv")
    }
}
