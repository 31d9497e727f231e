package org.hapticon.companion.chat

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import java.io.File

/** `hapticon chat`, end to end by default, against the embedded broker: two terminals, their keys, a key change and its trust. */
class ChatE2eTest {
    @get:Rule
    val fixture = ChatFixture()

    private val alice = ChatFixture.unique("alice")
    private val bob = ChatFixture.unique("bob")

    private fun chat(user: String, peer: String, keys: File) = ChatRun(
        listOf("--broker", fixture.url, "--user", user, "--to", peer, "--password-file", ChatFixture.passwordFile(user), "--keys-dir", keys.path),
    )

    /** Asks [chat] for the safety number with [peer] until its key has arrived; returns the 60 digits. */
    private fun awaitSafetyNumber(chat: ChatRun, peer: String): String {
        val prefix = "safety number with $peer: "
        repeat(200) {
            chat.input.type("/safety $peer")
            Thread.sleep(50)
            chat.out.lines.firstOrNull { it.startsWith(prefix) }?.let { return it.removePrefix(prefix).substringBefore(" (") }
        }
        throw AssertionError("no key of $peer arrived:\n${chat.out.text}")
    }

    @Test
    fun chat_e2e_twoTerminalsExchangeSealedMessages_keyChangeWarnsUntilTrusted() {
        val bobKeys = File(fixture.temp.root, "bob-keys")
        val bobChat = chat(bob, alice, bobKeys)
        bobChat.err.awaitLine("chat: end-to-end encryption on; keys of $bob in $bobKeys (--plaintext turns it off)")
        bobChat.err.awaitLine { it.startsWith("chat: connected as $bob") }
        val aliceChat = chat(alice, bob, File(fixture.temp.root, "alice-keys"))
        aliceChat.err.awaitLine { it.startsWith("chat: connected as $alice") }
        val number = awaitSafetyNumber(aliceChat, bob)
        assertTrue(number, Regex("(\\d{5} ){11}\\d{5}").matches(number))

        aliceChat.input.type("hello bob, sealed")
        bobChat.out.awaitLine("$alice: hello bob, sealed")
        aliceChat.out.awaitLine("✓ $bob received \"hello bob, sealed\"")
        assertEquals(number, awaitSafetyNumber(bobChat, alice)) // both see the same number
        assertTrue(File(bobKeys, "pins/$alice.pub").isFile)
        assertEquals(0, aliceChat.quit())

        // alice comes back with new keys (a new phone): bob is warned and holds her messages back.
        val newAlice = chat(alice, bob, File(fixture.temp.root, "alice-new-keys"))
        bobChat.err.awaitLine { it.startsWith("chat: rejected a payload on hapticon/v1/keys/$alice: KEY_CHANGED: $alice's key changed (safety number now ") }
        bobChat.err.awaitLine("chat: WARNING: compare safety numbers with $alice (in person or by phone), then /trust $alice; until then their messages wait in their outbox")
        awaitSafetyNumber(newAlice, bob)
        newAlice.input.type("it is me, new phone")
        bobChat.err.awaitLine { it.startsWith("chat: rejected a payload on hapticon/v1/inbox/$bob/$alice: KEY_CHANGED:") && it.endsWith("message held back until you trust the new key") }
        bobChat.input.type("/trust $alice")
        bobChat.out.awaitLine { it.startsWith("now trusting $alice's new key; safety number ") }
        newAlice.input.type("and now?")
        bobChat.out.awaitLine("$alice: and now?")
        assertEquals(emptyList<String>(), bobChat.out.lines.filter { it.contains("it is me") }) // not shown before the trust
        bobChat.input.type("/trust $alice")
        bobChat.out.awaitLine("no changed key of $alice is waiting")
        assertEquals(0, bobChat.quit())
        newAlice.quit()
    }

    @Test
    fun chat_plaintext_isAnExplicitChoiceWarnedAboutAtStart() {
        val base = listOf("--broker", fixture.url, "--user", alice, "--password-file", ChatFixture.passwordFile(alice))
        val keys = ChatRun(base + listOf("--plaintext", "--keys-dir", "k"))
        assertEquals(2, keys.quit(null))
        assertEquals("hapticon: --keys-dir is for end-to-end encryption, which --plaintext turns off", keys.err.lines.first())
        val both = ChatRun(base + listOf("--plaintext", "--e2e"))
        assertEquals(2, both.quit(null))
        assertEquals("hapticon: --plaintext excludes --e2e", both.err.lines.first())

        val plain = ChatRun(base + "--plaintext")
        plain.err.awaitLine { it.startsWith("chat: connected as $alice") }
        assertEquals(
            "chat: WARNING: --plaintext: end-to-end encryption is OFF; the broker's operator can read and forge every message, and peers who encrypt refuse these",
            plain.err.lines.first(),
        )
        plain.input.type("/safety $bob")
        plain.out.awaitLine("end-to-end encryption is off (this chat was started with --plaintext)")
        assertEquals(0, plain.quit())
    }
}
