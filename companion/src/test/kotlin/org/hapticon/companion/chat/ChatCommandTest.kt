package org.hapticon.companion.chat

import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import kotlinx.coroutines.runBlocking
import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.WavReader
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.Topics
import org.hapticon.messaging.mqtt.DeviceId
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import java.io.File

class ChatCommandTest {
    @get:Rule
    val fixture = ChatFixture()

    private val alice = ChatFixture.unique("alice")
    private val bob = ChatFixture.unique("bob")

    // The phone at the other end speaks plaintext, and these tests publish raw payloads: the chat must too.
    private fun chat(vararg extra: String) =
        ChatRun(listOf("--broker", fixture.url, "--user", alice, "--to", bob, "--password-file", ChatFixture.passwordFile(alice), "--plaintext") + extra)

    @Test
    fun chat_withAPhone_exchangesTextIconStickerAndReceipts() {
        val wavDir = File(fixture.temp.root, "wavs")
        val chat = chat("--wav-dir", wavDir.path)
        chat.err.awaitLine("chat: connected as $alice, talking to $bob; /help lists commands")
        val (phone, bobEvents) = fixture.phone(bob)
        runBlocking { phone.publishCapabilities(Capabilities(bob, RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 34, resonantFrequencyHz = 170.0)) }
        chat.out.awaitLine("$bob's device: amplitude waveform, amplitude control, Android API 34, resonance 170.0 Hz")

        val hello = ChatMessage.compose(bob, "hello alice", icon = HapticIcon.KNOCK)
        runBlocking { phone.send(alice, hello) }
        chat.out.awaitLine("$bob: hello alice [icon knock: attack 0.005 s, sustain 0.01 s, release 0.005 s, level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s]")
        val wav = File(wavDir, "$bob-${hello.id.take(8)}-knock.wav")
        chat.out.awaitLine("  wrote $wav: knock, 24696 samples, 0.560 s at 44100 Hz, f32, processing model, exact mode")
        assertEquals(24_696L, wav.inputStream().use { WavReader.read(it) }.frames.toLong())
        val delivered = bobEvents.nextNonCapabilities() as InboxEvent.ReceiptReceived
        assertEquals(hello.id to ReceiptState.DELIVERED, delivered.receipt.messageId to delivered.receipt.state)
        assertEquals(alice, delivered.receipt.from)

        // Typing a line marks what the terminal showed as read, then sends the line.
        chat.input.type("hi bob")
        // The receipt and the message travel separately (receipts do not wait in the outbox): either may come first.
        val next = listOf(bobEvents.nextNonCapabilities(), bobEvents.nextNonCapabilities())
        val read = next.filterIsInstance<InboxEvent.ReceiptReceived>().single()
        assertEquals(hello.id to ReceiptState.READ, read.receipt.messageId to read.receipt.state)
        val text = next.filterIsInstance<InboxEvent.MessageReceived>().single().message
        assertEquals(Triple(alice, "hi bob", null as HapticIcon?), Triple(text.sender, text.text, text.icon))

        chat.input.type("/icon hug thinking of you")
        val icon = (bobEvents.nextNonCapabilities() as InboxEvent.MessageReceived).message
        assertEquals("thinking of you" to HapticIcon.HUG, icon.text to icon.icon)
        chat.input.type("/sticker wave")
        val sticker = (bobEvents.nextNonCapabilities() as InboxEvent.MessageReceived).message
        assertEquals("" to "wave", sticker.text to sticker.sticker)

        runBlocking { phone.send(alice, Receipt(text.id, bob, ReceiptState.READ, text.sentAtMillis + 1)) }
        chat.out.awaitLine("✓✓ $bob read \"hi bob\"")
        assertEquals(0, chat.quit())
    }

    @Test
    fun chat_patternFileAndPatternMessage_sentAsPatternAndRenderedToWav() {
        val wavDir = File(fixture.temp.root, "pattern-wavs")
        val chat = chat("--wav-dir", wavDir.path)
        chat.err.awaitLine("chat: connected as $alice, talking to $bob; /help lists commands")
        val (phone, bobEvents) = fixture.phone(bob)
        val file = File(fixture.temp.root, "buzz.haptic").apply {
            writeText("""{"version":{"major":1,"minor":0,"patch":0},"signals":{"continuous":{"envelopes":{"amplitude":[{"time":0,"amplitude":0.5},{"time":0.25,"amplitude":0}]}}}}""")
        }
        chat.input.type("/icon ${file.path} feel this")
        val sent = (bobEvents.nextNonCapabilities() as InboxEvent.MessageReceived).message
        val expected = org.hapticon.core.pattern.PatternFiles.read(file.readBytes(), org.hapticon.core.pattern.PatternFormat.HAPTIC, "buzz").pattern
        assertEquals(Triple("feel this", null as HapticIcon?, expected), Triple(sent.text, sent.icon, sent.pattern))

        val boing = ChatMessage.compose(bob, "", pattern = expected.named("boing"))
        runBlocking { phone.send(alice, boing) }
        chat.out.awaitLine("$bob: [pattern boing: 0.250 s, 2 amplitude keys, 185.0–185.0 Hz, 0 transients]")
        val wav = File(wavDir, "$bob-${boing.id.take(8)}-boing.wav")
        chat.out.awaitLine("  wrote $wav: boing, 11025 samples, 0.250 s at 44100 Hz, f32")
        assertEquals(0, chat.quit())
    }

    @Test
    fun chat_floodOfIcons_showsEveryMessageButRendersOnlyTheBurst() {
        val wavDir = File(fixture.temp.root, "wavs")
        val chat = chat("--wav-dir", wavDir.path)
        chat.err.awaitLine { it.startsWith("chat: connected") }
        val (phone, _) = fixture.phone(bob)
        runBlocking { repeat(5) { phone.send(alice, ChatMessage.compose(bob, "buzz $it", icon = HapticIcon.HIT)) } }
        chat.out.awaitLine { it.startsWith("$bob: buzz 4 ") }
        assertEquals(5, chat.out.lines.count { it.startsWith("$bob: buzz ") })
        assertEquals(2, chat.out.lines.count { it == "  (icon not played: $bob is sending icons too fast)" })
        assertEquals(3, wavDir.list()!!.size)
        assertEquals(0, chat.quit())
    }

    @Test
    fun chat_sameMessageTwice_isShownOnceAndAcknowledgedTwice() {
        val chat = chat()
        chat.err.awaitLine { it.startsWith("chat: connected") }
        val (phone, phoneEvents) = fixture.phone(bob)
        val once = ChatMessage.compose(bob, "only once")
        runBlocking {
            phone.send(alice, once)
            phone.send(alice, once)
            phone.send(alice, ChatMessage.compose(bob, "marker"))
        }
        chat.out.awaitLine("$bob: marker")
        assertEquals(1, chat.out.lines.count { it == "$bob: only once" })
        // The repeat is acknowledged again: the sender resends until a delivered receipt reaches it.
        val receipts = List(3) { (phoneEvents.nextNonCapabilities() as InboxEvent.ReceiptReceived).receipt }
        assertEquals(listOf(once.id, once.id), receipts.filter { it.state == ReceiptState.DELIVERED && it.messageId == once.id }.map { it.messageId })
        assertEquals(0, chat.quit())
    }

    @Test
    fun chat_hostilePayloads_areReportedAndTheChatGoesOn() {
        val chat = chat()
        chat.err.awaitLine { it.startsWith("chat: connected") }
        val (phone, _) = fixture.phone(bob)
        val malloryName = ChatFixture.unique("mallory")
        val mallory = MqttClient.builder().useMqttVersion3().identifier("$malloryName:${DeviceId.generate().value}")
            .serverHost("127.0.0.1").serverPort(fixture.broker.port)
            .simpleAuth().username(malloryName).password(ChatFixture.register(malloryName).toByteArray()).applySimpleAuth()
            .buildBlocking()
        mallory.connect()
        mallory.publishWith().topic(Topics.inbox(alice, malloryName)).qos(MqttQos.AT_LEAST_ONCE).payload("{\"schema\":\"hapticon.message\",\"version\":9}".toByteArray()).send()
        // bob's name in the payload, mallory's (the broker's word) in the topic: dropped as a forgery.
        mallory.publishWith().topic(Topics.inbox(alice, malloryName)).qos(MqttQos.AT_LEAST_ONCE).payload(org.hapticon.messaging.MessageCodec.encode(ChatMessage.compose(bob, "I am bob"))).send()
        val escape = ChatMessage.compose(bob, "\u001b[2Jgotcha\u202e")
        runBlocking { phone.send(alice, escape) }
        chat.err.awaitLine("chat: rejected a payload on hapticon/v1/inbox/$alice/$malloryName: UNSUPPORTED_VERSION (version): this build reads versions 1–2 of \"hapticon.message\", got 9")
        chat.err.awaitLine("chat: rejected a payload on hapticon/v1/inbox/$alice/$malloryName: INVALID_VALUE (sender): sender $bob on the topic of $malloryName")
        chat.out.awaitLine("$bob: \\u001b[2Jgotcha\\u202e")
        mallory.disconnect()
        assertEquals(0, chat.quit())
    }

    @Test
    fun chat_linesWithoutAPeerAndUnknownCommands_getAnswers() {
        val chat = ChatRun(listOf("--broker", fixture.url, "--user", alice, "--password-file", ChatFixture.passwordFile(alice)))
        chat.err.awaitLine { it.startsWith("chat: connected") }
        chat.input.type("hello?")
        chat.input.type("/frobnicate")
        chat.input.type("/icon nonesuch")
        chat.input.type("/to bob/x")
        chat.out.awaitLine("not a user name: 'bob/x'")
        assertEquals(
            listOf(
                "no recipient: start with --to PEER or type /to PEER",
                "unknown command /frobnicate; /help lists them",
                "no icon sent: unknown icon 'nonesuch': not a preset (stroke, hit, knock, hug) and no such file",
                "not a user name: 'bob/x'",
            ),
            chat.out.lines,
        )
        assertEquals(0, chat.quit(command = null))
    }

    @Test
    fun chat_endOfInputRightAfterTyping_stillDeliversWhatWasTyped() {
        val (_, bobEvents) = fixture.phone(bob)
        val chat = chat()
        chat.input.type("sent before the end")
        chat.input.end()
        assertEquals(0, chat.quit(command = null))
        val message = (bobEvents.nextNonCapabilities() as InboxEvent.MessageReceived).message
        assertEquals("sent before the end", message.text)
    }

    @Test
    fun chat_brokerUnreachable_saysWhyAndExitsNonZeroWithTheUndeliveredCount_nextStartSendsIt() {
        val port = java.net.ServerSocket(0, 1, java.net.InetAddress.getByName("127.0.0.1")).use { it.localPort } // nobody listens
        val data = File(fixture.temp.root, "alice-data")
        val args = listOf("--user", alice, "--to", bob, "--password-file", ChatFixture.passwordFile(alice), "--plaintext", "--data-dir", data.path)
        val chat = ChatRun(listOf("--broker", "tcp://127.0.0.1:$port") + args)
        chat.err.awaitLine { it.startsWith("chat: cannot connect: connection refused: nothing accepts connections there") }
        chat.input.type("typed while the broker was down")
        assertEquals(2, chat.quit(command = null))
        val last = chat.err.lines.last()
        assertEquals(true, last.startsWith("hapticon: 1 message(s) not delivered (connection refused: nothing accepts connections there"))
        assertEquals(last, true, last.endsWith("); kept in ${File(data, "chat.db")} and sent at the next start"))

        // The next start, with the broker up, says what it found and sends it.
        val (_, bobEvents) = fixture.phone(bob)
        val again = ChatRun(listOf("--broker", fixture.url) + args)
        again.err.awaitLine("chat: 1 message(s) of an earlier session not yet confirmed by their receivers; sending them again:")
        again.err.awaitLine("  … to $bob: \"typed while the broker was down\" (not yet at the broker)")
        val message = (bobEvents.nextNonCapabilities() as InboxEvent.MessageReceived).message
        assertEquals(alice to "typed while the broker was down", message.sender to message.text)
        assertEquals(0, again.quit())
    }

    @Test
    fun chat_wrongPassword_exitsTwoSayingSo() {
        ChatFixture.register(alice)
        val wrong = File(fixture.temp.root, "wrong.pw").apply { writeText("guess\n") }
        val chat = ChatRun(listOf("--broker", fixture.url, "--user", alice, "--password-file", wrong.path))
        chat.err.awaitLine("chat: the broker refused $alice: bad user name or password")
        assertEquals(2, chat.quit(command = null))
        assertEquals("hapticon: cannot connect to ${fixture.url} as $alice: bad user name or password", chat.err.lines.last())
    }

    @Test
    fun chat_badArguments_exitTwoWithOneLine() {
        val cases = listOf(
            listOf("chat", "--user", "alice") to "hapticon: chat needs --broker",
            listOf("chat", "--broker", fixture.url) to "hapticon: chat needs --user",
            listOf("chat", "--broker", "http://x", "--user", "a") to "hapticon: --broker: broker URL \"http://x\": scheme must be tcp, mqtt, ssl or mqtts",
            listOf("chat", "--broker", fixture.url, "--user", "a/b") to
                "hapticon: --user must be 1..32 letters, digits, '.', '_' or '-', starting with a letter or digit; got 'a/b'",
            listOf("chat", "--broker", fixture.url, "--user", "a", "--password-file", "/nonexistent/pw") to
                "hapticon: --password-file /nonexistent/pw: no such file",
            listOf("chat", "--broker", fixture.url, "--user", "a") to
                "hapticon: chat needs --password-file FILE or --client-cert FILE.p12 (the broker authenticates every user), or --anonymous for a broker run with --allow-anonymous",
        )
        for ((args, line) in cases) {
            val result = cli(*args.toTypedArray())
            assertEquals(result.toString(), 2, result.exitCode)
            assertEquals(listOf(line), result.stderrLines)
        }
    }
}
