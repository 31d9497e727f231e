package org.hapticon.devicecheck.dumpsys

/**
 * The posted notifications in `dumpsys notification --noredact`, read from its text: one [PostedNotification] per
 * `NotificationRecord.dump` block (AOSP `services/core/java/com/android/server/notification/NotificationRecord.java`):
 * a header `NotificationRecord(0x…: pkg=… user=… id=… tag=… importance=… key=…: Notification(channel=… …))`, then
 * indented `name=value` lines, among them the extras (`android.template=String (android.app.Notification$MessagingStyle)`),
 * `mCreationTimeMs=` (the first post, epoch milliseconds), `mUpdateTimeMs=` (the latest post: an update of the same
 * notification is a new record that keeps the first one's creation time) and `mIntercept=` (Do Not Disturb held it back).
 */
public object NotificationDump {
    private val HEADER = Regex(
        """NotificationRecord\(0x[0-9a-f]+: pkg=(\S+) user=\S+ id=(-?\d+) tag=(\S+) importance=(-?\d+) key=(\S+): Notification\(channel=(\S+)""",
    )

    /** Every notification record in [text], in the dump's order. */
    public fun parse(text: String): List<PostedNotification> {
        val headers = HEADER.findAll(text).toList()
        return headers.mapIndexed { i, header ->
            val block = text.substring(header.range.first, headers.getOrNull(i + 1)?.range?.first ?: text.length)
            val (pkg, id, tag, importance, key, channel) = header.destructured
            PostedNotification(
                packageName = pkg,
                id = id.toInt(),
                tag = tag.takeIf { it != "null" },
                importance = importance.toInt(),
                key = key,
                channel = channel,
                template = Regex("""android\.template=String \(([^)]+)\)""").find(block)?.groupValues?.get(1),
                creationTimeMillis = Regex("""mCreationTimeMs=(\d+)""").find(block)?.groupValues?.get(1)?.toLong(),
                updateTimeMillis = Regex("""mUpdateTimeMs=(\d+)""").find(block)?.groupValues?.get(1)?.toLong(),
                intercepted = Regex("""mIntercept=(true|false)""").find(block)?.groupValues?.get(1)?.toBooleanStrict(),
                dump = block,
            )
        }
    }
}

/** One posted notification; [dump] is its whole block of the dump, for reports and looser checks. */
public data class PostedNotification(
    public val packageName: String,
    public val id: Int,
    public val tag: String?,
    public val importance: Int,
    public val key: String,
    public val channel: String,
    /** The style class (`android.app.Notification$MessagingStyle`), or null when the extras do not name one. */
    public val template: String?,
    public val creationTimeMillis: Long?,
    /** When it was last posted (the message that updated it), epoch milliseconds. */
    public val updateTimeMillis: Long?,
    /** Whether Do Not Disturb intercepts it (no sound, vibration or peek); null when not dumped. */
    public val intercepted: Boolean?,
    public val dump: String,
) {
    /** Whether it is a conversation notification in `MessagingStyle` (platform or AndroidX, which builds the platform's). */
    public val isMessagingStyle: Boolean get() = template?.endsWith("\$MessagingStyle") == true

    override fun toString(): String =
        "$packageName id=$id tag=$tag channel=$channel template=$template created=$creationTimeMillis updated=$updateTimeMillis intercepted=$intercepted"
}
