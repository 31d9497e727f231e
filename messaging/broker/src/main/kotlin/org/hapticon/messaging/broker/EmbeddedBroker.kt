package org.hapticon.messaging.broker

import ch.qos.logback.classic.Level
import ch.qos.logback.classic.LoggerContext
import ch.qos.logback.classic.encoder.PatternLayoutEncoder
import ch.qos.logback.classic.spi.ILoggingEvent
import ch.qos.logback.core.ConsoleAppender
import com.hivemq.embedded.EmbeddedExtension
import com.hivemq.embedded.EmbeddedHiveMQ
import org.slf4j.LoggerFactory
import java.io.File
import java.io.IOException
import java.net.InetAddress
import java.net.ServerSocket
import java.util.concurrent.ExecutionException

/**
 * An MQTT broker (HiveMQ Community Edition) running inside this JVM, listening on [host] (loopback unless
 * told otherwise): for the `hapticon broker` command, the demo and tests. For a study with many phones see
 * `companion/mosquitto/` and docs/deployment.md.
 *
 * [security] decides who connects and what they may do: with [BrokerSecurity.Authenticated] the same
 * password file, client-id binding and ACL as the Mosquitto deployment (see [SecurityExtension]);
 * [BrokerSecurity.AllowAnonymous] lets anyone do anything and is logged as a warning on every start.
 *
 * Sessions, subscriptions, retained messages and the QoS 1 messages queued for offline persistent
 * sessions (clients that connect with cleanSession=false) are kept in [dataDirectory], so they survive
 * [stop] and [start], and [restart].
 *
 * [requestedPort] 0 picks a free port on the first [start]; later starts reuse the port it got, so clients
 * can reconnect to the same address after a restart. Not thread-safe: start and stop from one thread.
 *
 * Run at most one at a time in a process: HiveMQ CE keeps its publish counter in a static field that every
 * start resets from its own store (`PublishPayloadRocksDBLocalPersistence.init` sets `PUBLISH.PUBLISH_COUNTER`),
 * so a second broker started beside a running one makes the first reuse payload ids and deliver stored
 * payloads in place of new ones (docs/security.md, "Known weaknesses"). Stopping and starting one broker
 * ([restart]) is safe.
 *
 * The first start sets this process's logback logging to warnings on stderr: HiveMQ would otherwise log
 * at INFO to stdout, which belongs to the command that embeds the broker.
 *
 * @property dataDirectory where the persistent store lives; created when missing.
 * @property security authentication and authorization.
 * @property host the address to listen on: [HOST] (loopback) by default, a LAN address so that phones can
 *   reach a laptop, or `0.0.0.0` for every interface.
 * @property tls TLS listeners next to the plain one (see [BrokerTls]), each with its own client-certificate
 *   mode; none by default.
 * @property limits what one participant may ask of the broker (its share of others' queues, failed logins,
 *   retained publishes); applied with [BrokerSecurity.Authenticated] only.
 */
public class EmbeddedBroker(
    public val dataDirectory: File,
    private val requestedPort: Int = 0,
    public val security: BrokerSecurity,
    public val host: String = HOST,
    public val tls: List<BrokerTls> = emptyList(),
    public val limits: BrokerLimits = BrokerLimits(),
) : AutoCloseable {
    private var broker: EmbeddedHiveMQ? = null
    private var boundPort: Int = requestedPort
    private val boundTlsPorts: IntArray = tls.map { it.port }.toIntArray()

    init {
        require(requestedPort in 0..65_535) { "port must be in 0..65535, was $requestedPort" }
    }

    /**
     * The port of the TLS listener `tls[index]`. Throws [IllegalStateException] when that listener was created
     * with port 0 and the broker was never started.
     */
    public fun tlsPort(index: Int = 0): Int {
        check(boundTlsPorts[index] != 0) { "the broker has not been started yet" }
        return boundTlsPorts[index]
    }

    /** True between [start] and [stop]. */
    public val isRunning: Boolean get() = broker != null

    /**
     * The port the broker listens on. Throws [IllegalStateException] when it was never started and was
     * created with port 0 (no port is known yet).
     */
    public val port: Int
        get() {
            check(boundPort != 0) { "the broker has not been started yet" }
            return boundPort
        }

    /**
     * Starts listening on [host]:[port] and blocks until the broker accepts connections (about a second;
     * five in a JVM that has not loaded the broker's classes yet).
     * Does nothing when already running. Throws [IOException] when the port is taken or the data directory
     * is unusable.
     */
    public fun start() {
        if (broker != null) return
        val address = InetAddress.getByName(host)
        if (boundPort == 0) boundPort = ServerSocket(0, 1, address).use { it.localPort }
        try {
            ServerSocket(boundPort, 1, address).close()
        } catch (e: IOException) {
            throw IOException("cannot listen on $host:$boundPort: ${e.message}", e)
        }
        val tlsXml = tls.mapIndexed { i, listener ->
            val tlsAddress = InetAddress.getByName(listener.host)
            if (boundTlsPorts[i] == 0) boundTlsPorts[i] = ServerSocket(0, 1, tlsAddress).use { it.localPort }
            try {
                ServerSocket(boundTlsPorts[i], 1, tlsAddress).close()
            } catch (e: IOException) {
                throw IOException("cannot listen on ${listener.host}:${boundTlsPorts[i]}: ${e.message}", e)
            }
            listener.listenerXml(boundTlsPorts[i], File(dataDirectory, "conf"), i)
        }.joinToString("\n")
        if (security is BrokerSecurity.Authenticated) {
            // Fail here with the reason rather than with an extension that refuses to start.
            AclFile.read(security.aclFile)
        }
        val conf = File(dataDirectory, "conf")
        val data = File(dataDirectory, "data")
        val extensions = File(dataDirectory, "extensions")
        for (dir in listOf(conf, data, extensions)) {
            if (!dir.isDirectory && !dir.mkdirs()) throw IOException("cannot create the broker directory $dir")
        }
        quietLogging()
        if (security == BrokerSecurity.AllowAnonymous) {
            LoggerFactory.getLogger(EmbeddedBroker::class.java).warn(
                "ANONYMOUS ACCESS: the broker on $host:$boundPort lets any client connect without a password, " +
                    "read every inbox and publish as anyone (--allow-anonymous)",
            )
        }
        // The config names the TLS key stores' password: readable by this user only.
        CertificateAuthority.writeAtomically(File(conf, "config.xml"), configXml(host, boundPort, tlsXml).toByteArray())
        File(conf, "logback.xml").writeText(LOGBACK_XML)
        val started = EmbeddedHiveMQ.builder()
            .withConfigurationFolder(conf.toPath())
            .withDataFolder(data.toPath())
            .withExtensionsFolder(extensions.toPath())
            .withEmbeddedExtension(
                EmbeddedExtension.builder()
                    .withId("hapticon-security").withName("Hapticon users and ACL").withVersion("1")
                    .withPriority(1000).withStartPriority(1000)
                    .withExtensionMain(SecurityExtension(security, limits))
                    .build(),
            )
            .build()
        try {
            started.start().get()
        } catch (e: ExecutionException) {
            runCatching { started.close() }
            throw IOException("the broker did not start on $host:$boundPort: ${e.cause?.message}", e.cause)
        }
        broker = started
    }

    /**
     * Stops the broker, blocking until its store is closed (about 4.5 s: HiveMQ shuts its two Netty event
     * loop groups down gracefully, each with a fixed 2 s quiet period); queued messages stay on disk.
     * Idempotent.
     */
    public fun stop() {
        val running = broker ?: return
        broker = null
        running.stop().get()
        running.close()
    }

    /**
     * The sessions the broker holds now, client id to whether its client is connected, sorted by id:
     * persistent sessions (cleanSession=false) stay after their client left, clean ones end with the
     * connection. For checking that a client leaves nothing behind (HiveMQ's extension
     * `ClientService.iterateAllClients`, which lists connected clients and stored sessions alike).
     * Throws [IllegalStateException] when the broker is not running.
     */
    public fun sessions(): Map<String, Boolean> {
        check(broker != null) { "the broker is not running" }
        val found = java.util.concurrent.ConcurrentHashMap<String, Boolean>()
        com.hivemq.extension.sdk.api.services.Services.clientService()
            .iterateAllClients { _, session -> found[session.clientIdentifier] = session.isConnected }
            .get(10, java.util.concurrent.TimeUnit.SECONDS)
        return found.toSortedMap()
    }

    /** [stop], then [start] on the same port; blocks for about 6 s. Throws as [start] does. */
    public fun restart() {
        stop()
        start()
    }

    /** Same as [stop]. */
    override fun close(): Unit = stop()

    public companion object {
        private var loggingQuieted = false

        // HiveMQ's jar carries a logback.xml that logs INFO to stdout, which belongs to the command embedding
        // the broker; its own logging set-up (from LOGBACK_XML, written into the configuration folder) comes
        // only after its first lines. So logback is set to warnings on stderr before anything starts.
        @Synchronized
        private fun quietLogging() {
            if (loggingQuieted) return
            loggingQuieted = true
            val context = LoggerFactory.getILoggerFactory() as? LoggerContext ?: return // another backend: not ours to touch
            context.reset()
            val encoder = PatternLayoutEncoder().apply {
                this.context = context
                pattern = LOG_PATTERN
                start()
            }
            val appender = ConsoleAppender<ILoggingEvent>().apply {
                this.context = context
                target = "System.err"
                this.encoder = encoder
                start()
            }
            context.getLogger(org.slf4j.Logger.ROOT_LOGGER_NAME).apply {
                level = Level.WARN
                addAppender(appender)
            }
        }

        private const val LOG_PATTERN = "broker %level %logger{0}: %msg%n%ex"

        /** The address the embedded broker binds unless told otherwise: loopback. */
        public const val HOST: String = "127.0.0.1"

        /** QoS 1 messages kept per offline persistent session. */
        public const val MAX_QUEUED_MESSAGES: Int = 10_000

        /** Largest MQTT packet accepted, in bytes: a 64 KiB payload plus topic and headers, with room to spare. */
        public const val MAX_PACKET_BYTES: Int = 131_072

        private fun configXml(host: String, port: Int, tlsListener: String) = """
            |<?xml version="1.0"?>
            |<hivemq>
            |    <listeners>
            |        <tcp-listener>
            |            <port>$port</port>
            |            <bind-address>$host</bind-address>
            |        </tcp-listener>
            |$tlsListener
            |    </listeners>
            |    <mqtt>
            |        <queued-messages>
            |            <max-queue-size>$MAX_QUEUED_MESSAGES</max-queue-size>
            |        </queued-messages>
            |        <packets>
            |            <max-packet-size>$MAX_PACKET_BYTES</max-packet-size>
            |        </packets>
            |    </mqtt>
            |    <anonymous-usage-statistics>
            |        <enabled>false</enabled>
            |    </anonymous-usage-statistics>
            |</hivemq>
            |""".trimMargin()

        private val LOGBACK_XML = """
            |<configuration scan="false">
            |    <appender name="STDERR" class="ch.qos.logback.core.ConsoleAppender">
            |        <target>System.err</target>
            |        <encoder><pattern>$LOG_PATTERN</pattern></encoder>
            |    </appender>
            |    <logger name="com.hivemq" level="WARN"/>
            |    <root level="WARN"><appender-ref ref="STDERR"/></root>
            |</configuration>
            |""".trimMargin()
    }
}
