package org.hapticon.messaging

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class TopicsTest {
    @Test
    fun inboxAndCapabilities_validUser_areTheVersionOneTopics() {
        assertEquals("hapticon/v1/inbox/alice/bob", Topics.inbox("alice", "bob"))
        assertEquals("hapticon/v1/inbox/alice/+", Topics.inboxFilter("alice"))
        assertEquals("hapticon/v1/capabilities/bob.k-2_x", Topics.capabilities("bob.k-2_x"))
    }

    @Test
    fun isValidUserName_wildcardsSeparatorsAndOddNames_areInvalid() {
        val invalid = listOf("", "+", "#", "a/b", "a+", ".", "..", "-a", "a b", "é", "a\u0000", "x".repeat(Topics.MAX_USER_NAME_LENGTH + 1))
        assertEquals(emptyList<String>(), invalid.filter(Topics::isValidUserName))
        val valid = listOf("a", "Alice", "bob.smith", "p_01", "x".repeat(Topics.MAX_USER_NAME_LENGTH))
        assertEquals(valid, valid.filter(Topics::isValidUserName))
    }

    @Test
    fun inbox_invalidUser_throws() {
        assertThrows(IllegalArgumentException::class.java) { Topics.inbox("#", "bob") }
        assertThrows(IllegalArgumentException::class.java) { Topics.inbox("bob", "+") }
        assertThrows(IllegalArgumentException::class.java) { Topics.inboxFilter("a/b") }
    }

    @Test
    fun inboxSender_readsTheLastLevelOnlyFromTheUsersOwnInbox() {
        assertEquals("alice", Topics.inboxSender("bob", "hapticon/v1/inbox/bob/alice"))
        assertEquals(null, Topics.inboxSender("bob", "hapticon/v1/inbox/carol/alice"))
        assertEquals(null, Topics.inboxSender("bob", "hapticon/v1/inbox/bob"))
        assertEquals(null, Topics.inboxSender("bob", "hapticon/v1/inbox/bob/"))
        assertEquals(null, Topics.inboxSender("bob", "hapticon/v1/inbox/bob/alice/x"))
        assertEquals(null, Topics.inboxSender("bob", "hapticon/v1/inbox/bobby/alice"))
    }

    @Test
    fun capabilitiesOwner_readsTheUserOnlyFromCapabilitiesTopics() {
        assertEquals("bob", Topics.capabilitiesOwner("hapticon/v1/capabilities/bob"))
        assertEquals(null, Topics.capabilitiesOwner("hapticon/v1/inbox/bob"))
        assertEquals(null, Topics.capabilitiesOwner("hapticon/v1/capabilities/bob/extra"))
        assertEquals(null, Topics.capabilitiesOwner("hapticon/v1/capabilities/"))
    }
}
