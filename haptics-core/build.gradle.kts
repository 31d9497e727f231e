plugins {
    alias(libs.plugins.kotlin.jvm)
}

kotlin {
    explicitApi()
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    // The wire and file formats' schemas are @Serializable types (docs/json.md).
    api(libs.kotlinx.serialization.json)

    testImplementation(libs.junit4)
}
