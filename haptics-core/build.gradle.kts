plugins {
    alias(libs.plugins.kotlin.jvm)
    // @Serializable schema types (the tests of SchemaJson declare their own).
    alias(libs.plugins.kotlin.serialization)
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
