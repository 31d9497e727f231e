package org.hapticon.messaging.broker

import java.io.ByteArrayOutputStream
import java.io.File
import java.io.IOException
import java.security.KeyStore
import java.security.SecureRandom
import java.util.Base64

/**
 * Who must show a client certificate on a [BrokerTls] listener (HiveMQ's `client-authentication-mode`).
 * Each listener has its own mode, so password users and certificate users can share a broker.
 */
public enum class ClientCertificates {
    /**
     * Every client shows a certificate signed by the study's CA (the TLS handshake fails otherwise) and is
     * the certificate's user: passwords are not accepted on this listener. HiveMQ `REQUIRED`.
     */
    REQUIRED,

    /** A client may show a certificate (and is then its user) or log in with a password. HiveMQ `OPTIONAL`. */
    OPTIONAL,

    /** TLS protects passwords on the wire; no client certificates. HiveMQ `NONE`. */
    NONE,
}

/**
 * An [EmbeddedBroker]'s TLS listener (HiveMQ CE `tls-tcp-listener`).
 *
 * @property port the port; 0 picks a free one on the first start.
 * @property host the address it binds.
 * @property certificateFile the broker's certificate (PEM; `server.crt` of [CertificateAuthority]).
 * @property privateKeyFile its private key (PEM).
 * @property clientCaFile the CA (PEM, `ca.crt`) that client certificates must be signed by.
 * @property clientCertificates who must show a certificate.
 */
public data class BrokerTls(
    val port: Int,
    val host: String,
    val certificateFile: File,
    val privateKeyFile: File,
    val clientCaFile: File,
    val clientCertificates: ClientCertificates = ClientCertificates.REQUIRED,
) {
    init {
        require(port in 0..65_535) { "port must be in 0..65535, was $port" }
    }

    /**
     * The listener's XML for HiveMQ's config.xml, with the key store (certificate and key) and trust store (the
     * client CA) written as PKCS#12 files with a fresh random password into [conf] (mode 600). HiveMQ reads key
     * stores, not PEM. Throws [IOException] naming the file that does not parse.
     */
    internal fun listenerXml(port: Int, conf: File, index: Int): String {
        if (!conf.isDirectory && !conf.mkdirs()) throw IOException("cannot create the broker directory $conf")
        val password = Base64.getUrlEncoder().withoutPadding().encodeToString(ByteArray(24).also { SecureRandom().nextBytes(it) })
        val chain = CertificateAuthority.readCertificates(certificateFile)
        val key = CertificateAuthority.readPrivateKey(privateKeyFile)
        val keyStore = KeyStore.getInstance("PKCS12").apply { load(null, null) }
        try {
            keyStore.setKeyEntry("broker", key, password.toCharArray(), chain.toTypedArray())
        } catch (e: java.security.KeyStoreException) {
            throw IOException("$privateKeyFile does not belong to $certificateFile: ${e.message}", e)
        }
        val keyStoreFile = File(conf, "tls-$index-keystore.p12")
        CertificateAuthority.writeAtomically(keyStoreFile, ByteArrayOutputStream().also { keyStore.store(it, password.toCharArray()) }.toByteArray())
        val trustXml = if (clientCertificates == ClientCertificates.NONE) "" else {
            val trustStore = KeyStore.getInstance("PKCS12").apply { load(null, null) }
            CertificateAuthority.readCertificates(clientCaFile).forEachIndexed { i, ca -> trustStore.setCertificateEntry("client-ca-$i", ca) }
            val trustStoreFile = File(conf, "tls-$index-truststore.p12")
            CertificateAuthority.writeAtomically(trustStoreFile, ByteArrayOutputStream().also { trustStore.store(it, password.toCharArray()) }.toByteArray())
            """
            |                <truststore>
            |                    <path>${xml(trustStoreFile.absolutePath)}</path>
            |                    <password>$password</password>
            |                </truststore>"""
        }
        // Element order as in HiveMQ CE's own example (hivemq/support-examples, hivemq-mqtt-client-tls-demo).
        return """
            |        <tls-tcp-listener>
            |            <port>$port</port>
            |            <bind-address>${xml(host)}</bind-address>
            |            <name>hapticon-tls-$index</name>
            |            <tls>
            |                <keystore>
            |                    <path>${xml(keyStoreFile.absolutePath)}</path>
            |                    <password>$password</password>
            |                    <private-key-password>$password</private-key-password>
            |                </keystore>
            |                <client-authentication-mode>${clientCertificates.name}</client-authentication-mode>$trustXml
            |                <protocols>
            |                    <protocol>TLSv1.3</protocol>
            |                    <protocol>TLSv1.2</protocol>
            |                </protocols>
            |            </tls>
            |        </tls-tcp-listener>""".trimMargin()
    }

    private fun xml(text: String) = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
}
