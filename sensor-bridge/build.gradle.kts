// Sensor protocols, models, safety limits and the live session: pure Kotlin, testable on the JVM. The Android USB
// transport lives in :sensor-bridge:usb and only moves bytes.
plugins {
    // @Serializable: the electrotactile calibration file (electrotactile/CalibrationFile.kt, docs/json.md).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    api(project(":haptics-core"))
    api(libs.kotlinx.coroutines.core) // the live session's state flows (live/, grains/, glove/)

    testImplementation(project(":test-fixtures"))
}
