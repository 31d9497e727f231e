package org.hapticon.messaging

import org.hapticon.core.platform.VibrationVerdict
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class ArrivalAlertsTest {
    private var limiterAsked = 0
    private fun plan(
        conditions: ArrivalConditions = ArrivalConditions.UNRESTRICTED,
        carriesHaptic: Boolean = true,
        autoPlay: Boolean = true,
        limit: VibrationDecision = VibrationDecision.VIBRATE,
        vibration: VibrationVerdict = VibrationVerdict.PLAYS,
    ): ArrivalPlan = ArrivalAlerts.plan(carriesHaptic, autoPlay, conditions, vibration) { limiterAsked++; limit }

    @Test
    fun icon_onARingingPhone_postedOnTheIconChannelThenPlayed() {
        assertEquals(ArrivalPlan(ArrivalAlert.ICON, "plays"), plan())
        assertEquals(ArrivalPlan(ArrivalAlert.ICON, "plays"), plan(ArrivalConditions.UNRESTRICTED.copy(ringer = RingerMode.VIBRATE)))
        assertEquals(AlertChannel.ICONS, ArrivalAlert.ICON.channel)
        assertTrue(ArrivalAlert.ICON.playsIcon)
        assertEquals(2, limiterAsked)
    }

    @Test
    fun silentOrDoNotDisturb_neitherIconNorRing_andTheSenderKeepsItsBudget() {
        val silent = plan(ArrivalConditions.UNRESTRICTED.copy(ringer = RingerMode.SILENT))
        assertEquals(ArrivalPlan(ArrivalAlert.NOTIFICATION, "the phone is on silent"), silent)
        for (filter in listOf(DoNotDisturb.Filter.NONE, DoNotDisturb.Filter.ALARMS, DoNotDisturb.Filter.PRIORITY)) {
            val dnd = plan(ArrivalConditions.UNRESTRICTED.copy(doNotDisturb = DoNotDisturb(filter)))
            assertEquals(ArrivalPlan(ArrivalAlert.NOTIFICATION, "Do Not Disturb"), dnd)
        }
        // On the message channel, where Android itself silences the ring (ringer mode) or intercepts it (DND).
        assertEquals(AlertChannel.MESSAGES, ArrivalAlert.NOTIFICATION.channel)
        assertFalse(ArrivalAlert.NOTIFICATION.playsIcon)
        assertEquals(0, limiterAsked)
    }

    @Test
    fun noIconOrAutoPlayOff_theMessageChannelAlerts() {
        assertEquals(ArrivalPlan(ArrivalAlert.NOTIFICATION, "no icon"), plan(carriesHaptic = false))
        assertEquals(ArrivalPlan(ArrivalAlert.NOTIFICATION, "auto-play is off"), plan(autoPlay = false))
    }

    @Test
    fun silencedConversationOrRateLimit_postedQuietlyWithoutTheIcon() {
        val silenced = plan(ArrivalConditions.UNRESTRICTED.copy(iconChannel = ChannelSettings(alerting = false)))
        assertEquals(ArrivalPlan(ArrivalAlert.QUIET, "the conversation is silenced"), silenced)
        assertEquals(0, limiterAsked)
        assertEquals(ArrivalPlan(ArrivalAlert.QUIET, "rate limit: SENDER_LIMIT"), plan(limit = VibrationDecision.SENDER_LIMIT))
        assertEquals(AlertChannel.ICONS, ArrivalAlert.QUIET.channel)
    }

    @Test
    fun vibratorWouldNotPlay_theMessageChannelAlertsInstead() {
        val saving = plan(vibration = VibrationVerdict.BATTERY_SAVER)
        assertEquals(ArrivalPlan(ArrivalAlert.NOTIFICATION, VibrationVerdict.BATTERY_SAVER.explanation), saving)
        assertEquals(0, limiterAsked)
    }

    @Test
    fun priorityOnly_letsThroughWhatZenModeFilteringLetsThrough() {
        val channel = ChannelSettings(alerting = true)
        val priority = DoNotDisturb(DoNotDisturb.Filter.PRIORITY)
        assertFalse(priority.letsThrough(channel))
        assertTrue(priority.letsThrough(channel.copy(bypassesDnd = true)))
        // Messages from anyone; from contacts only, the app's Person (no contacts URI) does not match.
        assertTrue(priority.copy(messages = DoNotDisturb.Senders.ANYONE).letsThrough(channel))
        assertFalse(priority.copy(messages = DoNotDisturb.Senders.CONTACTS).letsThrough(channel))
        assertFalse(priority.copy(messages = DoNotDisturb.Senders.STARRED).letsThrough(channel))
        // Conversations: only a notification that is one; from priority conversations, only a priority one.
        val conversation = channel.copy(conversation = true)
        assertTrue(priority.copy(conversations = DoNotDisturb.ConversationSenders.ANYONE).letsThrough(conversation))
        assertFalse(priority.copy(conversations = DoNotDisturb.ConversationSenders.ANYONE).letsThrough(channel))
        assertFalse(priority.copy(conversations = DoNotDisturb.ConversationSenders.IMPORTANT).letsThrough(conversation))
        assertTrue(priority.copy(conversations = DoNotDisturb.ConversationSenders.IMPORTANT).letsThrough(conversation.copy(importantConversation = true)))
        // Total silence and alarms only: nothing, whatever the channel.
        assertFalse(DoNotDisturb(DoNotDisturb.Filter.NONE).letsThrough(channel.copy(bypassesDnd = true, conversation = true)))
        assertFalse(DoNotDisturb(DoNotDisturb.Filter.ALARMS).letsThrough(channel.copy(bypassesDnd = true)))
        assertTrue(DoNotDisturb.OFF.letsThrough(channel))
    }

    @Test
    fun priorityConversation_underPriorityOnly_stillPlays() {
        val conditions = ArrivalConditions.UNRESTRICTED.copy(
            doNotDisturb = DoNotDisturb(DoNotDisturb.Filter.PRIORITY, conversations = DoNotDisturb.ConversationSenders.IMPORTANT),
            iconChannel = ChannelSettings(alerting = true, importantConversation = true, conversation = true),
        )
        assertEquals(ArrivalAlert.ICON, plan(conditions).alert)
    }

    @Test
    fun displayText_controlAndBidiCharactersRemoved_lineBreaksKept() {
        // U+202E would show "photo\u202Egnp.exe" as "photoexe.png".
        assertEquals("photognp.exe", DisplayText.neutralise("photo\u202Egnp.exe"))
        assertEquals("a b", DisplayText.neutralise("a\u202C\u0007\tb"))
        assertEquals("line 1\nline 2\nline 3", DisplayText.neutralise("line 1\r\nline 2\u2028line 3"))
        assertEquals("abc", DisplayText.neutralise("a\u0000b\u009Bc\u2066\u2069"))
        assertEquals("héllo 👋", DisplayText.neutralise("héllo 👋"))
    }
}
