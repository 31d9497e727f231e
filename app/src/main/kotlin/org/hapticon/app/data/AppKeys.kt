package org.hapticon.app.data

import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.FileKeyPins
import org.hapticon.messaging.e2e.Identity
import java.io.File
import java.security.GeneralSecurityException

/**
 * The phone's end-to-end keys ([EndToEnd]) in app-private storage under [dir] (`filesDir/e2e`): per user,
 * `USER.keys` holds the private HPKE and Ed25519 keysets wrapped by the Keystore key of [secrets] (so a copy of the
 * app's files opens nothing without this phone's Keystore), and `pins-USER/` the peers' public keys as first seen.
 */
class AppKeys(private val dir: File, private val secrets: KeystoreSecrets = KeystoreSecrets()) {
    // One instance per user, so that a changed key the messenger holds back is the one [trust] accepts.
    private val loaded = java.util.concurrent.ConcurrentHashMap<String, EndToEnd>()

    /**
     * [user]'s end-to-end protection, its keys made on first use. Throws [GeneralSecurityException] when the key
     * file does not open (the Keystore key is gone): the caller decides whether to make new keys, which peers
     * will then see as a key change.
     */
    fun endToEnd(user: String): EndToEnd = loaded.getOrPut(user) {
        val identity = Identity.loadOrCreate(user, File(dir, "$user.keys"), secrets.wrappingKey)
        EndToEnd(identity, FileKeyPins(File(dir, "pins-$user")))
    }

    /** [user] accepts [peer]'s changed key (after comparing safety numbers); false when none is waiting. */
    fun trust(user: String, peer: String): Boolean = loaded[user]?.trust(peer) != null
}
