// Plugins are declared here once and applied per module (the Gradle convention).
// The offline build (./build) reads the per-module build.gradle.kts files and the convention plugins in
// build-logic/ (docs/build.md "Conventions"); keep them declarative.
plugins {
    alias(libs.plugins.android.application) apply false
    alias(libs.plugins.android.library) apply false
    alias(libs.plugins.android.test) apply false
    alias(libs.plugins.kotlin.jvm) apply false
    alias(libs.plugins.kotlin.compose) apply false
    alias(libs.plugins.kotlin.serialization) apply false
    alias(libs.plugins.ksp) apply false
}
