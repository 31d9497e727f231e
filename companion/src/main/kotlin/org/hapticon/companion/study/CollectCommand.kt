package org.hapticon.companion.study

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.study.LikertScale
import java.io.IOException
import java.sql.SQLException

/** The port `hapticon collect` listens on unless told otherwise. */
const val DEFAULT_COLLECT_PORT: Int = 8080

/** The database `hapticon collect` uses unless told otherwise: a SQLite file in the working directory. */
const val DEFAULT_COLLECT_DB: String = "sqlite:hapticon-results.db"

/** [CollectorLimits] from the command line: each option within a range that keeps the service usable. */
private fun limits(arguments: Arguments): CollectorLimits {
    val defaults = CollectorLimits()
    fun bounded(name: String, default: Int, range: IntRange): Int =
        arguments.int(name, default).also { if (it !in range) throw UsageException("--$name must be in ${range.first}..${range.last}, got $it") }
    return CollectorLimits(
        idleTimeoutMillis = bounded("idle-timeout-ms", defaults.idleTimeoutMillis.toInt(), 100..600_000).toLong(),
        maxConnections = bounded("max-connections", defaults.maxConnections, 1..100_000),
        maxBodyBytes = bounded("max-body-mb", defaults.maxBodyBytes shr 20, 1..1024) shl 20,
        requestsPerSecondPerAddress = bounded("rate", defaults.requestsPerSecondPerAddress, 1..100_000),
        burstPerAddress = bounded("burst", defaults.burstPerAddress, 1..1_000_000),
    )
}

/**
 * `hapticon collect [--port N] [--host H] [--db sqlite:PATH|postgresql://HOST/DB?user=..] [--allow-anonymous]
 * [--max-connections N] [--idle-timeout-ms N] [--max-body-mb N] [--rate N] [--burst N] [--scale-points N]`:
 * runs the [CollectorServer] in the foreground until the process is stopped; [waitForStop] blocks until
 * then (tests pass their own and get the started server through [started]).
 * `--scale-points N` refuses responses outside 1..N (default [LikertScale.MAX_POINTS], the widest item a
 * protocol may ask). `hapticon collect token add|list|revoke …` manages the tokens in the same database ([runToken]).
 */
fun runCollect(
    args: List<String>,
    console: Console,
    started: (CollectorServer) -> Unit = {},
    waitForStop: () -> Unit = { Thread.currentThread().join() },
) {
    if (args.firstOrNull() == "token") return runToken(args.drop(1), console)
    val arguments = Arguments.parse(
        "collect",
        args,
        valueOptions = setOf("port", "host", "db", "max-connections", "idle-timeout-ms", "max-body-mb", "rate", "burst", "scale-points"),
        flagOptions = setOf("allow-anonymous"),
    )
    arguments.requireNoPositionals()
    val limits = limits(arguments)
    val points = arguments.int("scale-points", LikertScale.MAX_POINTS)
    if (points !in 2..LikertScale.MAX_POINTS) throw UsageException("--scale-points must be in 2..${LikertScale.MAX_POINTS} (a Likert item's points), got $points")
    val port = arguments.int("port", DEFAULT_COLLECT_PORT)
    if (port !in 0..65_535) throw UsageException("--port must be in 0..65535, got $port")
    val host = arguments.value("host") ?: "127.0.0.1"
    val db = arguments.value("db") ?: DEFAULT_COLLECT_DB
    val store = openStore(db)
    val tokens = openTokens(store, db)
    val anonymous = arguments.flag("allow-anonymous")
    val server = CollectorServer(store, if (anonymous) CollectorAccess.Anonymous else CollectorAccess.Tokens(tokens), host, port, limits, 1..points)
    try {
        server.start()
    } catch (e: IOException) {
        throw UsageException("cannot listen on $host:$port: ${e.message}")
    }
    val hook = Thread { server.stop() }
    Runtime.getRuntime().addShutdownHook(hook)
    if (anonymous) {
        // Loud on purpose: this mode lets anyone who reaches the port read and fill every study.
        console.err.println("collect: WARNING: --allow-anonymous: NO AUTHENTICATION. Anyone who can reach $host:${server.port} can upload to and download EVERY study.")
        console.err.flush()
    }
    val auth = if (anonymous) "anonymous access" else tokenSummary(tokens)
    console.out.println(
        "collect: limits: ${limits.maxConnections} connections, ${limits.idleTimeoutMillis} ms idle timeout, ${limits.maxBodyBytes shr 20} MiB per upload, " +
            "${limits.requestsPerSecondPerAddress} requests/s per address (bursts of ${limits.burstPerAddress}), responses 1..$points",
    )
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

/**
 * `hapticon collect token add --study ID --role upload|download [--db DB]` prints a new token (once: only
 * its hash is stored); `token list [--db DB]` prints id, study, role and creation time; `token revoke ID
 * [--db DB]` deletes one, effective on the next request.
 */
private fun runToken(args: List<String>, console: Console) {
    val action = args.firstOrNull() ?: throw UsageException("collect token needs add, list or revoke")
    val rest = args.drop(1)
    when (action) {
        "add" -> {
            val arguments = Arguments.parse("collect token add", rest, valueOptions = setOf("db", "study", "role"))
            arguments.requireNoPositionals()
            val study = arguments.required("study")
            val role = arguments.required("role").let { TokenRole.of(it) ?: throw UsageException("--role must be upload or download, got '$it'") }
            if (!ResultRows.STUDY_ID.matches(study)) throw UsageException("--study must be 1-64 letters, digits, '.', '_' or '-', got '$study'")
            val db = arguments.value("db") ?: DEFAULT_COLLECT_DB
            val issued = openTokens(openStore(db), db).add(study, role)
            console.out.println(issued.token)
            console.err.println("collect: ${role.word} token ${issued.info.id} for study '$study' (shown once; only its SHA-256 is stored)")
        }
        "list" -> {
            val arguments = Arguments.parse("collect token list", rest, valueOptions = setOf("db"))
            arguments.requireNoPositionals()
            val db = arguments.value("db") ?: DEFAULT_COLLECT_DB
            console.out.println("id,study_id,role,created_at")
            for (t in openTokens(openStore(db), db).list()) console.out.println("${t.id},${t.studyId},${t.role.word},${t.createdAt}")
        }
        "revoke" -> {
            val arguments = Arguments.parse("collect token revoke", rest, valueOptions = setOf("db"))
            val id = arguments.single("a token id (see 'hapticon collect token list')")
            val db = arguments.value("db") ?: DEFAULT_COLLECT_DB
            if (!openTokens(openStore(db), db).revoke(id)) throw UsageException("no token with id '$id'")
            console.out.println("collect: revoked token $id")
        }
        else -> throw UsageException("collect token needs add, list or revoke, got '$action'")
    }
}

private fun openStore(db: String): ResultStore {
    val jdbcUrl = try {
        ResultStore.jdbcUrl(db)
    } catch (e: IllegalArgumentException) {
        throw UsageException(e.message.orEmpty())
    }
    return try {
        ResultStore(jdbcUrl)
    } catch (e: SQLException) {
        throw UsageException("cannot open database ${dbLabel(db)}: ${e.message?.lineSequence()?.firstOrNull()}")
    }
}

private fun openTokens(store: ResultStore, db: String): CollectorTokens = try {
    CollectorTokens(store)
} catch (e: SQLException) {
    throw UsageException("cannot open the token table in ${dbLabel(db)}: ${e.message?.lineSequence()?.firstOrNull()}")
}

/** How many tokens there are, or how to make the first: without one, every /v1 request gets 401. */
private fun tokenSummary(tokens: CollectorTokens): String {
    val count = tokens.list().size
    return if (count == 0) "no tokens yet: every /v1 request gets 401; add one with 'hapticon collect token add --study ID --role upload'" else "$count token${if (count == 1) "" else "s"}"
}

/** The database for the log line, without the query string that may hold a password. */
private fun dbLabel(db: String): String = db.substringBefore('?')
