// Shared test doubles and recorded data, used by the tests of every other module.
plugins {
    alias(libs.plugins.kotlin.jvm)
}

kotlin {
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    api(project(":haptics-core"))
    api(libs.junit4)
    implementation(project(":gesture")) // the gesture label types of the synthetic gestures
}
