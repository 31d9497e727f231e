package org.hapticon.messaging.broker

/**
 * Each sender's share of each recipient's queues ([BrokerLimits.inboxShare]): counts, per device session of a
 * recipient and per sender, the QoS 1 inbox messages the broker accepted and has not yet sent on to that session.
 * The broker's own queue (HiveMQ's `max-queue-size`) is per session and first come, first served: a sender who fills
 * it makes the broker drop everybody else's messages. Here a sender's message is held back when each of the
 * recipient's sessions already holds [share] of its messages, and nobody else is affected.
 *
 * The sessions of a user are the client ids `USER:DEVICE` ([ClientIds]) the broker has seen authenticated since it
 * started or found in its store at start. A recipient without a session gets nothing held back: the broker keeps no
 * message for a user nobody subscribed for. The counts live in memory: after a restart each sender starts again
 * from zero (at most one more share each per restart). Thread-safe.
 */
internal class InboxQuota(private val share: Int) {
    private val sessionsOf = HashMap<String, MutableSet<String>>()
    // session client id -> sender -> messages accepted for it and not yet sent to it
    private val waiting = HashMap<String, HashMap<String, Int>>()

    /** [clientId] is a session of its user (from now on, or again); [fresh]: it starts empty (clean session). */
    @Synchronized
    fun session(clientId: String, fresh: Boolean) {
        val user = ClientIds.userOf(clientId) ?: return
        sessionsOf.getOrPut(user) { HashSet() } += clientId
        if (fresh) waiting.remove(clientId)
    }

    /** True when [clientId] is a session seen before (see [session]). */
    @Synchronized
    fun isKnown(clientId: String): Boolean = ClientIds.userOf(clientId)?.let { sessionsOf[it]?.contains(clientId) } == true

    /** Whether [sender] may put one more message into [recipient]'s inbox now; when so, it is counted in every session of [recipient]. */
    @Synchronized
    fun admit(sender: String, recipient: String): Boolean {
        val sessions = sessionsOf[recipient] ?: return true
        if (sessions.all { (waiting[it]?.get(sender) ?: 0) >= share }) return false
        for (session in sessions) {
            val counts = waiting.getOrPut(session) { HashMap() }
            counts[sender] = (counts[sender] ?: 0) + 1
        }
        return true
    }

    /** A message of [sender] was sent on to the session [clientId]. */
    @Synchronized
    fun sent(clientId: String, sender: String) {
        val counts = waiting[clientId] ?: return
        val count = counts[sender] ?: return
        if (count <= 1) counts.remove(sender) else counts[sender] = count - 1
    }

    /** How many of [sender]'s messages wait for [clientId] (for tests and logs). */
    @Synchronized
    fun waiting(clientId: String, sender: String): Int = waiting[clientId]?.get(sender) ?: 0
}
