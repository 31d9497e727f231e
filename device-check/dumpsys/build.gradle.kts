// Reads what the device check needs from Android's dumps (`dumpsys vibrator_manager`, `dumpsys notification`):
// plain Kotlin, so the parsers are tested on the JVM against recorded dumps in the formats of AOSP's sources.
plugins {
    alias(libs.plugins.hapticon.kotlin.library)
}
