package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import org.hapticon.messaging.broker.CertificateAuthority
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import java.util.concurrent.TimeUnit

/**
 * [ClientCertificateContract] against the embedded broker's TLS listener with client-authentication-mode
 * REQUIRED, plus the OPTIONAL listener where password and certificate users meet.
 */
class EmbeddedClientCertificateTest : ClientCertificateContract() {
    @get:Rule
    val fixture = BrokerFixture()

    override val alice = uniqueUser("alice")
    override val bob = uniqueUser("bob")
    override val mallory = uniqueUser("mallory")
    override val ca: CertificateAuthority get() = SharedBroker.ca
    override val tlsAddress: BrokerAddress get() = BrokerAddress(MosquittoProcess.HOST, fixture.broker.tlsPort(SharedBroker.TLS_REQUIRED), tls = true)
    override val refusesForeignClientIds = true

    override fun password(user: String): String = SharedBroker.register(user)

    private val optionalAddress: BrokerAddress get() = BrokerAddress(MosquittoProcess.HOST, fixture.broker.tlsPort(SharedBroker.TLS_OPTIONAL), tls = true)

    @Test
    fun optionalListener_takesPasswordUsersAndCertificateUsers_butNeitherAsSomeoneElse() {
        raw(TestDevices.clientId(bob), p12 = null, user = bob, password = password(bob), address = optionalAddress).disconnect().get(5, TimeUnit.SECONDS)
        raw(TestDevices.clientId(alice), p12(alice), address = optionalAddress).disconnect().get(5, TimeUnit.SECONDS)
        assertEquals(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, (refusal { raw(TestDevices.clientId(bob), p12 = null, address = optionalAddress) } as Mqtt3ConnAckException).mqttMessage.returnCode)
        // A certificate decides who the client is: another user name with it is refused, whatever the password.
        assertEquals(
            Mqtt3ConnAckReturnCode.BAD_USER_NAME_OR_PASSWORD,
            (refusal { raw(TestDevices.clientId(bob), p12(mallory), user = bob, password = password(bob), address = optionalAddress) } as Mqtt3ConnAckException).mqttMessage.returnCode,
        )
    }

    @Test
    fun plainListener_stillTakesPasswords() {
        fixture.rawClient(bob).disconnect()
    }
}
