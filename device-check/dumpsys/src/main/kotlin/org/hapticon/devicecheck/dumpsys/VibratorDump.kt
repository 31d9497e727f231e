package org.hapticon.devicecheck.dumpsys

import java.time.LocalDateTime
import java.time.format.DateTimeFormatter
import java.time.format.DateTimeParseException

/**
 * What `dumpsys vibrator_manager` says about the vibrations Android played or refused, read from its text.
 *
 * Two formats, both written by AOSP's `services/core/java/com/android/server/vibrator/`:
 * - Android 14 and later: "Recent vibrations:", grouped by usage, one line per vibration written by
 *   `Vibration.DebugInfo.dumpCompact` (`MM-dd HH:mm:ss.SSS |   effect |   finished | duration: …ms | start: … | end: … |
 *   scale: … | flags: … | usage: COMMUNICATION_REQUEST | org.x (uid=10234, deviceId=0) | reason: … | played: … | original: …`),
 *   the effects as `VibrationEffect.toDebugString` (`[Step=10ms(amplitude=0.50),…]`);
 * - Android 12 and 13: "Previous … vibrations:", one `Vibration.DebugInfo.toString` per line (`startTime: …, endTime: …,
 *   status: finished, effect: Composed{segments=[Step{amplitude=0.5, frequencyHz=0.0, duration=10}, …], repeat=-1},
 *   originalEffect: …, scale: 1.00, attrs: VibrationAttributes: Usage=… Flags=0, uid: …, opPkg: …, reason: …`).
 *
 * A vibration Android refused is listed too, with the status that says why (`ignored_background`,
 * `ignored_for_settings`, …; `Vibration.Status`, lower-cased by the dump).
 */
public class VibratorDump private constructor(
    /** Every vibration the dump lists, in the order it lists them. */
    public val vibrations: List<VibrationRecord>,
    /**
     * The process state VibrationSettings last saw for each uid (`processStateCache`), the number it compares with
     * `PROCESS_STATE_IMPORTANT_FOREGROUND` (6) to decide whether a uid is in the foreground; empty when not dumped.
     */
    public val processStates: Map<Int, Int>,
) {
    /** The vibrations [packageName] asked for (`opPkg`), not those the system played on its behalf. */
    public fun of(packageName: String): List<VibrationRecord> = vibrations.filter { it.packageName == packageName }

    /**
     * The vibrations the system played for [packageName]'s notifications: NotificationManagerService vibrates as
     * "android" with the reason `Notification (<package> <uid>)` (NotificationAttentionHelper.vibrate).
     */
    public fun notificationAlertsOf(packageName: String): List<VibrationRecord> =
        vibrations.filter { it.reason.startsWith("Notification ($packageName ") }

    public companion object {
        /**
         * Reads [text]. The dump writes times without a year (`MM-dd HH:mm:ss.SSS`, the phone's time zone): [year] is
         * the one to read them in.
         */
        public fun parse(text: String, year: Int): VibratorDump {
            val records = text.lineSequence().mapNotNull { line ->
                compactLine(line, year) ?: debugInfoLine(line, year)
            }.toList()
            val states = PROCESS_STATES.find(text)?.groupValues?.get(1).orEmpty()
                .split(',').mapNotNull { entry ->
                    val (uid, state) = entry.split('=').map { it.trim() }.takeIf { it.size == 2 } ?: return@mapNotNull null
                    val u = uid.toIntOrNull() ?: return@mapNotNull null
                    val s = state.toIntOrNull() ?: return@mapNotNull null
                    u to s
                }.toMap()
            return VibratorDump(records, states)
        }

        private val PROCESS_STATES = Regex("""(?:processStateCache = |mProcStatesCache=)\{([^}]*)\}""")
        private val CALLER = Regex("""^(\S+) \(uid=(-?\d+)""")
        private val TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS")

        /** One line of Android 14+'s "Recent vibrations" (`Vibration.DebugInfo.dumpCompact`), or null. */
        private fun compactLine(line: String, year: Int): VibrationRecord? {
            val parts = line.trim().split(" | ")
            if (parts.size < 8 || !parts[0].matches(Regex("""\d\d-\d\d \d\d:\d\d:\d\d\.\d{3}"""))) return null
            val field = { prefix: String -> parts.firstOrNull { it.startsWith(prefix) }?.removePrefix(prefix)?.trim() }
            val usage = field("usage:") ?: return null
            val callerIndex = parts.indexOfFirst { CALLER.containsMatchIn(it) }
            val caller = parts.getOrNull(callerIndex)?.let { CALLER.find(it) } ?: return null
            val played = parts.indexOfFirst { it.startsWith("played:") }
            val original = parts.indexOfFirst { it.startsWith("original:") }
            val reasonStart = parts.indexOfFirst { it.startsWith("reason:") }
            val reason = if (reasonStart >= 0 && played > reasonStart) {
                parts.subList(reasonStart, played).joinToString(" | ").removePrefix("reason:").trim()
            } else ""
            val playedText = if (played >= 0) parts.subList(played, if (original > played) original else parts.size).joinToString(" | ").removePrefix("played:").trim() else "null"
            val originalText = if (original >= 0) parts.subList(original, parts.size).joinToString(" | ").removePrefix("original:").trim() else "null"
            return VibrationRecord(
                createdAt = time(year, parts[0]),
                external = parts[1].trim() == "external",
                status = parts[2].trim(),
                durationMillis = field("duration:")?.removeSuffix("ms")?.trim()?.toLongOrNull(),
                usage = usage,
                packageName = caller.groupValues[1],
                uid = caller.groupValues[2].toInt(),
                reason = reason,
                playedEffect = playedText,
                originalEffect = originalText,
            )
        }

        /** One `Vibration.DebugInfo.toString` line of Android 12 and 13's "Previous … vibrations", or null. */
        private fun debugInfoLine(line: String, year: Int): VibrationRecord? {
            val text = line.trim()
            if (!text.startsWith("startTime: ") || ", opPkg: " !in text) return null
            val value = { name: String, next: String ->
                val start = text.indexOf("$name: ").takeIf { it >= 0 }?.plus(name.length + 2)
                start?.let {
                    val end = text.indexOf(", $next: ", it).takeIf { e -> e >= 0 } ?: text.length
                    text.substring(it, end).trim()
                }
            }
            val attrs = value("attrs", "uid").orEmpty()
            return VibrationRecord(
                createdAt = value("startTime", "endTime")?.let { time(year, it) },
                external = false,
                status = value("status", "effect") ?: return null,
                durationMillis = value("durationMs", "status")?.toLongOrNull(),
                usage = Regex("""Usage=(\w+)""").find(attrs)?.groupValues?.get(1) ?: return null,
                packageName = value("opPkg", "reason") ?: return null,
                uid = Regex(""", uid: (-?\d+)""").find(text)?.groupValues?.get(1)?.toInt() ?: return null,
                reason = value("reason", "\u0000").orEmpty(),
                playedEffect = value("effect", "originalEffect") ?: "null",
                originalEffect = value("originalEffect", "scale") ?: "null",
            )
        }

        private fun time(year: Int, monthDayTime: String): LocalDateTime? = try {
            LocalDateTime.parse("$year-$monthDayTime", TIME)
        } catch (e: DateTimeParseException) {
            null
        }
    }
}

/**
 * One vibration in the dump. [status] is `Vibration.Status` lower-cased (`finished`, `running`, `cancelled_superseded`,
 * `ignored_background`, …); [usage] is `VibrationAttributes.usageToString` (`COMMUNICATION_REQUEST`, `TOUCH`, `UNKNOWN`…).
 * [playedEffect] is what the vibrator was given after scaling and adapting, [originalEffect] what the app asked for;
 * "null" for an external (audio-coupled) vibration, which has no effect of its own.
 */
public data class VibrationRecord(
    public val createdAt: LocalDateTime?,
    public val external: Boolean,
    public val status: String,
    public val durationMillis: Long?,
    public val usage: String,
    public val packageName: String,
    public val uid: Int,
    public val reason: String,
    public val playedEffect: String,
    public val originalEffect: String,
) {
    /** Whether Android played it (or is playing it): not refused, not cut short by another vibration. */
    public val played: Boolean get() = status == "finished" || status == "running"

    /** [originalEffect] as steps, or null when it is not a plain step waveform (a ramp, a primitive, an envelope…). */
    public val originalSteps: List<Step>? get() = Step.parse(originalEffect)

    /** One line for a report: when, status, usage, who and what. */
    override fun toString(): String =
        "$createdAt $status usage=$usage $packageName (uid=$uid) reason=$reason original=${originalEffect.take(120)}"
}

/** A step of a waveform: [amplitude] 0..1 (−1: the vibrator's default) for [durationMillis]. */
public data class Step(public val durationMillis: Int, public val amplitude: Float) {
    public companion object {
        // VibrationEffect.toDebugString (Android 14+): StepSegment "Step=%dms(amplitude=%.2f…)", in the phone's locale
        // (String.format without one), so the decimal separator may be a comma.
        private val DEBUG = Regex("""Step=(\d+)ms\(amplitude=(-?\d+[.,]\d+)""")
        // VibrationEffect.Composed.toString (Android 12, 13): StepSegment "Step{amplitude=…, frequencyHz=…, duration=…}".
        private val FULL = Regex("""Step\{amplitude=(-?[\d.E-]+)(?:, frequencyHz=[^,]+)?, duration=(\d+)""")
        private val OTHER_SEGMENTS = Regex("""\b(?:Ramp|Prebaked|Primitive|Pwle|BasicPwle)\b""")

        /** The steps of an effect's text, or null when it has none or anything other than steps. */
        public fun parse(effect: String): List<Step>? {
            if (OTHER_SEGMENTS.containsMatchIn(effect)) return null
            val debug = DEBUG.findAll(effect).map { Step(it.groupValues[1].toInt(), it.groupValues[2].replace(',', '.').toFloat()) }.toList()
            val full = FULL.findAll(effect).map { Step(it.groupValues[2].toInt(), it.groupValues[1].toFloat()) }.toList()
            return (debug.ifEmpty { full }).ifEmpty { null }
        }
    }
}
