// The convention of the pure-Kotlin library modules (haptics-core, sensor-bridge, messaging,
// messaging:broker, study, gesture): Kotlin/JVM at the catalog's jvmTarget, explicit API mode (every
// public declaration states its visibility and type), and JUnit 4 for the tests. A module applies it with
// alias(libs.plugins.hapticon.kotlin.library) and adds its own plugins and dependencies.
//
// The offline build (./build) reads this file like a module's build file (docs/build.md "Conventions"):
// keep it to plugins {}, kotlin {} and dependencies {} in the same declarative subset, libraries only
// (project dependencies stay in the modules' files, where the architecture check reads them).
plugins {
    id("org.jetbrains.kotlin.jvm")
}

// The catalog by name: precompiled script plugins get no `libs` accessor (gradle/gradle#15383).
val libs = the<VersionCatalogsExtension>().named("libs")

kotlin {
    explicitApi()
    jvmToolchain(libs.findVersion("jvmTarget").get().requiredVersion.toInt())
}

dependencies {
    testImplementation(libs.findLibrary("junit4").get())
}
