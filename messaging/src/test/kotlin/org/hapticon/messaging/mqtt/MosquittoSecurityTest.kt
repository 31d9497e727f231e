package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.junit.After
import org.junit.Before
import org.junit.Rule
import org.junit.rules.TemporaryFolder

/** [BrokerSecurityContract] against a real Mosquitto running companion/mosquitto's configuration and ACL. */
class MosquittoSecurityTest : BrokerSecurityContract() {
    @get:Rule
    val temp = TemporaryFolder()

    private lateinit var mosquitto: MosquittoProcess

    override val alice = "alice"
    override val bob = "bob"
    override val mallory = "mallory"
    override val address: BrokerAddress get() = mosquitto.address
    override val keepsSessionsOnRefusedConnects = false // eclipse-mosquitto/mosquitto#3551
    override val refusesForeignClientIds = false // use_username_as_clientid replaces the id instead

    override fun password(user: String): String = "$user-secret"

    override fun brokerLog(): String = mosquitto.log()

    @Before
    fun startMosquitto() {
        MosquittoProcess.assumeInstalled()
        mosquitto = MosquittoProcess(temp.root, listOf(alice, bob, mallory).associateWith(::password))
        mosquitto.start()
    }

    @After
    fun stopMosquitto() {
        disconnectClients()
        if (::mosquitto.isInitialized) mosquitto.stop()
    }
}
