package org.hapticon.devicecheck.dumpsys

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class NotificationDumpTest {
    private val dump = requireNotNull(javaClass.getResource("/dumpsys/notification-android15.txt")).readText()

    @Test
    fun parse_eachRecordWithPackageTagChannelTemplateAndPostTimes() {
        val records = NotificationDump.parse(dump)

        assertEquals(2, records.size)
        val ongoing = records[0]
        assertEquals(2, ongoing.id)
        assertEquals(null, ongoing.tag)
        assertEquals("reachable", ongoing.channel)
        assertFalse(ongoing.isMessagingStyle)

        val message = records[1]
        assertEquals("org.hapticon.app", message.packageName)
        assertEquals(1, message.id)
        assertEquals("peer-7f3a", message.tag)
        assertEquals(4, message.importance)
        assertEquals("chat-peer-7f3a", message.channel)
        assertEquals("android.app.Notification\$MessagingStyle", message.template)
        assertTrue(message.isMessagingStyle)
        // First posted for an earlier message; this message's post updated it.
        assertEquals(1764165781020L, message.creationTimeMillis)
        assertEquals(1764165787386L, message.updateTimeMillis)
        assertEquals(false, message.intercepted)
        // Its own block only: the message line is in it, the ongoing notification's text is not.
        assertTrue("〰 knock · device check" in message.dump)
        assertFalse("Connected to tcp://" in message.dump)
    }

    @Test
    fun parse_noRecords_empty() {
        assertEquals(emptyList<PostedNotification>(), NotificationDump.parse("Current Notification Manager state:\n  Notification List:\n"))
    }
}
