package org.hapticon.app.sensors

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.flowOf

/** The handshake's network side: partners' hands arriving, own angles going out. */
interface HandshakeLink {
    /** The people one can shake hands with (the chat's conversations). */
    val handshakePeers: Flow<List<String>>

    /** The hand of [peer] as it arrives. */
    fun partner(peer: String): NetworkPartnerHand

    /** Sends the wearer's angles to [peer]; returns at once and drops the sample when offline. */
    fun sendOwnHand(peer: String, thumbDegrees: Double, middleDegrees: Double)
}

/** No chat account: nobody to shake hands with over the network. */
object NoHandshakeLink : HandshakeLink {
    override val handshakePeers: Flow<List<String>> = flowOf(emptyList())

    override fun partner(peer: String): NetworkPartnerHand = NetworkPartnerHand(peer)

    override fun sendOwnHand(peer: String, thumbDegrees: Double, middleDegrees: Double) = Unit
}
