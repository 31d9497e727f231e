// Sensor protocols, models, safety limits and the live session: pure Kotlin, testable on the JVM. The Android USB
// transport lives in :sensor-bridge:usb and only moves bytes.
plugins {
    alias(libs.plugins.hapticon.kotlin.library)
}

dependencies {
    api(project(":haptics-core"))
    api(libs.kotlinx.coroutines.core) // the live session's state flows (live/, grains/, glove/)

    testImplementation(project(":test-fixtures"))
}
