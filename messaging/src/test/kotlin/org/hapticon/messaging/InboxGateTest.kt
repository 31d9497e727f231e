package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Test

class InboxGateTest {
    private val clock = FakeClock()
    private val gate = InboxGate(BoundedDeduplicator(), VibrationRateLimiter(clock))

    @Test
    fun admit_sameIdTwice_isNewThenDuplicate() {
        val message = ChatMessage(ID_1, "bob", 1, "hi", icon = HapticIcon.KNOCK)
        assertEquals(Admission.New(message, VibrationDecision.VIBRATE), gate.admit(message))
        assertEquals(Admission.Duplicate, gate.admit(message))
    }

    @Test
    fun admit_messageWithoutIcon_hasNoVibrationDecisionAndUsesNoToken() {
        repeat(5) { i ->
            val message = ChatMessage("00000000-0000-4000-8000-00000000000$i", "bob", 1, "hi")
            assertEquals(Admission.New(message, null), gate.admit(message))
        }
        val withIcon = ChatMessage(ID_1, "bob", 1, "", icon = HapticIcon.HIT)
        assertEquals(Admission.New(withIcon, VibrationDecision.VIBRATE), gate.admit(withIcon))
    }

    @Test
    fun admit_floodOfIconsFromOneSender_isStoredButOnlyTheBurstVibrates() {
        val decisions = List(6) { i ->
            val message = ChatMessage("00000000-0000-4000-8000-00000000000$i", "mallory", 1, "buzz", icon = HapticIcon.HIT)
            (gate.admit(message) as Admission.New).vibration
        }
        assertEquals(List(3) { VibrationDecision.VIBRATE } + List(3) { VibrationDecision.SENDER_LIMIT }, decisions)
    }

    @Test
    fun admit_strokeIcon_chargesItsDurationInMillisecondsToTheDutyCycle() {
        // stroke lasts 10.8 s; a 21.6 s budget holds exactly two.
        val tight = InboxGate(BoundedDeduplicator(), VibrationRateLimiter(clock, dutyWindowMillis = 43_200, maxDutyCycle = 0.5))
        val decisions = List(3) { i ->
            (tight.admit(ChatMessage("00000000-0000-4000-8000-00000000000$i", "s$i", 1, "", icon = HapticIcon.STROKE)) as Admission.New).vibration
        }
        assertEquals(listOf(VibrationDecision.VIBRATE, VibrationDecision.VIBRATE, VibrationDecision.DUTY_CYCLE_LIMIT), decisions)
    }
}
