package org.hapticon.messaging

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class InviteLinkTest {
    private fun reason(text: String): String = InviteLink.parse(text).exceptionOrNull()!!.message!!

    @Test
    fun toString_userAndBroker_writesTheEscapedLink() {
        val link = InviteLink("alice", BrokerAddress("192.168.1.20", 1883))
        assertEquals("hapticon://invite?user=alice&broker=tcp%3A%2F%2F192.168.1.20%3A1883", link.toString())
    }

    @Test
    fun parse_ownLink_roundTripsExactly() {
        for (link in listOf(
            InviteLink("alice", BrokerAddress("192.168.1.20", 1883)),
            InviteLink("bob.smith_2", BrokerAddress("broker.example.org", 8883, tls = true)),
            InviteLink(null, BrokerAddress("fe80::1", 1884)),
        )) {
            assertEquals(link, InviteLink.parse(link.toString()).getOrThrow())
        }
    }

    @Test
    fun parse_unknownParameterAndSurroundingSpace_ignored() {
        val link = InviteLink.parse("  hapticon://invite?broker=10.0.0.5&user=carol&theme=dark\n").getOrThrow()
        assertEquals(InviteLink("carol", BrokerAddress("10.0.0.5", 1883)), link)
    }

    @Test
    fun parse_badLinks_oneLineReasonEach() {
        val cases = mapOf(
            "https://invite?user=a&broker=tcp://h:1" to "Not a Hapticon invite",
            "hapticon://other?user=a&broker=h" to "Not a Hapticon invite",
            "hapticon://invite/x?user=a&broker=h" to "unexpected parts",
            "hapticon://invite?user=a&broker=h#frag" to "unexpected parts",
            "hapticon://invite?user=a" to "no broker",
            "hapticon://invite?user=a%2F%23&broker=h" to "user name is not valid",
            "hapticon://invite?user=${"a".repeat(33)}&broker=h" to "user name is not valid",
            "hapticon://invite?user=a&user=b&broker=h" to "names \"user\" twice",
            "hapticon://invite?user=a&broker=http%3A%2F%2Fh" to "broker is not valid",
            "hapticon://invite?user=a&broker=tcp%3A%2F%2Fu%3Ap%40h" to "broker is not valid",
            "hapticon://invite?user=a&broker=h%3A99999" to "broker is not valid",
            "hapticon://invite?user=a&broker=h%ZZ" to "Not a link",
            "hapticon://invite?user=a\u0000&broker=h" to "control characters",
            "hapticon://invite?user=a&broker=" + "h".repeat(600) to "too long",
            "not a link at all" to "Not a",
            "" to "Not a",
        )
        for ((text, expected) in cases) {
            val why = reason(text)
            assertTrue("\"$text\": \"$why\" should mention \"$expected\"", why.contains(expected))
            assertTrue("one line: $why", '\n' !in why)
        }
    }
}
