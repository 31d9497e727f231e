package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.broker.CertificateAuthority
import org.junit.After
import org.junit.Before
import org.junit.Rule
import org.junit.rules.TemporaryFolder
import java.io.File

/**
 * [ClientCertificateContract] against a real Mosquitto running companion/mosquitto's configuration with its
 * client-certificate listener (`require_certificate`, `use_identity_as_username`)
 * enabled, and a CA made by [CertificateAuthority] as `hapticon broker ca init` makes it.
 */
class MosquittoClientCertificateTest : ClientCertificateContract() {
    @get:Rule
    val temp = TemporaryFolder()

    private lateinit var mosquitto: MosquittoProcess
    private lateinit var authority: CertificateAuthority

    override val alice = "alice"
    override val bob = "bob"
    override val mallory = "mallory"
    override val ca: CertificateAuthority get() = authority
    override val tlsAddress: BrokerAddress get() = mosquitto.tlsAddress
    override val refusesForeignClientIds = false // Mosquitto does not bind client ids (see mosquitto.conf)

    override fun password(user: String): String = "$user-secret"

    @Before
    fun startMosquitto() {
        MosquittoProcess.assumeInstalled()
        authority = CertificateAuthority.init(File(temp.root, "ca"), "Hapticon test CA", emptyList())
        mosquitto = MosquittoProcess(temp.root, listOf(alice, bob, mallory).associateWith(::password), authority)
        mosquitto.start()
    }

    @After
    fun stopMosquitto() {
        disconnectCertificateClients()
        if (::mosquitto.isInitialized) mosquitto.stop()
    }
}
