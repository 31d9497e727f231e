// User-study logic, pure Kotlin: protocols, counterbalancing, the hash-chained event log, export and analysis.
plugins {
    // Protocols, exports and log payloads are @Serializable documents (StudyDocuments.kt).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    api(project(":haptics-core"))
    // The compliance protocol names its conditions as grain settings and electrode masks.
    api(project(":sensor-bridge"))

    testImplementation(project(":test-fixtures"))
}
