package org.hapticon.companion.study

import java.security.MessageDigest
import java.security.SecureRandom
import java.time.Clock
import java.time.Instant
import java.util.Base64

/** What a collector token may do, for its one study: send results, or fetch them. Neither implies the other. */
enum class TokenRole(val word: String) {
    UPLOAD("upload"),
    DOWNLOAD("download"),
    ;

    companion object {
        /** The role called [word] (`upload` or `download`), or null. */
        fun of(word: String): TokenRole? = entries.firstOrNull { it.word == word.lowercase() }
    }
}

/** A stored token without its secret: [id] (public, for `token revoke`), its [studyId], [role] and [createdAt]. */
class TokenInfo(val id: String, val studyId: String, val role: TokenRole, val createdAt: String)

/** A token just made: [token] is the only copy of the secret (only its hash is stored), shown once. */
class IssuedToken(val info: TokenInfo, val token: String)

/**
 * The collector's access tokens, in table `collector_tokens` of the [store]'s database (so collectors
 * sharing one PostgreSQL share the tokens). A token is `hct1.ID.SECRET`: ID is 8 random bytes in hex (a
 * public handle), SECRET 32 random bytes (256 bits) in unpadded base64url. Only SHA-256(SECRET) is stored,
 * so a copy of the database grants nothing; a plain hash (no salt, no slow KDF) is enough for 256 random
 * bits, as nobody can guess them (OWASP Password Storage: slow hashes are for low-entropy passwords).
 * [authenticate] compares hashes in constant time (`MessageDigest.isEqual`).
 */
class CollectorTokens(
    private val store: ResultStore,
    private val random: SecureRandom = SecureRandom(),
    private val clock: Clock = Clock.systemUTC(),
) {
    init {
        store.connect().use { c -> c.createStatement().use { it.executeUpdate(CREATE_TABLE) } }
    }

    /** Makes a token for [studyId] with [role]; [IllegalArgumentException] for a study id that uploads could not use. */
    fun add(studyId: String, role: TokenRole): IssuedToken {
        require(ResultRows.STUDY_ID.matches(studyId)) { "--study must be 1-64 letters, digits, '.', '_' or '-', got '$studyId'" }
        val id = ByteArray(ID_BYTES).also(random::nextBytes).joinToString("") { "%02x".format(it.toInt() and 0xff) }
        val secret = Base64.getUrlEncoder().withoutPadding().encodeToString(ByteArray(SECRET_BYTES).also(random::nextBytes))
        val info = TokenInfo(id, studyId, role, Instant.now(clock).toString())
        store.connect().use { c ->
            c.prepareStatement("INSERT INTO collector_tokens (token_id, study_id, role, secret_sha256, created_at) VALUES (?, ?, ?, ?, ?)").use { s ->
                s.setString(1, id)
                s.setString(2, studyId)
                s.setString(3, role.word)
                s.setString(4, sha256Hex(secret))
                s.setString(5, info.createdAt)
                s.executeUpdate()
            }
        }
        return IssuedToken(info, "$PREFIX.$id.$secret")
    }

    /** Every token, by study, role and creation time. */
    fun list(): List<TokenInfo> = store.connect().use { c ->
        c.prepareStatement("SELECT token_id, study_id, role, created_at FROM collector_tokens ORDER BY study_id, role, created_at, token_id").use { s ->
            s.executeQuery().use { r ->
                val tokens = ArrayList<TokenInfo>()
                while (r.next()) {
                    val role = TokenRole.of(r.getString(3)) ?: continue // a row written by a newer collector: not ours to honour
                    tokens += TokenInfo(r.getString(1), r.getString(2), role, r.getString(4))
                }
                tokens
            }
        }
    }

    /** Deletes token [id]; false when there is none. Takes effect on the next request (nothing is cached). */
    fun revoke(id: String): Boolean = store.connect().use { c ->
        c.prepareStatement("DELETE FROM collector_tokens WHERE token_id = ?").use { s ->
            s.setString(1, id)
            s.executeUpdate() > 0
        }
    }

    /** The stored token [presented] is, or null when it is malformed, unknown, revoked or its secret is wrong. */
    fun authenticate(presented: String): TokenInfo? {
        val parts = presented.split('.')
        val id = parts.getOrNull(1)
        if (parts.size != 3 || parts[0] != PREFIX || id == null || !ID.matches(id)) return null
        val given = sha256Hex(parts[2]).toByteArray(Charsets.US_ASCII)
        val found = store.connect().use { c ->
            c.prepareStatement("SELECT study_id, role, secret_sha256, created_at FROM collector_tokens WHERE token_id = ?").use { s ->
                s.setString(1, id)
                s.executeQuery().use { r -> if (r.next()) listOf(r.getString(1), r.getString(2), r.getString(3), r.getString(4)) else null }
            }
        } ?: return null
        // Constant time: how long the comparison takes must not tell how much of a guessed secret was right.
        if (!MessageDigest.isEqual(given, found[2].toByteArray(Charsets.US_ASCII))) return null
        val role = TokenRole.of(found[1]) ?: return null
        return TokenInfo(id, found[0], role, found[3])
    }

    companion object {
        /** The token format's prefix and version, so a leaked token is recognisable (e.g. by secret scanners). */
        const val PREFIX: String = "hct1"
        private const val ID_BYTES = 8
        private const val SECRET_BYTES = 32
        private val ID = Regex("[0-9a-f]{16}")
        private const val CREATE_TABLE = "CREATE TABLE IF NOT EXISTS collector_tokens (token_id TEXT NOT NULL PRIMARY KEY, " +
            "study_id TEXT NOT NULL, role TEXT NOT NULL, secret_sha256 TEXT NOT NULL, created_at TEXT NOT NULL)"

        /** SHA-256 of [text]'s UTF-8 bytes, in lower-case hex: what the table stores for a secret. */
        fun sha256Hex(text: String): String =
            MessageDigest.getInstance("SHA-256").digest(text.toByteArray(Charsets.UTF_8)).joinToString("") { "%02x".format(it.toInt() and 0xff) }
    }
}
