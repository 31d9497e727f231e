package org.hapticon.app.study

import android.content.Context
import android.content.SharedPreferences
import java.security.MessageDigest
import java.security.SecureRandom
import javax.crypto.SecretKeyFactory
import javax.crypto.spec.PBEKeySpec
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

/**
 * The researcher's settings: the session running now ([activeSessionId], so the app reopens into it after a
 * crash), the protocol last picked, and where results are uploaded ([collectorUrl], [collectorToken]).
 */
data class StudyPreferences(
    val activeSessionId: Long? = null,
    val selectedProtocolId: String? = null,
    val collectorUrl: String = "",
    val collectorToken: String = "",
)

/** Reads and writes [StudyPreferences]. */
interface StudySettingsRepository {
    val preferences: StateFlow<StudyPreferences>
    fun update(transform: (StudyPreferences) -> StudyPreferences)
}

/** [StudySettingsRepository] in SharedPreferences; writes are committed synchronously, as a crash may follow. */
class SharedPreferencesStudySettings(private val prefs: SharedPreferences) : StudySettingsRepository {
    constructor(context: Context) : this(context.getSharedPreferences(FILE, Context.MODE_PRIVATE))

    private val state = MutableStateFlow(read())
    override val preferences: StateFlow<StudyPreferences> = state.asStateFlow()

    override fun update(transform: (StudyPreferences) -> StudyPreferences) {
        val next = transform(state.value)
        val edit = prefs.edit()
        if (next.activeSessionId != null) edit.putLong(ACTIVE, next.activeSessionId) else edit.remove(ACTIVE)
        edit.putString(PROTOCOL, next.selectedProtocolId)
            .putString(URL, next.collectorUrl)
            .putString(TOKEN, next.collectorToken)
            .commit()
        state.value = next
    }

    private fun read() = StudyPreferences(
        activeSessionId = if (prefs.contains(ACTIVE)) prefs.getLong(ACTIVE, 0) else null,
        selectedProtocolId = prefs.getString(PROTOCOL, null),
        collectorUrl = prefs.getString(URL, null).orEmpty(),
        collectorToken = prefs.getString(TOKEN, null).orEmpty(),
    )

    companion object {
        /** The SharedPreferences file of the study settings and the PIN. */
        const val FILE = "study"
        private const val ACTIVE = "active_session"
        private const val PROTOCOL = "protocol"
        private const val URL = "collector_url"
        private const val TOKEN = "collector_token"
    }
}

/**
 * The researcher PIN: 4..12 digits, stored as PBKDF2-HMAC-SHA256 ([ITERATIONS] rounds) of the PIN with a random
 * 16-byte salt, never the PIN itself. [check] compares in constant time.
 */
class PinGate(private val prefs: SharedPreferences, private val random: SecureRandom = SecureRandom()) {
    constructor(context: Context) : this(context.getSharedPreferences(SharedPreferencesStudySettings.FILE, Context.MODE_PRIVATE))

    /** Whether a PIN has been set. */
    val isSet: Boolean get() = prefs.contains(HASH) && prefs.contains(SALT)

    /** Sets the PIN. Throws [IllegalArgumentException] when [pin] is not 4..12 digits. */
    fun set(pin: String) {
        requireValid(pin)
        val salt = ByteArray(16).also(random::nextBytes)
        prefs.edit().putString(SALT, salt.toHex()).putString(HASH, hash(pin, salt).toHex()).commit()
    }

    /** True when [pin] is the PIN; false when it is not or none is set. */
    fun check(pin: String): Boolean {
        val salt = prefs.getString(SALT, null)?.fromHex() ?: return false
        val stored = prefs.getString(HASH, null)?.fromHex() ?: return false
        return MessageDigest.isEqual(stored, hash(pin, salt))
    }

    private fun hash(pin: String, salt: ByteArray): ByteArray {
        val spec = PBEKeySpec(pin.toCharArray(), salt, ITERATIONS, 256)
        try {
            return SecretKeyFactory.getInstance("PBKDF2WithHmacSHA256").generateSecret(spec).encoded
        } finally {
            spec.clearPassword()
        }
    }

    companion object {
        /** PBKDF2 rounds: a few tens of milliseconds on a phone, which makes guessing 10^4..10^12 PINs slow offline. */
        const val ITERATIONS: Int = 60_000
        private const val HASH = "pin_hash"
        private const val SALT = "pin_salt"
        private val DIGITS = Regex("[0-9]{4,12}")

        /** Throws [IllegalArgumentException] saying what is wrong when [pin] is not 4..12 digits. */
        fun requireValid(pin: String) {
            require(DIGITS.matches(pin)) { "the PIN must be 4 to 12 digits" }
        }

        private fun ByteArray.toHex() = joinToString("") { "%02x".format(it.toInt() and 0xff) }

        private fun String.fromHex(): ByteArray? =
            if (length % 2 != 0) null else runCatching { ByteArray(length / 2) { substring(2 * it, 2 * it + 2).toInt(16).toByte() } }.getOrNull()
    }
}
