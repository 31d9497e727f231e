package org.hapticon.companion.chat

import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3BlockingClient
import kotlinx.coroutines.runBlocking
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.Topics
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import java.io.File

/**
 * `hapticon chat` against the attacks of a hostile participant or operator on the embedded broker: an acknowledged
 * message the broker lost while the sender's chat had already exited, a replayed sealed payload in a later session,
 * and a peer's text or icon name written to pass for someone else's line or to drive the terminal.
 */
class ChatTrustTest {
    @get:Rule
    val fixture = ChatFixture()

    private val alice = ChatFixture.unique("alice")
    private val bob = ChatFixture.unique("bob")

    private fun dir(name: String) = File(fixture.temp.root, name)

    /** A chat of [user] to [peer] with its own keys and store under the test's folder, kept across runs. */
    private fun chat(user: String, peer: String, vararg extra: String) = ChatRun(
        listOf("--broker", fixture.url, "--user", user, "--to", peer, "--password-file", ChatFixture.passwordFile(user), "--data-dir", dir("$user-data").path) +
            (if ("--plaintext" in extra) emptyList() else listOf("--keys-dir", dir("$user-keys").path)) + extra,
    )

    /** A raw MQTT client logged in as [user]: it publishes exactly the bytes a test gives it. */
    private fun raw(user: String): Mqtt3BlockingClient = MqttClient.builder().useMqttVersion3().identifier("$user:" + org.hapticon.messaging.mqtt.DeviceId.generate().value)
        .serverHost("127.0.0.1").serverPort(fixture.broker.port)
        .simpleAuth().username(user).password(ChatFixture.register(user).toByteArray()).applySimpleAuth()
        .buildBlocking().also { it.connect() }

    private fun awaitKey(chat: ChatRun, peer: String) {
        repeat(200) {
            chat.input.type("/safety $peer")
            Thread.sleep(50)
            if (chat.out.lines.any { it.startsWith("safety number with $peer: ") }) return
        }
        throw AssertionError("no key of $peer arrived:\n${chat.out.text}")
    }

    @Test
    fun outbox_acknowledgedMessageLostWhileTheSenderWasGone_nextStartsResendIt_receiverShowsItOnce() {
        // bob's key is published, but no session of his exists yet: the broker acknowledges alice's message and
        // drops it (no subscriber), exactly what a broker killed before it saved does.
        val bobIdentity = Identity.loadOrCreate(bob, File(dir("$bob-keys"), "identity.keys"))
        raw(bob).apply {
            publishWith().topic(Topics.keys(bob)).qos(MqttQos.AT_LEAST_ONCE).retain(true).payload(bobIdentity.bundle.encoded).send()
            disconnect()
        }
        val alice1 = chat(alice, bob)
        alice1.err.awaitLine { it.startsWith("chat: connected as $alice") }
        awaitKey(alice1, bob)
        alice1.input.type("are you there?")
        assertEquals(0, alice1.quit())
        val store = File(dir("$alice-data"), "chat.db")
        alice1.err.awaitLine("chat: 1 message(s) reached the broker but were not yet confirmed by the receiver; kept in $store and sent again at the next start:")
        alice1.err.awaitLine("  … to $bob: \"are you there?\" (reached the broker, no receipt yet)")

        // bob connects once (now the broker keeps his queue) and leaves; alice's next session sends it again and
        // ends before his receipt too; her third sends it once more.
        val bob1 = chat(bob, alice)
        bob1.err.awaitLine { it.startsWith("chat: connected as $bob") }
        assertEquals(0, bob1.quit())
        assertEquals(emptyList<String>(), bob1.out.lines.filter { it.startsWith("$alice:") }) // lost by the broker
        val alice2 = chat(alice, bob)
        alice2.err.awaitLine("chat: 1 message(s) of an earlier session not yet confirmed by their receivers; sending them again:")
        alice2.err.awaitLine { it.startsWith("chat: connected as $alice") }
        alice2.input.type("second") // after the resend: the outbox sends in order, and quitting waits for this one
        assertEquals(0, alice2.quit())
        alice2.err.awaitLine("chat: 2 message(s) reached the broker but were not yet confirmed by the receiver; kept in $store and sent again at the next start:")
        val alice3 = chat(alice, bob)
        alice3.err.awaitLine("chat: 2 message(s) of an earlier session not yet confirmed by their receivers; sending them again:")
        alice3.err.awaitLine { it.startsWith("chat: connected as $alice") }
        alice3.input.type("/pending")
        alice3.out.awaitLine("2 message(s) not yet confirmed by their receivers:")
        alice3.input.type("third")

        // bob's queue holds "are you there?" twice, "second" twice and "third": each is shown once, in order.
        val bob2 = chat(bob, alice)
        bob2.out.awaitLine("$alice: third")
        assertEquals(listOf("$alice: are you there?", "$alice: second", "$alice: third"), bob2.out.lines.filter { it.startsWith("$alice:") })
        alice3.out.awaitLine("✓ $bob received \"third\"")
        alice3.input.type("/pending")
        alice3.out.awaitLine("every message you sent is confirmed by its receiver")
        // One ✓ per message, although every copy was acknowledged (bob answers each in order, "third" last).
        assertEquals(
            listOf("✓ $bob received \"are you there?\"", "✓ $bob received \"second\"", "✓ $bob received \"third\""),
            alice3.out.lines.filter { it.startsWith("✓ ") },
        )
        assertEquals(0, bob2.quit())
        assertEquals(0, alice3.quit())
    }

    @Test
    fun replay_aGenuineSealedPayloadInALaterSession_isNotShownAgain() {
        val bob1 = chat(bob, alice)
        bob1.err.awaitLine { it.startsWith("chat: connected as $bob") }
        // What an operator who recorded alice's payload holds: her genuine, sealed and signed bytes.
        val aliceE2e = EndToEnd(Identity.generate(alice), TestKeyPins().apply { pin(Identity.loadOrCreate(bob, File(dir("$bob-keys"), "identity.keys")).bundle) })
        val genuine = aliceE2e.seal(bob, MessageCodec.encode(ChatMessage.compose(alice, "meet at 5")))
        val wire = raw(alice)
        wire.publishWith().topic(Topics.inbox(bob, alice)).qos(MqttQos.AT_LEAST_ONCE).payload(genuine).send()
        bob1.out.awaitLine("$alice: meet at 5")
        assertEquals(0, bob1.quit())

        val bob2 = chat(bob, alice)
        bob2.err.awaitLine { it.startsWith("chat: connected as $bob") }
        wire.publishWith().topic(Topics.inbox(bob, alice)).qos(MqttQos.AT_LEAST_ONCE).payload(genuine).send()
        wire.publishWith().topic(Topics.inbox(bob, alice)).qos(MqttQos.AT_LEAST_ONCE).payload(aliceE2e.seal(bob, MessageCodec.encode(ChatMessage.compose(alice, "marker")))).send()
        bob2.out.awaitLine("$alice: marker")
        assertEquals(listOf("$alice: marker"), bob2.out.lines.filter { it.startsWith("$alice:") })
        wire.disconnect()
        assertEquals(0, bob2.quit())
    }

    @Test
    fun impersonation_sealedTextWithNewlinesAndIconNameWithEscapes_stayUnderTheirSenderAsText() {
        val carol = ChatFixture.unique("carol")
        val wavs = dir("wavs")
        val chat = chat(alice, bob, "--wav-dir", wavs.path)
        chat.err.awaitLine { it.startsWith("chat: connected as $alice") }
        val (phone, _) = fixture.phone(bob, EndToEnd(Identity.generate(bob), TestKeyPins()))
        val icon = HapticIcon.KNOCK.copy(name = "\u001b]0;owned\u0007knock\n$carol: x")
        val message = ChatMessage.compose(bob, "see you at 5\n$carol: bob is lying, send the data to me\r\u001b[1A", icon = icon)
        var sent = false
        repeat(200) { if (!sent) sent = runCatching { runBlocking { phone.send(alice, message) } }.isSuccess.also { if (!it) Thread.sleep(50) } }
        assertTrue("alice's key never reached bob's phone", sent)
        val wrote = chat.out.awaitLine { it.startsWith("  wrote ") }
        val indent = " ".repeat(bob.length) + ChatFormat.CONTINUATION
        val iconLine = "icon \\u001b]0;owned\\u0007knock\\u000a$carol: x: attack 0.005 s, sustain 0.01 s, release 0.005 s, level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s"
        assertEquals(
            listOf("$bob: see you at 5", "$indent$carol: bob is lying, send the data to me\\u000d\\u001b[1A [$iconLine]", wrote),
            chat.out.lines,
        )
        val wav = File(wavs, "$bob-${message.id.take(8)}-${ChatFormat.fileSafe(icon.name)}.wav")
        assertEquals("  wrote $wav: \\u001b]0;owned\\u0007knock\\u000a$carol: x, 24696 samples, 0.560 s at 44100 Hz, f32, processing model, exact mode", wrote)
        // Nothing that drives a terminal reached it: no control character but the line ends.
        assertEquals(emptyList<Char>(), chat.out.text.filter { Character.isISOControl(it) && it != '\n' }.toList())
        assertEquals(0, chat.quit())
    }

    @Test
    fun impersonation_plaintextTextWithNewlines_staysUnderItsSender() {
        val carol = ChatFixture.unique("carol")
        val chat = chat(alice, bob, "--plaintext")
        chat.err.awaitLine { it.startsWith("chat: connected as $alice") }
        val (phone, _) = fixture.phone(bob)
        runBlocking { phone.send(alice, ChatMessage.compose(bob, "ok\n\n$carol: wire the money\n")) }
        chat.out.awaitLine("$bob: ok")
        val indent = " ".repeat(bob.length) + ChatFormat.CONTINUATION
        chat.out.awaitLine("$indent$carol: wire the money")
        assertEquals(listOf("$bob: ok", indent, "$indent$carol: wire the money", indent), chat.out.lines)
        assertEquals(0, chat.quit())
    }
}
