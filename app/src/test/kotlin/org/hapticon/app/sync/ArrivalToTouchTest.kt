package org.hapticon.app.sync

import android.app.NotificationManager
import android.content.Context
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.TestAndroidKeyStore
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * What the arrival-to-touch bench ([ArrivalToTouchBench]) times, checked for behaviour, not time: each of a few sealed
 * messages through the real broker passes every stage once and in order (decoded, stored, notification posted, then its icon handed to the platform vibrator), nothing vibrates or notifies outside a message,
 * and the icon plays as the peer's communication.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35], shadows = [HandoffVibrator::class])
class ArrivalToTouchTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private lateinit var rig: ArrivalRig

    @Before
    fun setUp() {
        TestAndroidKeyStore.install()
        rig = ArrivalRig(context, temp.newFolder("arrival"))
    }

    @After
    fun tearDown() {
        rig.close()
        TestAndroidKeyStore.uninstall()
    }

    @Test
    fun eachMessage_passesEveryStageOnceInOrder_notificationBeforeItsVibration() {
        val texts = (1..8).map { "knock $it" }
        val arrivals = texts.map { rig.deliver(rig.knock(it)) }

        for (arrival in arrivals) {
            assertEquals(arrival.id, ArrivalStage.entries.map { it.name }, arrival.events)
            // Stamped in order in time too (one clock for sender and phone).
            assertEquals(arrival.id, arrival.at.toList().sorted(), arrival.at.toList())
            // The delivered receipt: acknowledged after the row was stored (awaited beside the notification).
            assertEquals(arrival.id, true, arrival.receiptAcked > arrival.at[ArrivalStage.STORED.ordinal])
        }
        assertEquals(emptyList<String>(), rig.strays)
        val vibrator = context.getSystemService(Vibrator::class.java)
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
        val posted = shadowOf(context.getSystemService(NotificationManager::class.java)).getNotification("bob", MessageNotifier.NOTIFICATION_ID)
        assertEquals(MessageNotifier.channelId("bob", org.hapticon.messaging.AlertChannel.ICONS), posted.channelId)
        val stored = runBlocking { rig.storedTexts() }
        assertEquals(texts, stored)
    }
}
