package org.hapticon.devicecheck

import android.os.Bundle
import android.os.SystemClock
import android.os.VibratorManager
import androidx.test.ext.junit.runners.AndroidJUnit4
import androidx.test.platform.app.InstrumentationRegistry
import androidx.test.uiautomator.UiDevice
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.devicecheck.dumpsys.PostedNotification
import org.hapticon.devicecheck.dumpsys.Step
import org.hapticon.devicecheck.dumpsys.VibrationRecord
import org.hapticon.devicecheck.dumpsys.VibratorDump
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.ReceiptState
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assume.assumeTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import java.time.LocalDateTime
import java.time.ZoneId

/**
 * A knock arrives while nobody looks at the app, and Android decides what the phone does. Each test prepares the app
 * (its account, "Stay reachable", "play icons when messages arrive"), makes sure it is online with a text message,
 * puts it where a pocket puts it, sends the knock as the peer and reads the outcome where Android keeps it:
 * `dumpsys vibrator_manager` for what vibrated (the usage Android judged it by, the waveform, whether it was played or
 * refused), `dumpsys notification` for the conversation notification, the peer's receipts for what the sender is told.
 * docs/device-check.md says what each failure means.
 */
@RunWith(AndroidJUnit4::class)
class ReceivedKnockTest {
    private val instrumentation = InstrumentationRegistry.getInstrumentation()
    private val args = DeviceCheckArguments.from(InstrumentationRegistry.getArguments())
    private val device = UiDevice.getInstance(instrumentation)
    private val app = AppUnderTest(Shell(instrumentation.uiAutomation), device, instrumentation.context)
    private lateinit var peer: Peer

    @Before
    fun setUp() {
        val vibrator = instrumentation.context.getSystemService(VibratorManager::class.java).defaultVibrator
        assumeTrue("this phone has no vibrator", vibrator.hasVibrator())
        app.doNotDisturb(false)
        app.screenOn()
        peer = Peer(args).also { it.connect() }
    }

    @After
    fun tearDown() {
        runCatching { peer.close() }
        app.doNotDisturb(false)
        app.screenOn()
        device.pressHome()
    }

    /**
     * Swiped away with "Stay reachable" on, screen off: the knock is announced by its conversation notification, then
     * felt once, as a communication request, with the knock's waveform; no notification alert of the channel competes
     * with it; the sender gets "felt".
     */
    @Test
    fun swipedAwayScreenOff_knockIsNotifiedThenFeltAsCommunicationRequest_senderGetsFelt() {
        app.prepare(args, stayReachable = true, autoPlay = true)
        app.launch()
        online()
        app.swipeAway()
        app.screenOff()
        SystemClock.sleep(SETTLE_MILLIS)

        val (_, since, felt, vibration, dump) = knockPlayedOnce("the app did not receive the knock while swiped away with Stay reachable on")
        val notification = conversationNotification()
        assertNotNull("no notification of the conversation with ${args.peer}: ${app.notifications()}", notification)
        assertTrue("the message notification is not MessagingStyle: $notification", notification!!.isMessagingStyle)
        val postedAt = notification.updateTimeMillis ?: notification.creationTimeMillis!!
        val vibratedAt = epochMillis(vibration.createdAt!!)
        assertTrue("the knock vibrated at $vibratedAt, before its notification was posted at $postedAt: the icon must follow " +
            "the notification", vibratedAt >= postedAt)
        val alerts = dump.notificationAlertsOf(AppUnderTest.PACKAGE).filter { it.played && after(it, since) }
        assertTrue("the notification's own vibration competed with the knock: $alerts", alerts.isEmpty())
        assertNotNull("the knock vibrated but the sender got no \"felt\" within ${FELT_MILLIS / 1000} s", felt)
        note("knock: ${vibration.usage}, ${vibration.status}, ${vibration.durationMillis} ms, ${vibratedAt - postedAt} ms after " +
            "its notification; felt ${felt!!.atUptimeMillis - sentUptime} ms after sending; app process state " +
            "${dump.processStates[app.uid]}")
    }

    /**
     * The conversation open, "Stay reachable" off, screen off: the open activity is now TOP_SLEEPING, a background
     * state for the vibrator (VibrationSettings: foreground only at PROCESS_STATE_IMPORTANT_FOREGROUND or better), so
     * only an allowed usage passes. The knock must still be felt as a communication request, be notified (nobody sees
     * the open chat), and earn "felt" but no "read".
     */
    @Test
    fun conversationOpenScreenOff_knockStillFeltAndNotified_noRead() {
        app.prepare(args, stayReachable = false, autoPlay = true)
        app.openConversation(args.peer)
        online()
        app.screenOff()
        SystemClock.sleep(SETTLE_MILLIS)

        val (knock, _, felt, vibration, dump) = knockPlayedOnce("the app, open in the conversation, stopped receiving when the screen went off")
        assertNotNull("the knock vibrated but the sender got no \"felt\" within ${FELT_MILLIS / 1000} s", felt)
        assertNull("a \"read\" receipt went out while the screen was off", peer.find(knock, ReceiptState.READ))
        val notification = conversationNotification()
        assertTrue("no MessagingStyle notification for a message nobody could see: ${app.notifications()}",
            notification?.isMessagingStyle == true)
        note("knock: ${vibration.usage}, ${vibration.status}; app process state ${dump.processStates[app.uid]} " +
            "(background for the vibrator above 6)")
    }

    /**
     * Do Not Disturb on, app swiped away with "Stay reachable": the message arrives and is stored ("delivered"), but
     * nothing vibrates, neither the icon nor the notification, and the sender is not told "felt".
     */
    @Test
    fun doNotDisturb_knockArrivesButNothingVibrates_noFelt() {
        app.prepare(args, stayReachable = true, autoPlay = true)
        app.launch()
        online()
        app.swipeAway()
        app.doNotDisturb(true)
        app.screenOff()
        SystemClock.sleep(SETTLE_MILLIS)

        val (knock, since) = sendKnock()
        assertNotNull("no \"delivered\" receipt within ${DELIVERY_MILLIS / 1000} s: the app did not receive the knock in Do Not Disturb",
            peer.await(knock, ReceiptState.DELIVERED, DELIVERY_MILLIS))
        val felt = peer.await(knock, ReceiptState.FELT, QUIET_MILLIS)
        val (vibrations, dump) = appVibrationsSince(since, atLeast = 0)
        val alerts = dump.notificationAlertsOf(AppUnderTest.PACKAGE).filter { it.played && after(it, since) }
        assertTrue("the app vibrated in Do Not Disturb: $vibrations", vibrations.isEmpty())
        assertTrue("the notification vibrated in Do Not Disturb: $alerts", alerts.isEmpty())
        assertNull("the sender was told \"felt\" for a knock that did not play (Do Not Disturb)", felt)
        note("Do Not Disturb: delivered, no vibration, no felt; notification intercepted: ${conversationNotification()?.intercepted}")
    }

    private var sentUptime = 0L

    /** Sends a text and waits for its "delivered": the app is connected and subscribed. */
    private fun online() {
        val ping = peer.send("device check: are you there?")
        assertNotNull("the app did not answer a text with \"delivered\" within ${ONLINE_MILLIS / 1000} s: it is not connected to " +
            "${args.broker} as ${args.user} (is the broker running and `adb reverse tcp:1883` set?)",
            peer.await(ping, ReceiptState.DELIVERED, ONLINE_MILLIS))
    }

    /** What a knock did on the phone: the message, when it was sent (phone time), its "felt" if one came, its vibration. */
    private data class Played(
        val knock: ChatMessage,
        val since: LocalDateTime,
        val felt: Peer.Arrived?,
        val vibration: VibrationRecord,
        val dump: VibratorDump,
    )

    /**
     * Sends the knock, waits for its "delivered" (failing with [undelivered] without one) and its "felt", and checks that
     * the app vibrated exactly once for it, as the knock ([checkKnock]).
     */
    private fun knockPlayedOnce(undelivered: String): Played {
        val (knock, since) = sendKnock()
        assertNotNull("no \"delivered\" receipt within ${DELIVERY_MILLIS / 1000} s: $undelivered",
            peer.await(knock, ReceiptState.DELIVERED, DELIVERY_MILLIS))
        val felt = peer.await(knock, ReceiptState.FELT, FELT_MILLIS)
        val (vibrations, dump) = appVibrationsSince(since, atLeast = 1)
        val vibration = vibrations.singleOrNull()
            ?: failure("expected the knock to vibrate once; the app's vibrations since it was sent: ${vibrations.ifEmpty { "none" }}; ${context(dump)}")
        checkKnock(vibration, dump)
        return Played(knock, since, felt, vibration, dump)
    }

    /** Sends the knock preset; returns it and the phone's local time just before sending. */
    private fun sendKnock(): Pair<ChatMessage, LocalDateTime> {
        val since = LocalDateTime.now().minusNanos(CLOCK_SLACK_NANOS)
        sentUptime = SystemClock.uptimeMillis()
        return peer.send("device check: knock", HapticIcon.KNOCK) to since
    }

    /**
     * The app's vibrations created since [since], polling the dump until at least [atLeast] are listed (a vibration is
     * recorded when it ends) or [RECORD_MILLIS] pass; for none expected, one read after the quiet wait.
     */
    private fun appVibrationsSince(since: LocalDateTime, atLeast: Int): Pair<List<VibrationRecord>, VibratorDump> {
        var dump = app.vibrator()
        AppUnderTest.waitFor(if (atLeast == 0) 0 else RECORD_MILLIS) {
            dump = app.vibrator()
            dump.of(AppUnderTest.PACKAGE).count { after(it, since) } >= atLeast
        }
        return dump.of(AppUnderTest.PACKAGE).filter { after(it, since) } to dump
    }

    /**
     * What Android did with the knock: played (not refused), as a communication request (allowed from the background
     * and not silenced by the ringer, VibrationSettings), and — for the step renderers, whose waveform haptics-core
     * computes — exactly the knock's steps as the app asked for them (the dump's "original" effect, before the user's
     * intensity scales it).
     */
    private fun checkKnock(vibration: VibrationRecord, dump: VibratorDump) {
        assertEquals("the knock's vibration usage (${context(dump)})", "COMMUNICATION_REQUEST", vibration.usage)
        assertTrue("Android did not play the knock: status ${vibration.status} ($vibration)", vibration.played)
        val renderer = peer.capabilitiesOf(args.user)?.renderer
        val expected = when (renderer) {
            RendererKind.AMPLITUDE_WAVEFORM -> VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK)
            RendererKind.ON_OFF -> VibrationWaveform.onOff(HapticIcon.KNOCK)
            else -> null
        }
        if (expected == null) {
            note("renderer ${renderer ?: "unknown"}: the knock's waveform is not a step waveform to compare; usage and status checked")
            return
        }
        val steps = vibration.originalSteps ?: failure("the knock was not played as steps: ${vibration.originalEffect}")
        assertEquals("the knock's step timings", expected.timings().map { it.toInt() }, steps.map(Step::durationMillis))
        val amplitudes = expected.amplitudes()
        for ((i, step) in steps.withIndex()) {
            assertEquals("the knock's amplitude at step $i (${steps})", amplitudes[i] / 255f, step.amplitude, AMPLITUDE_TOLERANCE)
        }
    }

    private fun conversationNotification(): PostedNotification? =
        app.notifications().firstOrNull { it.isMessagingStyle && (it.tag == args.peer || args.peer in it.channel || "=${args.peer}" in it.dump) }
            ?: app.notifications().firstOrNull { args.peer in it.dump }

    private fun failure(message: String): Nothing = throw AssertionError(message)

    private fun after(record: VibrationRecord, since: LocalDateTime): Boolean = record.createdAt?.isBefore(since) == false

    private fun epochMillis(time: LocalDateTime): Long = time.atZone(ZoneId.systemDefault()).toInstant().toEpochMilli()

    private fun context(dump: VibratorDump): String =
        "app uid ${app.uid} process state ${dump.processStates[app.uid] ?: "not listed"}; its recent vibrations: " +
            dump.of(AppUnderTest.PACKAGE).takeLast(3)

    /** A line for the report under this test's result (`./build device-check` prints it). */
    private fun note(text: String) {
        instrumentation.sendStatus(NOTE_STATUS, Bundle().apply { putString(NOTE_KEY, text) })
    }

    private companion object {
        const val SETTLE_MILLIS = 3_000L // the process state follows HOME, kill and screen-off within this
        const val ONLINE_MILLIS = 30_000L
        const val DELIVERY_MILLIS = 30_000L
        const val FELT_MILLIS = 10_000L
        const val QUIET_MILLIS = 10_000L // no "felt" may come in this long
        const val RECORD_MILLIS = 5_000L
        const val CLOCK_SLACK_NANOS = 500_000_000L // the dump's times and ours come from one clock; this is rounding room
        // The Android 14+ dump writes amplitudes with two decimals.
        const val AMPLITUDE_TOLERANCE = 0.006f
        const val NOTE_STATUS = 2
        const val NOTE_KEY = "hapticon.note"
    }
}
