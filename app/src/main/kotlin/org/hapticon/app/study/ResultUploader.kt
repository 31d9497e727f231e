package org.hapticon.app.study

import java.io.IOException
import java.net.HttpRetryException
import java.net.HttpURLConnection
import java.net.URI
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.Json

/** The outcome of an upload. */
sealed interface UploadResult {
    /** The collector took the CSV. */
    data class Uploaded(val message: String) : UploadResult

    /** It did not: [message] says why (the collector's error, the HTTP status, or the network failure). */
    data class Failed(val message: String) : UploadResult
}

/** Sends results to the study collector service. */
fun interface ResultUploader {
    /** POSTs [csv] for [studyId] to [url]; never throws. */
    suspend fun upload(url: String, token: String, studyId: String, csv: String): UploadResult
}

/**
 * [ResultUploader] for `hapticon collect`: `POST {url}/v1/results` with the long-format CSV as `text/csv`, the study
 * id in `X-Study-Id` and the study's upload token as `Authorization: Bearer` (made with `hapticon collect token add
 * --study ID --role upload`; sent only when set, for a collector run with `--allow-anonymous`). 200 is success;
 * 400 carries `{"error": "..."}`; 401 (no or unknown token) and 403 (a download token, or another study's) get a
 * message saying which token to enter. Runs on Dispatchers.IO with [connectTimeoutMillis] and [readTimeoutMillis].
 */
class HttpResultUploader(
    private val connectTimeoutMillis: Int = 10_000,
    private val readTimeoutMillis: Int = 30_000,
) : ResultUploader {
    override suspend fun upload(url: String, token: String, studyId: String, csv: String): UploadResult = withContext(Dispatchers.IO) {
        val endpoint = try {
            resultsUrl(url)
        } catch (e: IllegalArgumentException) {
            return@withContext UploadResult.Failed(e.message.orEmpty())
        }
        try {
            val connection = endpoint.openConnection() as HttpURLConnection
            try {
                connection.requestMethod = "POST"
                connection.connectTimeout = connectTimeoutMillis
                connection.readTimeout = readTimeoutMillis
                connection.doOutput = true
                connection.setRequestProperty("Content-Type", "text/csv; charset=utf-8")
                connection.setRequestProperty("X-Study-Id", studyId)
                if (token.isNotBlank()) connection.setRequestProperty("Authorization", "Bearer ${token.trim()}")
                val body = csv.toByteArray(Charsets.UTF_8)
                connection.setFixedLengthStreamingMode(body.size)
                connection.outputStream.use { it.write(body) }
                val status = try {
                    connection.responseCode
                } catch (e: HttpRetryException) {
                    // The JDK's HttpURLConnection (Robolectric, desktop) cannot re-send a streamed body for
                    // authentication and throws on 401 instead of returning it; Android's returns 401.
                    e.responseCode()
                }
                val text = if (status == 200) "" else runCatching { connection.errorStream?.use { it.readBytes().decodeToString() } }.getOrNull().orEmpty()
                when (status) {
                    200 -> UploadResult.Uploaded("uploaded to ${endpoint.host}")
                    401 -> UploadResult.Failed(
                        if (token.isBlank()) "the collector needs a token: enter the upload token of study '$studyId' and upload again"
                        else "the collector does not know this token (revoked, mistyped or from another collector): enter the upload token of study '$studyId' and upload again",
                    )
                    403 -> UploadResult.Failed("the collector refused this token (${errorOf(text)}): enter the upload token of study '$studyId' and upload again")
                    else -> UploadResult.Failed("collector answered $status: ${errorOf(text)}")
                }
            } finally {
                connection.disconnect()
            }
        } catch (e: IOException) {
            UploadResult.Failed("upload failed: ${e.message ?: e.javaClass.simpleName}")
        }
    }

    companion object {
        /** `{url}/v1/results` for a collector base URL. Throws [IllegalArgumentException] for a URL that is not http(s). */
        fun resultsUrl(url: String): java.net.URL {
            val base = url.trim().trimEnd('/')
            require(base.startsWith("http://") || base.startsWith("https://")) { "the collector URL must start with http:// or https://, got \"${url.take(80)}\"" }
            return try {
                URI("$base/v1/results").toURL()
            } catch (e: Exception) {
                throw IllegalArgumentException("not a valid collector URL: \"${url.take(80)}\"")
            }
        }

        private fun errorOf(body: String): String {
            val error = runCatching { ((Json.decode(body) as JsonObject)["error"] as JsonPrimitive).takeIf { it.isString }?.content }.getOrNull()
            return error ?: body.take(200).ifBlank { "no details" }
        }
    }
}
