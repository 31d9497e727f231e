package org.hapticon.messaging.broker

/**
 * How much one participant may ask of an [EmbeddedBroker] with [BrokerSecurity.Authenticated], so that nobody can
 * flood or lock out another (docs/security.md, "Floods and guessing").
 *
 * @property inboxShare QoS 1 messages one sender may have waiting, not yet sent on, in one device session of a
 *   recipient. Beyond it the sender's further messages to that recipient are acknowledged and dropped (the sender's
 *   outbox sends them again until the recipient's receipt comes), so one sender fills at most this much of a
 *   session's queue of [EmbeddedBroker.MAX_QUEUED_MESSAGES] and the rest stays for everyone else. With several
 *   devices a message is held back only when every one of the recipient's sessions holds the sender's full share.
 * @property failedLoginsPerSource wrong passwords one client address may send before it must wait; it regains one
 *   every [failedLoginRefillMillis]. Checked before the password hash is computed. A device that already has a
 *   session of its user (its client id is a secret, OWASP's "device cookie") is never held to these limits, so nobody
 *   can lock a user's own devices out.
 * @property failedLoginsPerUser the same per user name, so that guessing one user's password from many addresses is
 *   slow too.
 * @property failedLoginRefillMillis how long it takes to regain one failed login.
 * @property waitingLogins logins (needing a password hash) that may wait for the one hashing thread; more are told
 *   "server unavailable" at once and try again.
 * @property retainedPublishes publishes of a user's own retained topics (capabilities, keys) allowed in a burst; it
 *   regains one every [retainedRefillMillis]. Each such publish reaches every session of every user.
 * @property retainedRefillMillis how long it takes to regain one retained publish.
 */
public data class BrokerLimits(
    val inboxShare: Int = 1_000,
    val failedLoginsPerSource: Int = 5,
    val failedLoginsPerUser: Int = 10,
    val failedLoginRefillMillis: Long = 60_000,
    val waitingLogins: Int = 16,
    val retainedPublishes: Int = 20,
    val retainedRefillMillis: Long = 6_000,
) {
    init {
        require(inboxShare >= 1) { "inboxShare must be >= 1, was $inboxShare" }
        require(failedLoginsPerSource >= 1 && failedLoginsPerUser >= 1) { "failed login limits must be >= 1" }
        require(failedLoginRefillMillis >= 1 && retainedRefillMillis >= 1) { "refill periods must be >= 1 ms" }
        require(waitingLogins >= 1) { "waitingLogins must be >= 1, was $waitingLogins" }
        require(retainedPublishes >= 1) { "retainedPublishes must be >= 1, was $retainedPublishes" }
    }
}
