package org.hapticon.app.sync

import org.hapticon.messaging.BrokerAddress

/**
 * Asks a broker whether [user] can connect; null when it can, else a one-line reason. The chat screens' view
 * models take it; [ChatComponent] makes it from the sync's settings.
 */
typealias BrokerProbe = suspend (user: String, broker: BrokerAddress, password: String?) -> String?
