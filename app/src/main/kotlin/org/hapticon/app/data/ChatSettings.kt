package org.hapticon.app.data

import android.content.Context
import org.hapticon.core.pattern.PitchFit
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow

/** The user's chat settings. */
data class ChatPreferences(
    /** The user name; null until the first-run screen set it. */
    val userName: String? = null,
    /** Empty until the first-launch screen tested and saved one: no address is right for every phone. */
    val brokerUrl: String = "",
    /** Play an arriving message's icon at once (rate-limited). Off by default: vibrating unasked surprises people. */
    val autoPlay: Boolean = false,
    /** A renderer the user forces instead of the best available one ([org.hapticon.core.render.RendererKind] name), or null. */
    val rendererOverride: String? = null,
    /** Android 12+ wallpaper colours instead of Hapticon's own scheme. */
    val dynamicColor: Boolean = false,
    /** Tell a sender when this user played their icon (the "felt" receipt); the user can switch it off. */
    val sendFeltReceipts: Boolean = true,
    /** Keep the broker connection in a foreground service while the app is closed ("Stay reachable"). */
    val stayReachable: Boolean = false,
    /** Start the "Stay reachable" service again after the phone restarts. */
    val reachableAfterBoot: Boolean = false,
    /**
     * First launch saved the account and still owes the user the offer of "Stay reachable" and autoplay (asked
     * once, before the chat list; answered, it is false for good).
     */
    val reachableOfferPending: Boolean = false,
    /** Conversations moved out of the chat list (still stored, back on a new message). */
    val archived: Set<String> = emptySet(),
    /**
     * The broker password of [userName] (the MQTT user name is the Hapticon user name: the broker's ACL
     * ties topics to it), or null for a broker run with `--allow-anonymous`.
     */
    val brokerPassword: String? = null,
    /**
     * The keyboard's Enter key sends the message instead of starting a new line (Signal's "Enter key sends",
     * Google Messages' "Press Enter to send"); off by default in both, so here too.
     */
    val enterSends: Boolean = false,
    /**
     * Seal every message end to end ([org.hapticon.messaging.e2e.EndToEnd], keys in [AppKeys]), so whoever runs the
     * broker can neither read nor forge them. On by default, as in `hapticon chat`; off only by the user's explicit
     * choice (a study that needs the broker to see content), confirmed in Settings and logged at every session.
     */
    val endToEnd: Boolean = true,
    /**
     * What this phone does with a pattern's or icon's frequencies its actuator cannot give (API 36 frequency
     * profile): move the whole thing by octaves (the default, docs/patterns.md) or clamp each frequency. Published
     * with the capabilities, so a sender sees the pitch this phone will play.
     */
    val pitchFit: PitchFit = PitchFit.OCTAVES,
) {
    /** Omits the password, so that it never reaches a log. */
    override fun toString(): String =
        "ChatPreferences(userName=$userName, brokerUrl=$brokerUrl, autoPlay=$autoPlay, rendererOverride=$rendererOverride, " +
            "dynamicColor=$dynamicColor, sendFeltReceipts=$sendFeltReceipts, stayReachable=$stayReachable, " +
            "reachableAfterBoot=$reachableAfterBoot, reachableOfferPending=$reachableOfferPending, archived=$archived, enterSends=$enterSends, endToEnd=$endToEnd, pitchFit=$pitchFit, brokerPassword=${if (brokerPassword == null) "none" else "***"})"
}

/** Reads and writes [ChatPreferences]. */
interface ChatSettingsRepository {
    val preferences: StateFlow<ChatPreferences>
    fun update(transform: (ChatPreferences) -> ChatPreferences)
}

/**
 * Settings kept in SharedPreferences (small, synchronous reads at start-up are fine). The broker password
 * lives in a file of its own, `chat_credentials`, so that settings can be exported or shown without it, and is
 * encrypted there by [secrets] (AES-GCM under a key in Android Keystore; Jetpack Security's
 * EncryptedSharedPreferences, the usual answer, is deprecated). A password an older version stored in clear is
 * encrypted on first read and the clear copy removed. Only where no Keystore exists at all (a plain JVM) is it
 * kept in clear, with a warning in the log.
 */
class SharedPreferencesChatSettings(
    context: Context,
    private val secrets: KeystoreSecrets = KeystoreSecrets(),
    private val keystoreAvailable: () -> Boolean = KeystoreSecrets::keystoreAvailable,
) : ChatSettingsRepository {
    private val prefs = context.getSharedPreferences("chat", Context.MODE_PRIVATE)
    private val credentials = context.getSharedPreferences("chat_credentials", Context.MODE_PRIVATE)
    private val state = MutableStateFlow(read())
    override val preferences: StateFlow<ChatPreferences> = state.asStateFlow()

    override fun update(transform: (ChatPreferences) -> ChatPreferences) {
        val next = transform(state.value)
        prefs.edit()
            .putString(USER, next.userName)
            .putString(BROKER, next.brokerUrl)
            .putBoolean(AUTO_PLAY, next.autoPlay)
            .putString(RENDERER, next.rendererOverride)
            .putBoolean(DYNAMIC_COLOR, next.dynamicColor)
            .putBoolean(FELT_RECEIPTS, next.sendFeltReceipts)
            .putBoolean(STAY_REACHABLE, next.stayReachable)
            .putBoolean(AFTER_BOOT, next.reachableAfterBoot)
            .putBoolean(OFFER_PENDING, next.reachableOfferPending)
            .putStringSet(ARCHIVED, next.archived)
            .putBoolean(ENTER_SENDS, next.enterSends)
            .putBoolean(PLAINTEXT_CHOSEN, !next.endToEnd)
            .remove(OLD_END_TO_END)
            .putString(PITCH_FIT, next.pitchFit.name)
            .apply()
        writePassword(next.brokerPassword)
        state.value = next
    }

    private fun writePassword(password: String?) {
        val edit = credentials.edit()
        when {
            password == null -> edit.remove(PASSWORD).remove(SEALED_PASSWORD)
            keystoreAvailable() -> edit.putString(SEALED_PASSWORD, secrets.seal(password, PASSWORD_PURPOSE)).remove(PASSWORD)
            else -> {
                android.util.Log.w("ChatSettings", "no Android Keystore here: the broker password is stored unencrypted")
                edit.putString(PASSWORD, password).remove(SEALED_PASSWORD)
            }
        }
        edit.apply()
    }

    private fun readPassword(): String? {
        credentials.getString(SEALED_PASSWORD, null)?.let { return secrets.open(it, PASSWORD_PURPOSE) }
        val clear = credentials.getString(PASSWORD, null) ?: return null
        if (keystoreAvailable()) writePassword(clear) // written in clear by an older version: encrypt it now
        return clear
    }

    private fun read() = ChatPreferences(
        userName = prefs.getString(USER, null),
        brokerUrl = prefs.getString(BROKER, null) ?: "",
        autoPlay = prefs.getBoolean(AUTO_PLAY, false),
        rendererOverride = prefs.getString(RENDERER, null),
        brokerPassword = readPassword(),
        dynamicColor = prefs.getBoolean(DYNAMIC_COLOR, false),
        sendFeltReceipts = prefs.getBoolean(FELT_RECEIPTS, true),
        stayReachable = prefs.getBoolean(STAY_REACHABLE, false),
        reachableAfterBoot = prefs.getBoolean(AFTER_BOOT, false),
        reachableOfferPending = prefs.getBoolean(OFFER_PENDING, false),
        archived = prefs.getStringSet(ARCHIVED, null)?.toSet() ?: emptySet(),
        enterSends = prefs.getBoolean(ENTER_SENDS, false),
        // Only a choice stored under PLAINTEXT_CHOSEN turns encryption off. Earlier versions wrote end_to_end=false with
        // every other setting, so that old key cannot tell a choice from the old default: it is ignored.
        endToEnd = !prefs.getBoolean(PLAINTEXT_CHOSEN, false),
        // A name a later version wrote and this one does not know falls back to the default.
        pitchFit = PitchFit.entries.firstOrNull { it.name == prefs.getString(PITCH_FIT, null) } ?: PitchFit.OCTAVES,
    )

    private companion object {
        const val USER = "user"
        const val BROKER = "broker"
        const val AUTO_PLAY = "auto_play"
        const val RENDERER = "renderer"
        const val PASSWORD = "broker_password"
        const val SEALED_PASSWORD = "broker_password_sealed"
        const val PASSWORD_PURPOSE = "hapticon broker password"
        const val DYNAMIC_COLOR = "dynamic_color"
        const val FELT_RECEIPTS = "felt_receipts"
        const val STAY_REACHABLE = "stay_reachable"
        const val AFTER_BOOT = "reachable_after_boot"
        const val OFFER_PENDING = "reachable_offer_pending"
        const val ARCHIVED = "archived"
        const val ENTER_SENDS = "enter_sends"
        const val OLD_END_TO_END = "end_to_end"
        const val PLAINTEXT_CHOSEN = "plaintext_chosen"
        const val PITCH_FIT = "pitch_fit"
    }
}
