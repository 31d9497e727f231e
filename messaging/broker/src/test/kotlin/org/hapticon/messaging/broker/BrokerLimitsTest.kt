package org.hapticon.messaging.broker

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test

/** The bookkeeping behind [BrokerLimits], on a clock the test moves. Against a running broker: messaging's BrokerAbuseContract. */
class BrokerLimitsTest {
    private var now = 0L
    private val clock = { now }
    private fun advanceSeconds(s: Long) {
        now += s * 1_000_000_000
    }

    @Test
    fun clientIds_onlyTheUsersOwnNameAColonAnd32HexDigits() {
        val device = "0123456789abcdef0123456789abcdef"
        assertTrue(ClientIds.isDeviceOf("bob", "bob:$device"))
        assertTrue(ClientIds.isDeviceOf("b.o-b_1", "b.o-b_1:$device"))
        for (other in listOf("bob", "bob:", "bob:${device.drop(1)}", "bob:${device}0", "bob:${device.uppercase()}", "bobby:$device", "alice:$device", "bob/$device")) {
            assertFalse(other, ClientIds.isDeviceOf("bob", other))
        }
        assertEquals("bob", ClientIds.userOf("bob:$device"))
        assertEquals("alice:x", ClientIds.userOf("alice:x:$device")) // the broker never accepts such a user name (isDeviceOf came first)
        assertNull(ClientIds.userOf("bob"))
        assertNull(ClientIds.userOf(":$device"))
    }

    @Test
    fun buckets_spendThenRegainOnePerPeriod() {
        val buckets = Buckets(capacity = 3, refillNanos = 10_000_000_000, nanoTime = clock)
        assertEquals(listOf(true, true, true, false), List(4) { buckets.take("a") })
        assertTrue(buckets.take("b")) // another key has its own
        advanceSeconds(9)
        assertFalse(buckets.take("a"))
        advanceSeconds(1)
        assertEquals(listOf(true, false), List(2) { buckets.take("a") })
        advanceSeconds(1_000)
        assertEquals(listOf(true, true, true, false), List(4) { buckets.take("a") }) // never more than the capacity
    }

    @Test
    fun loginThrottle_failuresFromOneAddress_refusedBeforeHashingUntilItRegains() {
        val throttle = LoginThrottle(BrokerLimits(failedLoginsPerSource = 3, failedLoginsPerUser = 100, failedLoginRefillMillis = 30_000), clock)
        repeat(3) { (throttle.begin("10.0.0.9", "bob", knownDevice = false) as LoginThrottle.Permit).finish(success = false) }
        assertEquals(LoginThrottle.Refusal.SOURCE, throttle.begin("10.0.0.9", "bob", knownDevice = false))
        assertEquals(LoginThrottle.Refusal.SOURCE, throttle.begin("10.0.0.9", "carol", knownDevice = false))
        // A device of carol's that has a session (a secret client id) is not locked out by what others did from its address.
        assertTrue(throttle.begin("10.0.0.9", "carol", knownDevice = true) is LoginThrottle.Permit)
        // Another address is not held to this one's failures.
        assertTrue(throttle.begin("10.0.0.7", "bob", knownDevice = false) is LoginThrottle.Permit)
        advanceSeconds(30)
        assertTrue(throttle.begin("10.0.0.9", "carol", knownDevice = false) is LoginThrottle.Permit)
    }

    @Test
    fun loginThrottle_failuresForOneUserFromManyAddresses_refusedExceptOnTheUsersKnownDevices() {
        val throttle = LoginThrottle(BrokerLimits(failedLoginsPerSource = 100, failedLoginsPerUser = 3), clock)
        repeat(3) { (throttle.begin("10.0.0.$it", "bob", knownDevice = false) as LoginThrottle.Permit).finish(success = false) }
        assertEquals(LoginThrottle.Refusal.USER, throttle.begin("10.0.0.50", "bob", knownDevice = false))
        // Bob's own device (a session he made before; its client id is a secret) still gets its password checked,
        // even while a stranger's hash for bob is being computed, and its failure is charged to nobody.
        val stranger = throttle.begin("10.0.0.51", "alice", knownDevice = false) as LoginThrottle.Permit
        val own = throttle.begin("10.0.0.51", "bob", knownDevice = true) as LoginThrottle.Permit
        own.finish(success = false)
        stranger.finish(success = true)
        assertTrue(throttle.begin("10.0.0.50", "alice", knownDevice = false) is LoginThrottle.Permit)
    }

    @Test
    fun loginThrottle_loginsBeingHashedReserveAFailureEach_andTheQueueIsBounded() {
        val throttle = LoginThrottle(BrokerLimits(failedLoginsPerSource = 2, failedLoginsPerUser = 100, waitingLogins = 3), clock)
        // 32 at once from one address: only as many are hashed as it has failures left.
        val decisions = List(32) { throttle.begin("10.0.0.1", "bob", knownDevice = false) }
        assertEquals(2, decisions.count { it is LoginThrottle.Permit })
        assertEquals(30, decisions.count { it == LoginThrottle.Refusal.BUSY })
        val other = throttle.begin("10.0.0.2", "alice", knownDevice = false) as LoginThrottle.Permit
        assertEquals(LoginThrottle.Refusal.BUSY, throttle.begin("10.0.0.3", "carol", knownDevice = false)) // 3 wait
        decisions.filterIsInstance<LoginThrottle.Permit>().forEach { it.finish(success = false) }
        other.finish(success = true)
        assertEquals(LoginThrottle.Refusal.SOURCE, throttle.begin("10.0.0.1", "bob", knownDevice = false))
        // Successes cost nothing: alice's address has both its failures left.
        assertEquals(2, List(2) { throttle.begin("10.0.0.2", "alice", knownDevice = false) }.count { it is LoginThrottle.Permit })
    }

    @Test
    fun inboxQuota_oneSenderHoldsAtMostItsShareOthersStillGetIn() {
        val quota = InboxQuota(share = 3)
        val bob = "bob:0123456789abcdef0123456789abcdef"
        quota.session(bob, fresh = false)
        assertEquals(listOf(true, true, true, false, false), List(5) { quota.admit("mallory", "bob") })
        assertEquals(listOf(true, true), List(2) { quota.admit("alice", "bob") })
        quota.sent(bob, "mallory")
        assertEquals(listOf(true, false), List(2) { quota.admit("mallory", "bob") })
        assertEquals(3, quota.waiting(bob, "mallory"))
        // Nobody subscribed as carol: nothing is held back (the broker keeps nothing for her anyway).
        assertTrue(List(10) { quota.admit("mallory", "carol") }.all { it })
        // A clean session starts empty.
        quota.session(bob, fresh = true)
        assertEquals(0, quota.waiting(bob, "mallory"))
    }

    @Test
    fun inboxQuota_twoDevices_heldBackOnlyWhenEveryDeviceHoldsTheFullShare() {
        val quota = InboxQuota(share = 2)
        val phone = "bob:0123456789abcdef0123456789abcdef"
        val laptop = "bob:fedcba9876543210fedcba9876543210"
        quota.session(phone, fresh = false)
        quota.session(laptop, fresh = false)
        assertTrue(quota.isKnown(laptop))
        assertFalse(quota.isKnown("bob:00000000000000000000000000000000"))
        assertEquals(listOf(true, true, false), List(3) { quota.admit("mallory", "bob") })
        // The phone is online and takes both; the laptop stays offline with mallory's full share.
        repeat(2) { quota.sent(phone, "mallory") }
        assertEquals(listOf(true, true, false), List(3) { quota.admit("mallory", "bob") })
        assertEquals(4, quota.waiting(laptop, "mallory"))
    }
}
