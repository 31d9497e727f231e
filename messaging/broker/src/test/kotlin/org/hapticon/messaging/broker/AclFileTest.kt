package org.hapticon.messaging.broker

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.File

class AclFileTest {
    private val acl = AclFile.DEFAULT

    @Test
    fun defaultAcl_publish_onlyUnderTheUsersOwnName() {
        assertTrue(acl.mayPublish("alice", "alice", "hapticon/v1/inbox/bob/alice"))
        assertTrue(acl.mayPublish("alice", "alice", "hapticon/v1/capabilities/alice"))
        val refused = listOf(
            "hapticon/v1/inbox/bob/carol", "hapticon/v1/inbox/bob", "hapticon/v1/inbox/bob/alice/x",
            "hapticon/v1/capabilities/bob", "hapticon/v1/inbox/+/alice", "other", "#",
        )
        assertEquals(emptyList<String>(), refused.filter { acl.mayPublish("alice", "alice", it) })
        assertFalse(acl.mayPublish(null, "x", "hapticon/v1/inbox/bob/x"))
    }

    @Test
    fun defaultAcl_subscribe_onlyTheOwnInboxAndCapabilities() {
        assertTrue(acl.maySubscribe("bob", "bob", "hapticon/v1/inbox/bob/+"))
        assertTrue(acl.maySubscribe("bob", "bob", "hapticon/v1/inbox/bob/alice"))
        assertTrue(acl.maySubscribe("bob", "bob", "hapticon/v1/capabilities/+"))
        val refused = listOf("#", "+/#", "hapticon/#", "hapticon/v1/inbox/+/+", "hapticon/v1/inbox/alice/+", "hapticon/v1/inbox/bob/#", "hapticon/v1/+/bob/+", "\$SYS/#")
        assertEquals(emptyList<String>(), refused.filter { acl.maySubscribe("bob", "bob", it) })
    }

    @Test
    fun parse_userSectionsTopicsAndDeny_followMosquittosRules() {
        val custom = AclFile.parse(
            """
            |topic read public/#
            |user admin
            |topic readwrite #
            |topic deny secret/#
            |pattern write out/%u/%c
            """.trimMargin(),
        )
        assertTrue(custom.maySubscribe(null, "anon", "public/x")) // before any user line: anonymous only
        assertFalse(custom.maySubscribe("eve", "eve", "public/x"))
        assertTrue(custom.mayPublish("admin", "admin", "anything/here"))
        assertFalse(custom.mayPublish("admin", "admin", "secret/key"))
        assertFalse(custom.maySubscribe("admin", "admin", "#")) // overlaps the deny rule
        assertTrue(custom.mayPublish("eve", "dev1", "out/eve/dev1"))
        assertFalse(custom.mayPublish("eve", "dev1", "out/eve/dev2"))
        assertFalse(custom.mayPublish("eve", "a/b", "out/eve/a/b")) // a client id that would change the filter
    }

    @Test
    fun parse_unknownKeywordOrMissingTopic_namesTheLine() {
        assertEquals("line 2: unknown keyword 'topik'", assertThrows(IllegalArgumentException::class.java) { AclFile.parse("# c\ntopik read a") }.message)
        assertEquals("line 1: expected 'pattern [read|write|readwrite|deny] TOPIC'", assertThrows(IllegalArgumentException::class.java) { AclFile.parse("pattern read") }.message)
    }

    @Test
    fun matchesAndCovers_wildcardsAndDollarTopics() {
        assertTrue(AclFile.matches("a/+/c", "a/b/c"))
        assertTrue(AclFile.matches("a/#", "a"))
        assertFalse(AclFile.matches("#", "\$SYS/x"))
        assertFalse(AclFile.matches("a/+", "a/b/c"))
        assertTrue(AclFile.covers("a/#", "a/+/c"))
        assertFalse(AclFile.covers("a/+", "a/#"))
        assertTrue(AclFile.overlaps("a/+/c", "a/b/#"))
        assertFalse(AclFile.overlaps("a/b", "a/c"))
    }

    @Test
    fun deployedAclFile_isTheEmbeddedBrokersDefault() {
        var dir: File? = File("").absoluteFile
        while (dir != null && !File(dir, "settings.gradle.kts").isFile) dir = dir.parentFile
        val deployed = File(dir ?: throw AssertionError("project root not found"), "companion/mosquitto/aclfile")
        assertEquals(AclFile.DEFAULT_TEXT, deployed.readText())
    }
}
