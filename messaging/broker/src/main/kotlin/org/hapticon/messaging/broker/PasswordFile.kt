package org.hapticon.messaging.broker

import java.io.File
import java.io.IOException
import java.nio.file.Files
import java.nio.file.StandardCopyOption
import java.nio.file.attribute.BasicFileAttributes
import java.nio.file.attribute.PosixFilePermissions
import java.security.MessageDigest
import java.security.SecureRandom
import java.util.Base64
import javax.crypto.SecretKeyFactory
import javax.crypto.spec.PBEKeySpec

/**
 * A Mosquitto password file (`password_file` in mosquitto.conf): one `user:hash` line per user, read by
 * the embedded broker and by Mosquitto alike, so one file serves both. `mosquitto_passwd` writes it as well
 * as [add] does.
 *
 * The hash formats are Mosquitto's (mosquitto 2.0, `src/password_mosq.c` `pw__hash`/`pw__digest` and
 * `apps/mosquitto_passwd/mosquitto_passwd.c`):
 * - `$7$<iterations>$<base64 salt>$<base64 hash>`: PBKDF2-HMAC-SHA512 (`PKCS5_PBKDF2_HMAC` with
 *   `EVP_sha512()`) of the UTF-8 password over the decoded salt, 64 bytes; mosquitto_passwd's default
 *   (`PW_DEFAULT_ITERATIONS` 101 iterations, `SALT_LEN` 12 bytes). Verified against a line that
 *   mosquitto_passwd 2.0.11 wrote (PasswordFileTest).
 * - `$6$<base64 salt>$<base64 hash>`: SHA-512 of password then salt (Mosquitto 1.x files), read only.
 *
 * [add] writes `$7$` with [DEFAULT_ITERATIONS] rather than Mosquitto's 101: Mosquitto reads the count from
 * the line, and 101 rounds guard a leaked file poorly (OWASP's password storage cheat sheet asks 210,000 for
 * PBKDF2-HMAC-SHA512). Pass `iterations = 101` for Mosquitto's own choice.
 *
 * The file is read again when it changed on disk, so a user added while the broker runs can connect at
 * once (Mosquitto needs a SIGHUP for that). Thread-safe.
 */
public class PasswordFile(public val file: File) {
    private var loadedStamp: List<Any?>? = null
    private var hashes: Map<String, String> = emptyMap()

    /** True when [file] exists. */
    public val exists: Boolean get() = file.isFile

    /** The user names in the file, sorted. Throws [IOException] when it cannot be read. */
    @Synchronized
    public fun users(): List<String> = current().keys.sorted()

    /**
     * True when [user] is in the file and [password] matches its hash, compared in constant time. False
     * for unknown users, unreadable lines and unknown hash formats (Mosquitto's argon2id, say). Throws
     * [IOException] when the file cannot be read.
     */
    public fun verify(user: String, password: ByteArray): Boolean {
        val line = hashOf(user) ?: return false
        return matches(line, password)
    }

    /** [user]'s hash as the file has it now, or null when [user] is not in it. Throws [IOException] when it cannot be read. */
    @Synchronized
    internal fun hashOf(user: String): String? = current()[user]

    /**
     * Adds [user] with [password], or replaces its password, creating the file (mode 600) when missing.
     * Written to a temporary file and renamed, so a reader never sees half a file. Throws
     * [IllegalArgumentException] for a user name with `:` or a line break or an empty password,
     * [IOException] when the file cannot be written.
     */
    @Synchronized
    public fun add(user: String, password: CharArray, iterations: Int = DEFAULT_ITERATIONS) {
        require(user.isNotEmpty() && user.none { it == ':' || it == '\n' || it == '\r' }) { "a user name must not be empty or contain ':' or a line break" }
        require(password.isNotEmpty()) { "the password must not be empty" }
        val lines = if (file.isFile) file.readLines().filter { it.isNotBlank() && it.substringBefore(':') != user } else emptyList()
        val text = (lines + "$user:${hash(password, iterations)}").joinToString("\n", postfix = "\n")
        file.absoluteFile.parentFile?.mkdirs()
        val part = File(file.absoluteFile.parentFile, file.name + ".part")
        part.delete()
        try {
            Files.createFile(part.toPath(), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")))
        } catch (e: UnsupportedOperationException) {
            part.createNewFile() // not a POSIX file system
        }
        part.writeText(text)
        Files.move(part.toPath(), file.toPath(), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE)
        loadedStamp = null
    }

    private fun current(): Map<String, String> {
        if (!file.isFile) return emptyMap()
        // The file key (inode) changes with every add, which renames a new file into place: a password changed
        // within the same millisecond, to a line of the same length, is still noticed.
        val attributes = Files.readAttributes(file.toPath(), BasicFileAttributes::class.java)
        val stamp = listOf(attributes.fileKey(), attributes.lastModifiedTime(), attributes.size())
        if (stamp != loadedStamp) {
            hashes = file.readLines()
                .filter { it.isNotBlank() && !it.startsWith("#") && ':' in it }
                .associate { it.substringBefore(':') to it.substringAfter(':').trim() }
            loadedStamp = stamp
        }
        return hashes
    }

    public companion object {
        /** PBKDF2 rounds of the hashes [add] writes: OWASP's figure for PBKDF2-HMAC-SHA512. */
        public const val DEFAULT_ITERATIONS: Int = 210_000

        private const val SALT_BYTES = 12 // Mosquitto's SALT_LEN
        private const val HASH_BYTES = 64 // SHA-512
        private val random = SecureRandom()

        /** A `$7$` hash of [password] with a random 12-byte salt, as [PasswordFile] writes it. */
        public fun hash(password: CharArray, iterations: Int = DEFAULT_ITERATIONS): String {
            require(iterations >= 1) { "iterations must be >= 1, was $iterations" }
            val salt = ByteArray(SALT_BYTES).also(random::nextBytes)
            val b64 = Base64.getEncoder()
            return "\$7\$$iterations\$${b64.encodeToString(salt)}\$${b64.encodeToString(pbkdf2(password, salt, iterations))}"
        }

        /** True when [password] matches the Mosquitto hash [hash] (`$7$…` or `$6$…`); false for anything unreadable. */
        public fun matches(hash: String, password: ByteArray): Boolean {
            val parts = hash.split('$')
            return try {
                when {
                    parts.size == 5 && parts[0].isEmpty() && parts[1] == "7" -> {
                        val iterations = parts[2].toInt()
                        if (iterations !in 1..MAX_ITERATIONS) return false
                        val expected = Base64.getDecoder().decode(parts[4])
                        val chars = String(password, Charsets.UTF_8).toCharArray()
                        MessageDigest.isEqual(expected, pbkdf2(chars, Base64.getDecoder().decode(parts[3]), iterations, expected.size * 8))
                    }
                    parts.size == 4 && parts[0].isEmpty() && parts[1] == "6" -> {
                        val digest = MessageDigest.getInstance("SHA-512")
                        digest.update(password)
                        digest.update(Base64.getDecoder().decode(parts[2]))
                        MessageDigest.isEqual(Base64.getDecoder().decode(parts[3]), digest.digest())
                    }
                    else -> false
                }
            } catch (e: IllegalArgumentException) {
                false // bad base64 or number: an unusable line lets nobody in
            }
        }

        // Bounds the work one connection attempt can cost the broker through a crafted file line.
        private const val MAX_ITERATIONS = 10_000_000

        private fun pbkdf2(password: CharArray, salt: ByteArray, iterations: Int, bits: Int = HASH_BYTES * 8): ByteArray {
            require(bits in 8..HASH_BYTES * 8 * 4) { "hash length out of range" }
            val spec = PBEKeySpec(password, salt, iterations, bits)
            try {
                return SecretKeyFactory.getInstance("PBKDF2WithHmacSHA512").generateSecret(spec).encoded
            } finally {
                spec.clearPassword()
            }
        }
    }
}
