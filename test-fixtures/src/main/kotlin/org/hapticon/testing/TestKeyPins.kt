package org.hapticon.testing

import org.hapticon.messaging.e2e.KeyBundle
import org.hapticon.messaging.e2e.KeyPins
import java.util.concurrent.ConcurrentHashMap

/** [KeyPins] in memory, forgotten with the test: the tests' pins for [org.hapticon.messaging.e2e.EndToEnd]. */
class TestKeyPins : KeyPins {
    private val pins = ConcurrentHashMap<String, KeyBundle>()

    override fun pinned(user: String): KeyBundle? = pins[user]

    override fun pin(bundle: KeyBundle) {
        pins[bundle.user] = bundle
    }
}
