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
    /**
     * [user]'s end-to-end protection, its keys made on first use. Throws [GeneralSecurityException] when the key
     * file does not open (the Keystore key is gone): the caller decides whether to make new keys, which peers
     * will then see as a key change.
     */
    fun endToEnd(user: String): EndToEnd {
        val identity = Identity.loadOrCreate(user, File(dir, "$user.keys"), secrets.wrappingKey)
        return EndToEnd(identity, FileKeyPins(File(dir, "pins-$user")))
    }
}
