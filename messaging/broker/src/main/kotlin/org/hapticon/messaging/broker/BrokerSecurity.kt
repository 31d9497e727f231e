package org.hapticon.messaging.broker

import com.hivemq.extension.sdk.api.ExtensionMain
import com.hivemq.extension.sdk.api.auth.PublishAuthorizer
import com.hivemq.extension.sdk.api.auth.SimpleAuthenticator
import com.hivemq.extension.sdk.api.auth.SubscriptionAuthorizer
import com.hivemq.extension.sdk.api.auth.parameter.PublishAuthorizerInput
import com.hivemq.extension.sdk.api.auth.parameter.PublishAuthorizerOutput
import com.hivemq.extension.sdk.api.auth.parameter.SimpleAuthInput
import com.hivemq.extension.sdk.api.auth.parameter.SimpleAuthOutput
import com.hivemq.extension.sdk.api.auth.parameter.SubscriptionAuthorizerInput
import com.hivemq.extension.sdk.api.auth.parameter.SubscriptionAuthorizerOutput
import com.hivemq.extension.sdk.api.packets.connect.ConnackReasonCode
import com.hivemq.extension.sdk.api.parameter.ExtensionStartInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStartOutput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopOutput
import com.hivemq.extension.sdk.api.services.Services
import java.io.File
import java.io.IOException

/** Who may connect to an [EmbeddedBroker] and what they may do. */
public sealed interface BrokerSecurity {
    /**
     * Every client authenticates with a user name and password from [passwordFile] (Mosquitto's format, see
     * [PasswordFile]) or, on a TLS listener that asks for one ([BrokerTls]), with a client certificate of the
     * study's CA whose common name is the user; its client id must be its user name; it publishes and subscribes only as [aclFile]
     * (Mosquitto's format, see [AclFile]) allows. The same rules as companion/mosquitto/mosquitto.conf.
     */
    public data class Authenticated(val passwordFile: File, val aclFile: File) : BrokerSecurity

    /**
     * Anyone connects with any client id and reads and writes every topic: the broker's state before
     * authentication existed, for a throw-away local test only. [EmbeddedBroker.start] logs a warning.
     */
    public data object AllowAnonymous : BrokerSecurity
}

/**
 * The HiveMQ extension that enforces a [BrokerSecurity], with the HiveMQ extension SDK: a
 * [SimpleAuthenticator] (registered through `Services.securityRegistry().setAuthenticatorProvider`) decides
 * each CONNECT, and one authorizer that is both a [PublishAuthorizer] and a [SubscriptionAuthorizer]
 * decides each PUBLISH and each SUBSCRIBE topic filter (`setAuthorizerProvider`).
 *
 * The client id is bound to the user: a CONNECT whose client id is not its user name is refused with
 * "identifier rejected", where Mosquitto (`use_username_as_clientid true`) silently replaces the id with
 * the user name. Both mean that nobody can take over another user's session. Because of that binding the
 * authorizers take the user name from the client id.
 */
internal class SecurityExtension(private val security: BrokerSecurity) : ExtensionMain {
    override fun extensionStart(input: ExtensionStartInput, output: ExtensionStartOutput) {
        when (security) {
            is BrokerSecurity.Authenticated -> {
                val acl = try {
                    AclFile.read(security.aclFile)
                } catch (e: IOException) {
                    output.preventExtensionStartup("ACL file: ${e.message}")
                    return
                }
                val passwords = PasswordFile(security.passwordFile)
                Services.securityRegistry().setAuthenticatorProvider { PasswordAuthenticator(passwords) }
                Services.securityRegistry().setAuthorizerProvider { AclAuthorizer(acl) }
            }
            BrokerSecurity.AllowAnonymous -> {
                Services.securityRegistry().setAuthenticatorProvider { SimpleAuthenticator { _, out -> out.authenticateSuccessfully() } }
            }
        }
    }

    override fun extensionStop(input: ExtensionStopInput, output: ExtensionStopOutput) = Unit
}

/**
 * Accepts a CONNECT from a client that either showed a client certificate on a TLS listener or gave a user name
 * and its password from [passwords]; either way its client id must be its user name.
 *
 * A certificate has been checked by the TLS handshake already (signed by the listener's trusted CA, within its
 * validity: HiveMQ's trust store, `client-authentication-mode`); its user is its common name
 * ([CertificateAuthority.userOf]), as Mosquitto's `use_identity_as_username`. The extension SDK hands the
 * certificate over as `ConnectionInformation.getClientTlsInformation().getClientCertificate()`. A certificate
 * user needs no password-file entry; a user name sent with a certificate must be the certificate's.
 */
internal class PasswordAuthenticator(private val passwords: PasswordFile) : SimpleAuthenticator {
    override fun onConnect(input: SimpleAuthInput, output: SimpleAuthOutput) {
        val connect = input.connectPacket
        val certificate = input.connectionInformation.clientTlsInformation.flatMap { it.clientCertificate }.orElse(null)
        if (certificate != null) {
            val user = CertificateAuthority.userOf(certificate)
            val claimed = connect.userName.orElse(null)
            when {
                user == null -> output.failAuthentication(ConnackReasonCode.NOT_AUTHORIZED, "the client certificate names no user (one CN that is a user name)")
                claimed != null && claimed != user -> output.failAuthentication(ConnackReasonCode.BAD_USER_NAME_OR_PASSWORD, "the user name is not the certificate's")
                connect.clientId != user -> output.failAuthentication(ConnackReasonCode.CLIENT_IDENTIFIER_NOT_VALID, "the client id must be the certificate's user name")
                else -> output.authenticateSuccessfully()
            }
            return
        }
        val user = connect.userName.orElse(null)
        val password = connect.password.orElse(null)?.let { buffer -> ByteArray(buffer.remaining()).also { buffer.duplicate().get(it) } }
        when {
            user == null || password == null -> output.failAuthentication(ConnackReasonCode.NOT_AUTHORIZED, "a user name and password are required")
            !verify(user, password) -> output.failAuthentication(ConnackReasonCode.BAD_USER_NAME_OR_PASSWORD, "bad user name or password")
            // Checked after the password, so that the reply does not tell a stranger which user names exist.
            connect.clientId != user -> output.failAuthentication(ConnackReasonCode.CLIENT_IDENTIFIER_NOT_VALID, "the client id must be the user name")
            else -> output.authenticateSuccessfully()
        }
    }

    private fun verify(user: String, password: ByteArray): Boolean = try {
        passwords.verify(user, password)
    } catch (e: IOException) {
        false // an unreadable password file lets nobody in
    } finally {
        password.fill(0)
    }
}

/** Allows a PUBLISH or SUBSCRIBE only when [acl] does, for the user whose name is the client id. */
internal class AclAuthorizer(private val acl: AclFile) : PublishAuthorizer, SubscriptionAuthorizer {
    override fun authorizePublish(input: PublishAuthorizerInput, output: PublishAuthorizerOutput) {
        val client = input.clientInformation.clientId
        if (acl.mayPublish(client, client, input.publishPacket.topic)) output.authorizeSuccessfully() else output.failAuthorization()
    }

    override fun authorizeSubscribe(input: SubscriptionAuthorizerInput, output: SubscriptionAuthorizerOutput) {
        val client = input.clientInformation.clientId
        if (acl.maySubscribe(client, client, input.subscription.topicFilter)) output.authorizeSuccessfully() else output.failAuthorization()
    }
}
