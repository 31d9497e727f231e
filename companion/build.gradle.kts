plugins {
    alias(libs.plugins.kotlin.jvm)
    application
}

application {
    mainClass = "org.hapticon.companion.MainKt"
}

kotlin {
    jvmToolchain(libs.versions.jvmTarget.get().toInt())
}

dependencies {
    implementation(project(":haptics-core"))
    implementation(project(":sensor-bridge"))

    testImplementation(project(":test-fixtures"))
    testImplementation(libs.junit4)
}
