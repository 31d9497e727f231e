package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.junit.Rule

/** [BrokerSecurityContract] against the embedded broker with the shipped ACL. */
class EmbeddedBrokerSecurityTest : BrokerSecurityContract() {
    @get:Rule
    val fixture = BrokerFixture()

    override val alice = uniqueUser("alice")
    override val bob = uniqueUser("bob")
    override val mallory = uniqueUser("mallory")
    override val address: BrokerAddress get() = fixture.address
    override val refusesForeignClientIds = true
    override val refusesRetainedInboxPublishes = true
    override val sharesQueues = true
    override val brokerName = "embedded broker"

    override fun password(user: String): String = SharedBroker.register(user)
}
