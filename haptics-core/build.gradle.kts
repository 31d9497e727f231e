plugins {
    // @Serializable schema types (the tests of SchemaJson declare their own).
    alias(libs.plugins.hapticon.kotlin.library.serialization)
}

dependencies {
    // The wire and file formats' schemas are @Serializable types (docs/json.md).
    api(libs.kotlinx.serialization.json)
}
