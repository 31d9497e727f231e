package org.hapticon.companion.study

import org.hapticon.companion.Arguments
import org.hapticon.companion.Console
import org.hapticon.companion.UsageException
import java.io.File
import java.io.IOException
import java.sql.SQLException

/** The port `hapticon collect` listens on unless told otherwise. */
const val DEFAULT_COLLECT_PORT: Int = 8080

/** The database `hapticon collect` uses unless told otherwise: a SQLite file in the working directory. */
const val DEFAULT_COLLECT_DB: String = "sqlite:hapticon-results.db"

/**
 * `hapticon collect [--port N] [--host H] [--db sqlite:PATH|postgresql://HOST/DB?user=..] [--token-file F]`:
 * runs the [CollectorServer] in the foreground until the process is stopped; [waitForStop] blocks until
 * then (tests pass their own and get the started server through [started]).
 */
fun runCollect(
    args: List<String>,
    console: Console,
    started: (CollectorServer) -> Unit = {},
    waitForStop: () -> Unit = { Thread.currentThread().join() },
) {
    val arguments = Arguments.parse("collect", args, valueOptions = setOf("port", "host", "db", "token-file"))
    arguments.requireNoPositionals()
    val port = arguments.int("port", DEFAULT_COLLECT_PORT)
    if (port !in 0..65_535) throw UsageException("--port must be in 0..65535, got $port")
    val host = arguments.value("host") ?: "127.0.0.1"
    val db = arguments.value("db") ?: DEFAULT_COLLECT_DB
    val token = arguments.value("token-file")?.let { readToken(it) }
    val jdbcUrl = try {
        ResultStore.jdbcUrl(db)
    } catch (e: IllegalArgumentException) {
        throw UsageException(e.message.orEmpty())
    }
    val store = try {
        ResultStore(jdbcUrl)
    } catch (e: SQLException) {
        throw UsageException("cannot open database $db: ${e.message?.lineSequence()?.firstOrNull()}")
    }
    val server = try {
        CollectorServer(store, host, port, token)
    } catch (e: IOException) {
        throw UsageException("cannot listen on $host:$port: ${e.message}")
    }
    server.start()
    val hook = Thread { server.stop() }
    Runtime.getRuntime().addShutdownHook(hook)
    val auth = if (token == null) "no token" else "bearer token required"
    console.out.println("collect: listening on http://$host:${server.port} (${dbLabel(db)}, $auth); Ctrl-C stops it")
    console.out.flush()
    try {
        started(server)
        waitForStop()
    } finally {
        Runtime.getRuntime().removeShutdownHook(hook)
        server.stop()
    }
}

/** The database for the log line, without the query string that may hold a password. */
private fun dbLabel(db: String): String = db.substringBefore('?')

private fun readToken(path: String): String {
    val file = File(path)
    if (!file.isFile) throw UsageException("--token-file: no such file: $file")
    val token = try {
        file.readText(Charsets.UTF_8).trim()
    } catch (e: IOException) {
        throw UsageException("cannot read $file: ${e.message}")
    }
    if (token.isEmpty()) throw UsageException("--token-file: $file is empty")
    if (token.any { it.isWhitespace() }) throw UsageException("--token-file: $file must hold one token without spaces")
    return token
}
