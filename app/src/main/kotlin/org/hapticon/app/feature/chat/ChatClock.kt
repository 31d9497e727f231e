package org.hapticon.app.feature.chat

import java.time.Instant
import java.time.LocalDate
import java.time.ZoneId
import java.time.format.DateTimeFormatter
import java.time.format.FormatStyle
import java.time.temporal.ChronoUnit
import java.util.Locale

/**
 * How times and days read in the chat screens, the way Google Messages and Signal write them: the list
 * says "Now", "5 min", the time today, the weekday this week and the date before; a conversation puts a
 * "Today" / "Yesterday" / date separator before each day's first message and the time under each bubble.
 * Pure functions of the clock, zone and locale, so tests pin all three.
 */
class ChatClock(
    private val zone: ZoneId = ZoneId.systemDefault(),
    private val locale: Locale = Locale.getDefault(),
) {
    private val time = DateTimeFormatter.ofLocalizedTime(FormatStyle.SHORT).withLocale(locale)
    private val weekday = DateTimeFormatter.ofPattern("EEE", locale)
    private val dayMonth = DateTimeFormatter.ofPattern("d MMM", locale)
    private val dayMonthYear = DateTimeFormatter.ofPattern("d MMM yyyy", locale)
    private val longDay = DateTimeFormatter.ofPattern("EEEE, d MMMM", locale)
    private val longDayYear = DateTimeFormatter.ofPattern("d MMMM yyyy", locale)

    private fun date(millis: Long): LocalDate = Instant.ofEpochMilli(millis).atZone(zone).toLocalDate()

    /** The time of day, in the locale's short form ("14:05", "2:05 PM"). */
    fun timeOfDay(millis: Long): String = time.format(Instant.ofEpochMilli(millis).atZone(zone))

    /** A conversation row's time: "Now" under a minute, "N min" under an hour, then time, weekday, date. */
    fun relative(millis: Long, nowMillis: Long): String {
        val ago = nowMillis - millis
        if (ago in 0 until 60_000) return "Now"
        if (ago in 60_000 until 3_600_000) return "${ago / 60_000} min"
        val day = date(millis)
        val today = date(nowMillis)
        val days = ChronoUnit.DAYS.between(day, today)
        return when {
            days == 0L -> timeOfDay(millis)
            days in 1..6 -> weekday.format(day)
            day.year == today.year -> dayMonth.format(day)
            else -> dayMonthYear.format(day)
        }
    }

    /** A day separator's label. */
    fun dayLabel(millis: Long, nowMillis: Long): String {
        val day = date(millis)
        val today = date(nowMillis)
        return when (ChronoUnit.DAYS.between(day, today)) {
            0L -> "Today"
            1L -> "Yesterday"
            else -> if (day.year == today.year) longDay.format(day) else longDayYear.format(day)
        }
    }

    /** Whether two instants fall on different calendar days here. */
    fun differentDays(a: Long, b: Long): Boolean = date(a) != date(b)
}
