// The convention of the pure-Kotlin library modules whose types are @Serializable documents (haptics-core,
// sensor-bridge, messaging, study, gesture; docs/json.md): hapticon.kotlin-library, plus the Kotlin serialization plugin and
// its runtime, kotlinx-serialization-json, at the catalog's versions (the plugin generates the serializers, the
// runtime runs them). Read by the offline build like hapticon.kotlin-library.gradle.kts (docs/build.md).
plugins {
    id("hapticon.kotlin-library")
    id("org.jetbrains.kotlin.plugin.serialization")
}

// The catalog by name: precompiled script plugins get no `libs` accessor (gradle/gradle#15383).
val libs = the<VersionCatalogsExtension>().named("libs")

dependencies {
    implementation(libs.findLibrary("kotlinx-serialization-json").get())
}
