package org.hapticon.app.sync

import android.app.Notification
import org.hapticon.messaging.ConnectionState
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.Robolectric
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class ReachableServiceTest {
    @Test
    fun created_runsInTheForegroundWithAnOngoingStatusNotification() {
        val controller = Robolectric.buildService(ReachableService::class.java).create()
        val shadow = shadowOf(controller.get())
        assertTrue(shadow.isLastForegroundNotificationAttached)
        val notification = shadow.lastForegroundNotification
        assertEquals(ReachableService.CHANNEL, notification.channelId)
        assertTrue((notification.flags and Notification.FLAG_ONGOING_EVENT) != 0)
        // A fresh install has no broker yet.
        assertEquals("Not connected to a broker", notification.extras.getString(Notification.EXTRA_TEXT))
        assertEquals(android.app.Service.START_STICKY, controller.get().onStartCommand(null, 0, 1))
        controller.destroy()
    }

    @Test
    fun statusText_namesTheBrokerAndTheState() {
        val broker = "tcp://192.168.1.20:1883"
        assertEquals("Connected to tcp://192.168.1.20:1883", ReachableService.statusText(broker, ConnectionState.Connected))
        assertEquals(
            "Connecting to tcp://192.168.1.20:1883… (Connection refused)",
            ReachableService.statusText(broker, ConnectionState.Connecting("Connection refused")),
        )
        assertEquals("Refused by tcp://192.168.1.20:1883: not authorized", ReachableService.statusText(broker, ConnectionState.Failed("not authorized")))
    }

    // The boot path, through Android's broadcast to the manifest's receiver: KeepAliveTest.
}
