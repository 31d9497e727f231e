// Touch gestures, pure Kotlin: recordings, icon extraction (envelope fit) and live recognition (random forest).
plugins {
    alias(libs.plugins.kotlin.jvm)
    // Model files are @Serializable documents (recognition/ModelDocuments.kt).
    alias(libs.plugins.kotlin.serialization)
}

kotlin {
    explicitApi()
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    api(project(":haptics-core"))

    testImplementation(project(":test-fixtures"))
    testImplementation(libs.junit4)
}
