package org.hapticon.messaging.mqtt

import org.junit.Assert.assertEquals
import org.junit.Test
import java.net.ConnectException
import java.net.UnknownHostException
import java.security.cert.CertPathBuilderException
import java.security.cert.CertificateException
import javax.net.ssl.SSLHandshakeException

/** The one line a person reads when a connection fails (`hapticon chat`, the app's connection state). */
class ConnectionFailureTest {
    private fun wrapped(cause: Throwable) = RuntimeException("io.netty wrapper", cause)

    @Test
    fun describeFailure_untrustedCertificate_saysTlsTrust() {
        val handshake = SSLHandshakeException("PKIX path building failed").apply {
            initCause(CertificateException("unable to find valid certification path", CertPathBuilderException("no path")))
        }
        assertEquals(
            "TLS: the broker's certificate is not trusted (PKIX path building failed)",
            MqttMessenger.describeFailure(wrapped(handshake)),
        )
    }

    @Test
    fun describeFailure_otherTlsFailure_saysHandshake() {
        assertEquals("TLS handshake failed: Remote host terminated the handshake", MqttMessenger.describeFailure(SSLHandshakeException("Remote host terminated the handshake")))
    }

    @Test
    fun describeFailure_refusedAndUnknownHost_sayWhich() {
        assertEquals(
            "connection refused: nothing accepts connections there (Connection refused: /127.0.0.1:1)",
            MqttMessenger.describeFailure(wrapped(ConnectException("Connection refused: /127.0.0.1:1"))),
        )
        assertEquals("unknown host broker.invalid", MqttMessenger.describeFailure(UnknownHostException("broker.invalid")))
        assertEquals("IllegalStateException", MqttMessenger.describeFailure(IllegalStateException()))
    }
}
