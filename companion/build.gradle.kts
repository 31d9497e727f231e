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

    testImplementation(project(":test-fixtures"))
    testImplementation(libs.junit4)
}
