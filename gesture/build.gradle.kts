// Touch gestures, pure Kotlin: recordings, icon extraction (envelope fit) and live recognition (random forest).
plugins {
    // Model files are @Serializable documents (recognition/ModelDocuments.kt).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    api(project(":haptics-core"))

    testImplementation(project(":test-fixtures"))
}
