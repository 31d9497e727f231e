package org.hapticon.companion.study

import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse

/**
 * A [CollectorServer] on a free port of 127.0.0.1 over [store] with [access] (anonymous unless a test is about
 * tokens), [limits] and the item's [responses], and an HTTP client for it.
 */
class CollectorHarness(
    val store: ResultStore,
    access: CollectorAccess = CollectorAccess.Anonymous,
    limits: CollectorLimits = CollectorLimits(),
    responses: IntRange = ResultRows.ANY_SCALE,
) : AutoCloseable {
    val server = CollectorServer(store, access, "127.0.0.1", 0, limits, responses).also { it.start() }
    private val client = HttpClient.newHttpClient()
    private val base = "http://127.0.0.1:${server.port}"

    /** POST /v1/results with [body] as [contentType] for [studyId]; extra [headers] as name, value pairs. */
    fun upload(body: String, studyId: String? = "demo-study", contentType: String = "text/csv", vararg headers: String): HttpResponse<String> {
        val request = HttpRequest.newBuilder(URI("$base/v1/results")).POST(HttpRequest.BodyPublishers.ofString(body)).header("Content-Type", contentType)
        if (studyId != null) request.header("X-Study-Id", studyId)
        if (headers.isNotEmpty()) request.headers(*headers)
        return client.send(request.build(), HttpResponse.BodyHandlers.ofString())
    }

    /** GET [path]. */
    fun get(path: String, vararg headers: String): HttpResponse<String> {
        val request = HttpRequest.newBuilder(URI("$base$path")).GET()
        if (headers.isNotEmpty()) request.headers(*headers)
        return client.send(request.build(), HttpResponse.BodyHandlers.ofString())
    }

    override fun close() = server.stop()
}
