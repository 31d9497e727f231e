package org.hapticon.app.data

import org.hapticon.app.data.database.StoredMessage
import org.hapticon.core.io.IconJson
import org.json.JSONArray
import org.json.JSONObject

/**
 * The user's chats as one JSON document (Settings › Export): every stored message with its state and
 * icon by value (the icon's own JSON), so a researcher can read what was sent and felt without the app.
 */
object ChatExport {
    /** Format version of the document; bumped when a field changes meaning. */
    const val VERSION: Int = 1

    fun toJson(messages: List<StoredMessage>): String {
        val rows = JSONArray()
        for (m in messages) {
            rows.put(
                JSONObject()
                    .put("id", m.id)
                    .put("conversation", m.conversation)
                    .put("sender", m.sender)
                    .put("sentAt", m.sentAtMillis)
                    .put("outgoing", m.outgoing)
                    .put("state", m.state.name.lowercase())
                    .put("text", m.text)
                    .put("sticker", m.sticker ?: JSONObject.NULL)
                    .put("icon", m.icon?.let { JSONObject(IconJson.encode(it)) } ?: JSONObject.NULL)
                    .put("readAt", m.readAtMillis ?: JSONObject.NULL),
            )
        }
        return JSONObject().put("schema", "hapticon.chats").put("version", VERSION).put("messages", rows).toString(2)
    }
}
