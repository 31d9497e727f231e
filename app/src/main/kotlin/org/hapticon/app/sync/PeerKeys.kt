package org.hapticon.app.sync

/** What [ChatComponent.peerKeys] knows of a peer's end-to-end keys. */
enum class PeerKeys {
    /** Encryption is off (the user's choice): no keys are needed. */
    NOT_NEEDED,

    /** The peer published keys: messages to it are sealed. */
    PUBLISHED,

    /** Connected, and the broker holds no keys of the peer: nothing can be sent until it connects with encryption on. */
    NONE_PUBLISHED,

    /** Not connected since the app started: the retained keys have not been read yet. */
    NOT_KNOWN_YET,
}
