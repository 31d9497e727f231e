package org.hapticon.messaging.e2e

import org.hapticon.messaging.Topics
import java.io.File
import java.security.GeneralSecurityException

/**
 * The other users' public keys as first seen ("trust on first use"): [EndToEnd] pins a user's [KeyBundle]
 * the first time it arrives and from then on accepts only that one, until the user explicitly trusts a new
 * one. Implementations must be safe to call from several threads.
 */
public interface KeyPins {
    /** The pinned bundle of [user], or null before first contact. */
    public fun pinned(user: String): KeyBundle?

    /** Pins [bundle] for its user, replacing any earlier pin. */
    public fun pin(bundle: KeyBundle)
}

/**
 * [KeyPins] as one file per user, `<user>.pub` in [dir], holding [KeyBundle.encoded]. A damaged file throws
 * rather than counting as "no pin": pinning afresh would let whoever damaged it choose the key.
 */
public class FileKeyPins(private val dir: File) : KeyPins {
    override fun pinned(user: String): KeyBundle? {
        val file = File(dir, Topics.requireUserName(user) + ".pub")
        if (!file.exists()) return null
        return try {
            KeyBundle.decode(file.readBytes()).also { check(it.user == user) { "$file holds the key of ${it.user}" } }
        } catch (e: GeneralSecurityException) {
            throw IllegalStateException("pinned key file $file is damaged (${e.message}); delete it to pin $user's key again", e)
        }
    }

    @Synchronized
    override fun pin(bundle: KeyBundle) {
        Identity.writePrivately(File(dir, bundle.user + ".pub"), bundle.encoded)
    }
}
